// write_cases OUT_DIR [DATA_DIR] [CASE_SUBSTRING]: writes the cases of the comparison with the strongest
// peers (bench/gmnf/side_by_side.py) as files, so that programs outside this repository run on exactly
// the same inputs: OUT_DIR/<case>/noisy.off and original.off (17 significant digits, the vertices in
// the order of the case's meshes), for the denoising pairs of DATA_DIR/denoising and peer_cases().

#include "bench_cases.h"

#include <CGAL/boost/graph/IO/OFF.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: write_cases OUT_DIR [DATA_DIR] [CASE_SUBSTRING]\n");
    return 2;
  }
  const std::string out = argv[1];
  const std::string dir = argc > 2 && argv[2][0] ? argv[2] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const std::string only = argc > 3 ? argv[3] : "";
  std::vector<Case> cases;
  for(const std::string& p : denoising_pairs(dir + "/denoising"))
    cases.push_back({p, [dir, p](Case& c) { return read_denoising_pair(dir + "/denoising/" + p, c.noisy, c.original, c.note); }});
  for(Case& c : peer_cases(dir)) cases.push_back(std::move(c));
  int written = 0;
  for(Case& c : cases)
  {
    if(c.name.find(only) == std::string::npos) continue;
    if(!c.load(c)) { std::fprintf(stderr, "%s: skipped (%s)\n", c.name.c_str(), c.note.c_str()); continue; }
    std::string folder = c.name;
    for(char& ch : folder) if(ch == ' ') ch = '_';
    std::filesystem::create_directories(out + "/" + folder);
    for(const auto& [name, mesh] : {std::make_pair("noisy", &c.noisy), std::make_pair("original", &c.original)})
    {
      std::ofstream f(out + "/" + folder + "/" + name + ".off");
      if(!CGAL::IO::write_OFF(f, *mesh, CGAL::parameters::stream_precision(17)))
      {
        std::fprintf(stderr, "%s: cannot write %s\n", c.name.c_str(), name);
        return 1;
      }
    }
    std::printf("%s\t%zu vertices\t%s\n", folder.c_str(), std::size_t(num_vertices(c.noisy)), c.note.c_str());
    ++written;
  }
  return written > 0 ? 0 : 1;
}
