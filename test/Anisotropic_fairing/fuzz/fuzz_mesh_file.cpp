// libFuzzer target: a mesh file of one format (AF_FUZZ_FORMAT: 0 OFF, 1 OBJ, 2 PLY), read as the tool
// reads it (the checked reader, then CGAL's reader on a file the checks accepted), then faired for two
// steps. Any crash, sanitizer report, hang or out-of-memory is a bug; refusals (File_problem,
// Input_error) are the expected outcome for most inputs. Build and run: scripts/fuzz.sh.

#include "mesh_file_check.h"
#include "text_tokens.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/OBJ.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cstddef>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  af_tool::Polygon_soup soup;
  try
  {
    switch(AF_FUZZ_FORMAT)
    {
      case 0: soup = af_tool::read_checked_off("fuzz.off", text); break;
      case 1: soup = af_tool::read_checked_obj("fuzz.obj", text); break;
      default: soup = af_tool::read_checked_ply("fuzz.ply", text); break;
    }
    if(soup.faces.empty()) return 0;
    af_tool::check_oriented_manifold(soup);
  }
  catch(const af_tool::File_problem&) { return 0; }

  Mesh mesh;
  std::istringstream in(text);
  std::ostringstream quiet;
  std::streambuf* cerr = std::cerr.rdbuf(quiet.rdbuf());   // CGAL's readers print their complaints
  bool ok = false;
  if(AF_FUZZ_FORMAT == 0) ok = CGAL::IO::read_OFF(in, mesh);
  else if(AF_FUZZ_FORMAT == 1) ok = CGAL::IO::read_OBJ(in, mesh);
  else if(!soup.ply_strips) { std::string comments; ok = CGAL::IO::read_PLY(in, mesh, comments, false); }
  std::cerr.rdbuf(cerr);
  if(!ok || mesh.number_of_faces() != soup.faces.size()) return 0;
  if(mesh.number_of_faces() > 2000) return 0;   // the fairing's cost, not its robustness, grows beyond
  try
  {
    AF::anisotropic_fairing(mesh, AF::parameters::number_of_iterations(2).relative_time_step(1e-3));
  }
  catch(const AF::Input_error&) {}
  return 0;
}
