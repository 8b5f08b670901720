// Cost of the Loop limit element's set-up on a real mesh: numbering and validation, patch
// categories, quadrature stencils, the sparsity pattern and one assembly of the mass and stiffness matrices. Medians of
// several runs; one step of CGAL's own Loop subdivision on the same mesh is timed in the same run
// as a yardstick.
//
// usage: bench_loop_element MESH [RUNS=5]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_median.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AFi = CGAL::Anisotropic_fairing::internal;

int main(int argc, char** argv)
{
  if(argc < 2) { std::fprintf(stderr, "usage: %s MESH [RUNS=5]\n", argv[0]); return 2; }
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh)) { std::fprintf(stderr, "cannot read %s\n", argv[1]); return 1; }

  std::vector<double> t_index, t_cache, t_quad, t_pattern, t_mass, t_total, t_loop;
  std::size_t categories = 0, regular = 0, nnz = 0, points = 0;
  double area = 0;
  for(int r = 0; r < runs; ++r)
  {
    CGAL::Real_timer timer, total;
    total.start();
    timer.start();
    AFi::Indexed_mesh<Mesh> im(mesh);
    const AFi::Control_matrix X = im.read_points(mesh.points());
    t_index.push_back(timer.time());
    timer.reset();
    AFi::Patch_cache cache(im.topology());
    t_cache.push_back(timer.time());
    timer.reset();
    cache.prepare_quadrature(AFi::Quadrature_spec());
    t_quad.push_back(timer.time());
    timer.reset();
    AFi::Fem_assembler<AFi::Patch_cache> assembler(cache, im.number_of_vertices());
    t_pattern.push_back(timer.time());
    timer.reset();
    CGAL::Anisotropic_fairing::internal::Value_array m_values, l_values;
    area = assembler.assemble(X, 3, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), m_values, l_values).area;
    t_mass.push_back(timer.time());
    t_total.push_back(total.time());
    categories = cache.number_of_categories();
    nnz = assembler.number_of_nonzeros();
    regular = 0;
    points = 0;
    for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
      regular += cache.is_regular(cache.category(f)) ? 1 : 0;
    for(int c = 0; c < int(categories); ++c) points += cache.quadrature_points(c).size();

    Mesh copy = mesh;
    timer.reset();
    CGAL::Subdivision_method_3::Loop_subdivision(copy, CGAL::parameters::number_of_iterations(1));
    t_loop.push_back(timer.time());
  }
  std::printf("%s: %zu vertices, %zu faces (%zu regular), %zu patch categories, %zu cached quadrature stencils\n",
              argv[1], std::size_t(num_vertices(mesh)), std::size_t(num_faces(mesh)), regular, categories, points);
  std::printf("mass matrix: %zu non-zeros (%.2f per row), limit-surface area %.9g\n", nnz,
              double(nnz) / double(num_vertices(mesh)), area);
  std::printf("median of %d runs, seconds:\n", runs);
  std::printf("  numbering + validation   %8.4f\n", median(t_index));
  std::printf("  patch categories         %8.4f\n", median(t_cache));
  std::printf("  quadrature stencils      %8.4f\n", median(t_quad));
  std::printf("  sparsity pattern         %8.4f\n", median(t_pattern));
  std::printf("  assembly of M, L, stats  %8.4f\n", median(t_mass));
  std::printf("  total                    %8.4f\n", median(t_total));
  std::printf("  peer: one CGAL Loop_subdivision step %8.4f\n", median(t_loop));
  return 0;
}
