// The library call for the program's options (see fairing_call.h).
#include "fairing_call.h"

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

namespace af_tool {

namespace {

// The named parameters differ in type with the time step and fidelity flags given
// (the bounds always given, 0 for none, so that they add one variant of the call, not three)
template <typename NP, typename Run>
AF::Fairing_report with_bound(const NP& np, const Options& o, Run& run)
{
  const auto bounded = np.attribute_maximum_deviation(o.attribute_bound);
  if(o.has_bound) return run(bounded.absolute_maximum_deviation(o.bound));
  return run(bounded.relative_maximum_deviation(o.relative_bound));
}

template <typename NP, typename Run>
AF::Fairing_report with_fidelity(const NP& np, const Options& o, Run& run)
{
  if(o.has_fidelity) return with_bound(np.fidelity_weight(o.fidelity), o, run);
  if(o.has_relative_fidelity) return with_bound(np.relative_fidelity_weight(o.relative_fidelity), o, run);
  return with_bound(np, o, run);
}

template <typename NP, typename Run>
AF::Fairing_report with_time_step(const NP& np, const Options& o, Run& run)
{
  if(o.has_time_step) return with_fidelity(np.time_step(o.time_step), o, run);
  if(o.has_relative_time_step) return with_fidelity(np.relative_time_step(o.relative_time_step), o, run);
  return with_fidelity(np, o, run);
}

} // namespace

AF::Fairing_report fair_with_options(Mesh& mesh, const Options& o, AF::Attribute_mode mode, const Attribute_vectors& attributes,
                                     std::vector<std::vector<double>>& attribute_controls, std::vector<Point>& control_points,
                                     std::vector<unsigned char>& held, const Step_callback& callback)
{
  auto fair = [&](const auto& np) {
    return AF::anisotropic_fairing(mesh, mesh.points(), attributes, np.control_point_map(CGAL::make_property_map(control_points))
                                                                    .attribute_control_map(Attribute_vectors{&attribute_controls})
                                                                    .vertex_is_constrained_map(CGAL::make_property_map(held)));
  };
  const AF::Stopping_criteria stop = o.stop == "off" ? AF::Stopping_criteria::none()
                                  : o.stop == "paper" ? AF::Stopping_criteria()
                                  : o.stop == "noise" || (automatic_parameters(o) && effective_mode(o) != AF::Attribute_mode::ATTRIBUTES_ONLY)
                                    ? AF::Stopping_criteria::automatic()
                                  : AF::Stopping_criteria();
  const auto base = AF::parameters::number_of_iterations(o.steps)
                      .stopping_criteria(stop)
                      .finite_element(o.element)
                      .output_positions(o.output_positions)
                      .linear_solver(o.solver)
                      .boundary_handling(o.boundary)
                      .quadrature_degree(o.quadrature_degree)
                      .attribute_mode(mode)
                      .attribute_weight(o.attribute_weight)
                      .flow_order(o.order)
                      .callback(callback);
  AF::Anisotropic_diffusion_tensor tensor = AF::Anisotropic_diffusion_tensor().set_lambda(o.lambda).set_epsilon(o.epsilon)
                                              .set_normal_motion_only(o.normal_motion_only);
  if(automatic_tensor(o)) tensor = AF::Anisotropic_diffusion_tensor::automatic();
  return o.anisotropic ? with_time_step(base.diffusion_tensor(tensor), o, fair)
         : o.uniform   ? with_time_step(base.diffusion_tensor(AF::Uniform_diffusion_tensor()), o, fair)
                       : with_time_step(base.diffusion_tensor(AF::Isotropic_diffusion_tensor()), o, fair);
}

} // namespace af_tool
