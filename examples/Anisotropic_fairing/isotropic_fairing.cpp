// Fairs a closed triangle mesh by mean-curvature flow on its Loop limit surface, with a few fixed
// vertices and a callback that prints each step, and writes the result at full precision.
//
// usage: isotropic_fairing INPUT OUTPUT

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT\n";
    return 2;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  // hold the vertex with the largest z fixed, as an example of constraints
  auto fixed = mesh.add_property_map<Mesh::Vertex_index, bool>("v:fixed", false).first;
  Mesh::Vertex_index top = *vertices(mesh).begin();
  for(Mesh::Vertex_index v : vertices(mesh))
    if(mesh.point(v).z() > mesh.point(top).z()) top = v;
  put(fixed, top, true);

  try
  {
    const AF::Fairing_report report = AF::anisotropic_fairing(mesh,
        AF::parameters::relative_time_step(1e-3)           // tau = 1e-3 l^2, l = sqrt(area / 4 pi)
                       .number_of_iterations(20)            // at most 20 steps ...
                       .stopping_criteria(AF::Stopping_criteria())   // ... ended earlier by (27)-(29)
                       .vertex_is_constrained_map(fixed)
                       .callback([](const AF::Fairing_step& s) {
                         std::cout << "step " << s.step << ": area " << s.area << ", int |H|^2 " << s.H_integral
                                   << ", " << s.solver_iterations << " solver iterations\n";
                         return true;                      // false would end the run here
                       }));
    if(!report.succeeded())
    {
      std::cerr << "fairing failed (" << AF::to_string(report.status) << "): " << report.message << "\n";
      return 1;   // the mesh is unchanged
    }
    std::cout << report.steps.size() << " steps, stopped by " << AF::to_string(report.stop_reason) << ", "
              << report.total_seconds << " s\n";
  }
  catch(const AF::Input_error& e)   // not a closed 2-manifold triangle mesh, NaN, bad parameter...
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  if(!CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
