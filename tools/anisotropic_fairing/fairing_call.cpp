// The library call for the program's options (see fairing_call.h).
#include "fairing_call.h"

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

namespace af_tool {

AF::Fairing_report fair_with_options(Mesh& mesh, const Options& o, AF::Attribute_mode mode,
                                     const Attribute_vectors& attributes,
                                     std::vector<std::vector<double>>& attribute_controls,
                                     std::vector<Point>& control_points, std::vector<unsigned char>& held,
                                     const Step_callback& callback)
{
  AF::Fairing_options options = o.fairing;
  options.attribute_mode = mode;
  return AF::anisotropic_fairing(mesh, mesh.points(), attributes,
                                 AF::parameters::fairing_options(options)
                                   .control_point_map(CGAL::make_property_map(control_points))
                                   .attribute_control_map(Attribute_vectors{&attribute_controls})
                                   .vertex_is_constrained_map(CGAL::make_property_map(held))
                                   .callback(callback));
}

} // namespace af_tool
