// The Loop limit element against CGAL's own Loop subdivision: subdivide the control mesh k times
// with CGAL::Subdivision_method_3::Loop_subdivision, apply the limit mask to every level-k vertex
// (exact limit points at dyadic parameters), and compare with Loop_limit_surface::evaluate at the
// same parameters. At level-k vertices of valence 6 inside a control face the exact parametric
// derivatives are 2^k/3 sum_j cos(pi j/3 - phi) x_j over the level-k neighbours (doc/Anisotropic_fairing/design/loop-fem.md
// section 1), which checks the derivative rows against CGAL as well.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include "test_support/cgal_loop_reference.h"
#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace AF = CGAL::Anisotropic_fairing;

template <class Mesh>
void compare_with_cgal(const Mesh& control, int k, const std::string& name)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  AF::Loop_limit_surface<Mesh> surface(control);
  const AF_test::Loop_reference<Mesh> ref = AF_test::cgal_loop_reference(control, k);
  std::vector<face_descriptor> face_list(faces(control).begin(), faces(control).end());

  AF_test::Max_error pos("limit points vs CGAL Loop^" + std::to_string(k) + " + limit mask, " + name);
  for(const AF_test::Limit_sample& s : ref.samples)
  {
    const auto p = surface.evaluate(face_list[s.face], { 1 - s.xi1 - s.xi2, s.xi1, s.xi2 });
    pos.add_error(std::max({ std::abs(p.position.x() - s.limit[0]), std::abs(p.position.y() - s.limit[1]),
                             std::abs(p.position.z() - s.limit[2]) }));
  }
  pos.print();
  AF_CHECK(pos.count() > 0 && pos.value() <= 1e-12, "positions agree with CGAL's Loop subdivision to 1e-12");

  // exact first derivatives at regular level-k vertices strictly inside a control face
  AF_test::Max_error der("first derivatives vs level-" + std::to_string(k) + " regular tangent masks, " + name);
  const double scale = std::ldexp(1.0, k);
  const auto vpm = get(CGAL::vertex_point, ref.refined);
  for(std::size_t r = 0; r < ref.refined_vertices.size(); ++r)
  {
    const AF_test::Sparse_param& P = ref.params[r];
    if(P.size != 3) continue;
    const vertex_descriptor v = ref.refined_vertices[r];
    if(CGAL::halfedges_around_target(v, ref.refined).size() != 6) continue;
    // the control face containing the support, and its (v0, v1, v2)
    std::size_t f = 0;
    while(!(P.contains(ref.control_faces[f][0]) && P.contains(ref.control_faces[f][1]) &&
            P.contains(ref.control_faces[f][2]))) ++f;
    const auto& cf = ref.control_faces[f];
    const double u = P.weight_of(cf[1]), w = P.weight_of(cf[2]);
    double d1[3] = { 0, 0, 0 }, d2[3] = { 0, 0, 0 };
    for(vertex_descriptor nb : CGAL::vertices_around_target(v, ref.refined))
    {
      std::size_t ri = 0;
      while(ref.refined_vertices[ri] != nb) ++ri;
      const AF_test::Sparse_param& Q = ref.params[ri];
      const long du = std::lround((Q.weight_of(cf[1]) - u) * scale);
      const long dw = std::lround((Q.weight_of(cf[2]) - w) * scale);
      // lattice directions counter-clockwise: (1,0), (0,1), (-1,1), (-1,0), (0,-1), (1,-1)
      const long dirs[6][2] = { {1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1} };
      int j = -1;
      for(int i = 0; i < 6; ++i) if(dirs[i][0] == du && dirs[i][1] == dw) j = i;
      AF_CHECK(j >= 0, "neighbour on the parameter lattice");
      if(j < 0) continue;
      const auto& x = get(vpm, nb);
      for(int c = 0; c < 3; ++c)
      {
        d1[c] += scale / 3 * std::cos(CGAL_PI * j / 3) * x[c];
        d2[c] += scale / 3 * std::cos(CGAL_PI * j / 3 - CGAL_PI / 3) * x[c];
      }
    }
    const auto p = surface.evaluate(face_list[f], { 1 - u - w, u, w });
    for(int c = 0; c < 3; ++c)
    {
      der.add_error(std::abs(p.d1[c] - d1[c]) / (1 + std::abs(d1[c])));
      der.add_error(std::abs(p.d2[c] - d2[c]) / (1 + std::abs(d2[c])));
    }
  }
  der.print();
  AF_CHECK(der.count() > 0 && der.value() <= 1e-12, "derivatives agree with the exact regular tangent masks");
}

int main()
{
  {
    Surface_mesh tet, oct, ico, mixed;
    AF_test::make_tetrahedron(tet);
    AF_test::make_octahedron(oct);
    AF_test::make_icosahedron(ico);
    AF_test::make_mixed_valence_mesh(mixed);
    std::cout << "valences of the mixed mesh: " << AF_test::histogram_to_string(AF_test::valence_histogram(mixed)) << "\n";
    const auto by_ev = AF_test::faces_by_extraordinary_count(mixed);
    std::cout << "faces with 0/1/2/3 extraordinary vertices: " << by_ev[0] << "/" << by_ev[1] << "/" << by_ev[2] << "/" << by_ev[3] << "\n";
    AF_CHECK(by_ev[2] > 0 && by_ev[3] > 0, "the mixed mesh has faces with two and three extraordinary vertices");
    compare_with_cgal(tet, 5, "tetrahedron (Surface_mesh)");
    compare_with_cgal(oct, 5, "octahedron (Surface_mesh)");
    compare_with_cgal(ico, 4, "icosahedron (Surface_mesh)");
    compare_with_cgal(mixed, 4, "valences 3-9 (Surface_mesh)");
  }
  {
    Polyhedron tet, mixed;
    AF_test::make_tetrahedron(tet);
    AF_test::make_mixed_valence_mesh(mixed);
    compare_with_cgal(tet, 4, "tetrahedron (Polyhedron_3)");
    compare_with_cgal(mixed, 4, "valences 3-9 (Polyhedron_3)");
  }
  return AF_test::report();
}
