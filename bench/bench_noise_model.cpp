// Is the noise model right? (issue 53, point 1)
//
// For every case directory CASES_DIR/<case>/{noisy.off, original.off} (bench/write_cases writes them), the noise
// model the default run reads from the noisy mesh alone (internal/flow/Noise_model.h) beside the truth, the
// displacement noisy - original: its RMS along the original's vertex normals and across them (per direction), in
// units of the mean edge length h; the ratio of the RMS across to along; the 90th over 10th percentile of the true
// deviation across the normals, from vertex neighbourhoods (three rings); the share of the vertices moved by more
// than 4 robust deviations along the normal. The model's columns: along, across, their ratio, spreads, impulses'
// share and deviation, the lattice step found (in h). The clean mesh's own reading comes last (what the mesh's
// sampling alone gives).
//
//   bench_noise_model CASES_DIR [CASE_SUBSTRING]

#include "bench_cases.h"

#include <CGAL/Anisotropic_fairing/internal/flow/Noise_model.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>

#include <cstdio>
#include <string>
#include <vector>

namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

AFI::Noise_model read_model(const Mesh& m)
{
  const AFI::Indexed_mesh<Mesh> im(m, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  const AFI::Control_matrix X = im.read_points(get(CGAL::vertex_point, m));
  std::vector<bool> usable(std::size_t(X.rows()), true);
  for(int v : layer.boundary_vertices) usable[std::size_t(v)] = false;
  const AFI::Noise_estimate noise(*layer.topology, X, usable);
  return AFI::estimate_noise_model(*layer.topology, X, usable, noise, mean_edge_length(m));
}

struct Truth
{
  double along = 0, across = 0, spread = 1, impulses = 0;
};

Truth true_noise(const Mesh& noisy, const Mesh& original)
{
  const std::vector<Vector> n = area_weighted_normals(original);
  const double h = mean_edge_length(original);
  std::vector<double> along, across2;
  for(Mesh::Vertex_index v : original.vertices())
  {
    const Vector e = noisy.point(v) - original.point(v);
    const double a = e * n[v.idx()];
    along.push_back(a / h);
    across2.push_back((e - a * n[v.idx()]).squared_length() / (h * h));
  }
  Truth t;
  double s2 = 0, t2 = 0;
  for(std::size_t i = 0; i < along.size(); ++i) { s2 += along[i] * along[i]; t2 += across2[i]; }
  t.along = std::sqrt(s2 / double(along.size()));
  t.across = std::sqrt(t2 / double(2 * along.size()));
  std::vector<double> a = along;
  const double robust = AFI::robust_deviation(a);
  std::size_t hit = 0;
  for(double x : along) hit += std::abs(x) > 4 * robust;
  t.impulses = double(hit) / double(along.size());
  // the deviation across the normals, over three rings of each vertex
  std::vector<double> local(along.size());
  for(Mesh::Vertex_index v : original.vertices())
  {
    std::vector<Mesh::Vertex_index> seen{ v };
    for(int r = 0; r < 3; ++r)
    {
      const std::size_t end = seen.size();
      for(std::size_t k = 0; k < end; ++k)
        for(Mesh::Vertex_index w : CGAL::vertices_around_target(original.halfedge(seen[k]), original))
          if(std::find(seen.begin(), seen.end(), w) == seen.end()) seen.push_back(w);
    }
    double sum = 0;
    for(Mesh::Vertex_index w : seen) sum += across2[w.idx()];
    local[v.idx()] = std::sqrt(sum / double(2 * seen.size()));
  }
  std::sort(local.begin(), local.end());
  const double low = local[local.size() / 10], high = local[9 * local.size() / 10];
  t.spread = low > 0 ? high / low : 1;
  return t;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s CASES_DIR [CASE_SUBSTRING]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1], only = argc > 2 ? argv[2] : "";
  const std::vector<std::string> cases = case_folders(dir, only);
  std::printf("| case | true along / across (ratio), spread across, impulses | model along / across (ratio), spread "
              "along / across, impulses (deviation), lattice step / h | the clean mesh's reading: along / across, "
              "impulses |\n|---|---|---|---|\n");
  for(const std::string& name : cases)
  {
    Mesh noisy, original;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + name + "/noisy.off", noisy) ||
       !CGAL::IO::read_polygon_mesh(dir + "/" + name + "/original.off", original))
      continue;
    const Truth t = true_noise(noisy, original);
    const AFI::Noise_model m = read_model(noisy), c = read_model(original);
    const double h = mean_edge_length(noisy);
    std::printf("| %s | %.3f / %.3f (%.2f), %.2f, %.1f%% | %.3f / %.3f (%.2f), %.2f / %.2f, %.1f%% (%.1f), %.3f | "
                "%.3f / %.3f, %.1f%% |\n", name.c_str(), t.along, t.across, t.across / t.along, t.spread,
                100 * t.impulses, m.normal, m.tangential, m.tangential / m.normal, m.normal_spread,
                m.tangential_spread, 100 * m.hit_share, m.hit_deviation,
                std::max({ m.cell[0], m.cell[1], m.cell[2] }) / h, c.normal, c.tangential, 100 * c.hit_share);
    std::fflush(stdout);
  }
  return 0;
}
