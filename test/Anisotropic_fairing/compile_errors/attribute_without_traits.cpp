// Must not compile: the attribute map's value type (std::string) has no Vector_attribute_traits. The
// test (compile_error_test.cmake) expects exactly one error, the package's static_assert sentence.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <string>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main()
{
  Mesh m;
  auto names = m.add_property_map<Mesh::Vertex_index, std::string>("v:name").first;
  CGAL::Anisotropic_fairing::anisotropic_fairing(m, names);
}
