// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which tensor the default run keeps. Both the anisotropic and the isotropic flow are run to the same
// discrepancy (the noise level), and the result whose normals vary less in total is kept: among
// surfaces at the same distance from the data, the one with the least total variation (Rudin, Osher
// and Fatemi's choice) has removed the most noise. Total variation does not penalise a crease for
// being sharp (a rounded crease turns the normal by the same angle), so on CAD parts the anisotropic
// result wins, having spent its displacement on noise rather than on rounding; on organic scans whose
// curvature is everywhere as strong as the noise's, the isotropic one can. The anisotropic result is
// kept unless the isotropic one is clearly smoother (by `isotropic_margin`): a difference of a few
// percent is within what the noise itself changes from one sample to the next. Once an isotropic result
// is kept, the uniform tensor's fourth-order flow (Fourth_order_system.h) is compared with it by the same
// measure, without margin: neither keeps creases; on a graded triangulation the uniform weights smooth
// every region over the same number of rings, and the fourth order removes the noise while rounding the
// shape less (on evenly triangulated meshes the results are close).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

constexpr double isotropic_margin = 0.05;

/// The total variation of the face normals of the first `real_faces` faces of Y: over interior edges,
/// the angle between the two faces' normals times the edge's length.
inline double normal_variation(const Triangle_topology& topo, std::size_t real_faces, const Control_matrix& Y)
{
  double total = 0;
  for(int h = 0; h < int(3 * real_faces); ++h)
  {
    const int o = topo.opposite(h);
    if(o < h || std::size_t(topo.face_of(o)) >= real_faces) continue;   // each interior edge once
    double a[3], b[3];
    const double la = face_cross_product(topo, std::size_t(topo.face_of(h)), Y, a);
    const double lb = face_cross_product(topo, std::size_t(topo.face_of(o)), Y, b);
    if(!(la > 0) || !(lb > 0)) continue;
    const double c = std::max(-1.0, std::min(1.0, (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb)));
    total += std::acos(c) * (Y.row(topo.source(h)).head(3) - Y.row(topo.target(h)).head(3)).norm();
  }
  return total;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H
