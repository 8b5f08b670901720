// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The time step, fidelity weight and tensor scale of every vertex. Relative parameters are measured
// per connected component (l_c = sqrt(Area_c / 4 pi), or the component's mean edge length h_c for
// the automatic parameters), so that a small part of a mesh is faired as if it were alone. Within a
// component they are constant, so the system ((1 + tau w) M + tau L) stays symmetric: M and L have no
// entry between two components.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_UNITS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_UNITS_H

#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What a relative parameter is measured in.
enum class Length_unit { MODEL, SCALE, EDGE };

struct Step_units
{
  std::vector<double> tau, omega;   // per row, model units
  std::vector<double> length;       // per row: the length unit of the relative stopping thresholds (1 in model units)
  std::vector<double>
    tensor_scale; // per component: its unit over the global one (Quadrature_point_geometry::component_scale)
  std::vector<double> tensor_scale_of_row;
  double scale = 0;                 // l of the whole surface
  double tensor_unit = 1;           // the global unit given to the tensor's set_length_scale()
  double time_step = 0, fidelity_weight = 0;   // of the largest component, for the report
  double relative_time_step = 0;    // tau / l^2 of the largest component
};

/// l = sqrt(area / 4 pi), the radius of the sphere of the same area: the length unit of the relative parameters.
inline double length_scale(double area) { return std::sqrt(area / (4 * 3.14159265358979323846)); }

/// 1, or what the system of a step with f times the time step is divided by so that a huge time step
/// cannot overflow its norms (the solution does not change), over the rows `free`.
inline double system_scale(const Step_units& u, const std::vector<int>& free, double f, int order, double mean_edge)
{
  double largest = 0;
  const double stiffness = std::pow(mean_edge, -order);
  for(int i : free) largest = std::max(largest, f * u.tau[std::size_t(i)] * (u.omega[std::size_t(i)] + stiffness));
  return largest > 1e6 ? largest : 1.0;
}

/// `time_step` in units of `time_unit`^order (the flow's order: 2 or 4), `fidelity` in 1/l^2 if relative; the tensor
/// measured in `tensor_unit`. `edge[c]`: mean edge length of component c, `global_edge` of the whole mesh.
inline Step_units make_step_units(const Assembly_statistics& a0, const Mesh_components& comp, std::size_t rows,
                                  double time_step, Length_unit time_unit, int order, double fidelity,
                                  bool relative_fidelity, bool relative_stopping, Length_unit tensor_unit,
                                  const std::vector<double>& edge, double global_edge)
{
  Step_units u;
  u.scale = length_scale(a0.area);
  const std::size_t nc = comp.count;
  std::vector<double> ell(nc), tau(nc), omega(nc);
  std::size_t largest = 0;
  for(std::size_t c = 0; c < nc; ++c)
  {
    ell[c] = nc == 1 ? u.scale : length_scale(a0.component_area[c]);
    const double unit = time_unit == Length_unit::SCALE ? ell[c] : time_unit == Length_unit::EDGE ? edge[c] : 1.0;
    tau[c] = time_step * std::pow(unit, order);
    omega[c] = relative_fidelity ? fidelity / (ell[c] * ell[c]) : fidelity;
    if(a0.component_area[c] > a0.component_area[largest]) largest = c;
  }
  u.tensor_unit = tensor_unit == Length_unit::EDGE ? global_edge : u.scale;
  u.tensor_scale.resize(nc);
  for(std::size_t c = 0; c < nc; ++c)
    u.tensor_scale[c] = (tensor_unit == Length_unit::EDGE ? edge[c] : ell[c]) / u.tensor_unit;
  if(nc == 1) u.tensor_scale[0] = 1.0;   // one component: exactly the global unit
  u.tau.assign(rows, nc > 0 ? tau[largest] : 0.0);
  u.omega.assign(rows, nc > 0 ? omega[largest] : 0.0);
  u.length.assign(rows, relative_stopping ? u.scale : 1.0);
  u.tensor_scale_of_row.assign(rows, 1.0);
  for(std::size_t i = 0; i < rows; ++i)
  {
    const int c = comp.of_vertex[i];
    if(c < 0) continue;
    u.tau[i] = tau[std::size_t(c)];
    u.omega[i] = omega[std::size_t(c)];
    if(relative_stopping) u.length[i] = ell[std::size_t(c)];
    u.tensor_scale_of_row[i] = u.tensor_scale[std::size_t(c)];
  }
  if(nc > 0)
  {
    u.time_step = tau[largest];
    u.fidelity_weight = omega[largest];
    u.relative_time_step = tau[largest] / (ell[largest] * ell[largest]);
  }
  return u;
}

/// The root mean square of the rows of Z off their mean: the unit of a fixed surface's attributes.
inline double row_spread(const Control_matrix& Z)
{
  double spread = 0;
  const Eigen::RowVectorXd mean = Z.colwise().mean();
  for(Eigen::Index i = 0; i < Z.rows(); ++i) spread += (Z.row(i) - mean).squaredNorm();
  return Z.rows() > 0 ? std::sqrt(spread / double(Z.rows())) : 0.0;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_UNITS_H
