// Denoises a scanned CAD part with the feature-preserving anisotropic tensor on a CGAL::Surface_mesh,
// its settings given by name. Without a time step the package chooses one from the mesh's estimated
// noise and stops when the surface has moved off the input by that noise (the automatic parameters);
// the tensor given is used as it is (no comparison with the isotropic flow).
//
// usage: anisotropic_denoising INPUT [ORIGINAL] [OUTPUT.off]   (e.g. data/fandisk_noisy.obj)
// With ORIGINAL (the noise-free mesh, same vertices), prints the mean angle between the face normals
// and the original's before and after, and exits 1 unless it at least halved.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cmath>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

// mean angle (degrees) between the face normals of two meshes with the same faces
double normal_error(const Mesh& a, const Mesh& b)
{
  double sum = 0;
  for(Mesh::Face_index f : a.faces())
  {
    const double c = PMP::compute_face_normal(f, a) * PMP::compute_face_normal(f, b);
    sum += std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / CGAL_PI;
  }
  return sum / double(a.number_of_faces());
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [ORIGINAL] [OUTPUT.off]\n";
    return 2;
  }
  const std::string input = argv[1];
  Mesh mesh, original;
  if(!CGAL::IO::read_polygon_mesh(input, mesh))
  {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }
  const bool compare = argc > 2 && CGAL::IO::read_polygon_mesh(argv[2], original) &&
                       original.number_of_faces() == mesh.number_of_faces();
  const double before = compare ? normal_error(mesh, original) : 0;

  // the feature threshold lambda (principal curvatures above 2 / l are features, l = sqrt(area / 4 pi))
  // and the prefilter (curvature read after an isotropic step of 1e-3 l^2, so that noise is no feature)
  const AF::Anisotropic_diffusion_tensor tensor = AF::Anisotropic_diffusion_tensor().set_lambda(2.0).set_epsilon(1e-3);
  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, AF::parameters::diffusion_tensor(tensor));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed (" << AF::to_string(report.status) << "): " << report.message << "\n";
    return 1;
  }
  std::cout << input << ": " << report.steps.size() << " steps, stopped: " << AF::to_string(report.stop_reason)
            << " (" << report.choices << ")\n";
  if(argc > 3) CGAL::IO::write_polygon_mesh(argv[3], mesh, CGAL::parameters::stream_precision(17));
  if(!compare) return 0;
  const double after = normal_error(mesh, original);
  std::cout << "mean face-normal error " << before << " -> " << after << " degrees\n";
  return 2 * after <= before ? 0 : 1;
}
