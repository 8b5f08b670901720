// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of a run for which the user gave no time step, in units of the mean edge length h of each
// connected component, and what the report's `choices` says of them. How long to diffuse is not chosen here:
// the noise criterion stops the run when the surface has moved off the input by the noise estimated from the
// mesh (Noise_estimate.h), so a time step only sets the resolution of that search, and the tensor's constants
// say what a feature is. What they were measured against: the manual's Validation page (bench_defaults).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_model.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>

#include <cstddef>
#include <cstdio>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Automatic_parameters
{
  double time_step = 0.3;   // tau / h^2 per step: the noise is reached in a few steps, the last one interpolated
  double time_step4 = 0.1;  // tau / h^4 per step of the fourth-order flow: a larger one overshoots the noise
  double lambda = 0.1;      // feature threshold, units of 1/h: a turn of about 6 degrees per edge on M_eps
  double epsilon = 0.4;     // prefilter time, units of h^2: one isotropic step removes most of the noise's curvature
};

/// The settings of a run of the given order; with automatic parameters, its time step too.
inline Stepper_settings with_order(Stepper_settings s, int order)
{
  if(order != s.order && s.time_unit == Length_unit::EDGE)
    s.time_step = order == 4 ? Automatic_parameters().time_step4 : Automatic_parameters().time_step;
  s.order = order;
  return s;
}

/// What the default run chose from the mesh: the start of the report's `choices`. `tensor_chosen`: the
/// anisotropic tensor's threshold and prefilter were chosen; `scaled_flow`: the flow whose time step
/// follows the mesh's density, if any. The target is that of `s` (its strength named when not 1).
inline std::string automatic_choices(const Noise_estimate& noise, const Stepper_settings& s, bool tensor_chosen,
                                     std::size_t removed_spikes, std::size_t n, const char* scaled_flow)
{
  const Automatic_parameters a;
  char text[400];
  char scaled[80] = "";
  if(s.strength != 1) std::snprintf(scaled, sizeof scaled, " (strength %.6g)", s.strength);
  std::snprintf(text, sizeof text, "noise %.3g h (robust estimate over %zu vertices); time step %.3g h^%d per step "
                "until the surface has moved by %.3g x the noise%s%s", noise.relative_sigma(),
                noise.number_of_samples(), s.time_step, s.order, s.stopping.noise_discrepancy * s.strength, scaled,
                tensor_chosen ? "" : "; the tensor given");
  std::string choices = text;
  if(removed_spikes > 0)
  {
    std::snprintf(text, sizeof text, "; first %zu isolated spikes (%.2g%% of the vertices: impulsive noise) moved "
                  "to the centroids of their rings", removed_spikes, 100.0 * double(removed_spikes) / double(n));
    choices += text;
  }
  if(tensor_chosen)
  {
    std::snprintf(text, sizeof text, "; anisotropic tensor: principal curvatures above %.3g / h are features, "
                  "read on M_eps, the surface after an isotropic step of %.3g h^2", a.lambda, a.epsilon);
    choices += text;
  }
  if(scaled_flow)
    choices += std::string("; the ") + scaled_flow +
               " flow's time step follows the mesh's density (h: the edge length around each vertex)";
  return choices;
}

/// The noise the run read from the mesh, in the report (`mean_edge_length` filled).
inline void report_noise(const Noise_estimate& noise, const Noise_model& model, Fairing_report& report)
{
  report.noise_level = noise.relative_sigma();
  report.noise_deviation = noise.relative_sigma() * report.mean_edge_length;
  report.noise_correlation = noise.correlation().k;
  report.noise_correlation_factor = noise.correlation().factor();
  report.tangential_noise_level = model.tangential;
  report.noise_level_spread = model.normal_spread;
  report.tangential_noise_level_spread = model.tangential_spread;
  report.impulse_share = model.hit_share;
  report.impulse_deviation = model.hit_deviation;
  report.lattice_step = model.cell;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H
