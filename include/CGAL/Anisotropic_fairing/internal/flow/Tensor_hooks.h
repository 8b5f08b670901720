// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optional members of a DiffusionTensor, found once here: a scale-relative threshold
// (`set_length_scale`), normal motion only (`normal_motion_only`), a prefilter time
// (`prefilter_time`), and parameters the package chooses from the mesh (`is_automatic`).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Tensor>
auto give_length_scale(Tensor& t, double ell, int) -> decltype(t.set_length_scale(ell), void()) { t.set_length_scale(ell); }
template <typename Tensor>
void give_length_scale(Tensor&, double, long) {}
template <typename Tensor>
auto wants_length_scale(const Tensor& t, int) -> decltype(const_cast<Tensor&>(t).set_length_scale(1.0), true) { return true; }
template <typename Tensor>
bool wants_length_scale(const Tensor&, long) { return false; }

template <typename Tensor>
auto wants_normal_motion(const Tensor& t, int) -> decltype(bool(t.normal_motion_only())) { return bool(t.normal_motion_only()); }
template <typename Tensor>
bool wants_normal_motion(const Tensor&, long) { return false; }

template <typename Tensor>
auto prefilter_time(const Tensor& t, int) -> decltype(double(t.prefilter_time())) { return double(t.prefilter_time()); }
template <typename Tensor>
double prefilter_time(const Tensor&, long) { return 0.0; }

template <typename Tensor>
auto is_automatic_tensor(const Tensor& t, int) -> decltype(bool(t.is_automatic())) { return bool(t.is_automatic()); }
template <typename Tensor>
bool is_automatic_tensor(const Tensor&, long) { return false; }

template <typename Tensor>
auto threshold_of(const Tensor& t, int) -> decltype(double(t.threshold())) { return double(t.threshold()); }
template <typename Tensor>
double threshold_of(const Tensor&, long) { return 0.0; }

/// Automatic tensors: their threshold (units of 1/h) and prefilter time (units of h^2) are chosen by the package.
template <typename Tensor>
auto choose_tensor(Tensor& t, double lambda, double epsilon, int) -> decltype(t.choose(lambda, epsilon), void()) { t.choose(lambda, epsilon); }
template <typename Tensor>
void choose_tensor(Tensor&, double, double, long) {}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H
