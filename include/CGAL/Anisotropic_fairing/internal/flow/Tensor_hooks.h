// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optional members of a DiffusionTensor, found once here: a scale-relative threshold
// (`set_length_scale`), normal motion only (`normal_motion_only`), a prefilter time
// (`prefilter_time`), and parameters the package chooses from the mesh (`is_automatic`).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H

#include <type_traits>
#include <utility>
#include <variant>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

// whether Tensor has the member that Member<Tensor> names
template <typename Tensor, template <typename> class Member, typename = void>
struct has_tensor_member : std::false_type {};
template <typename Tensor, template <typename> class Member>
struct has_tensor_member<Tensor, Member, std::void_t<Member<Tensor>>> : std::true_type {};

template <typename T> using set_length_scale_member = decltype(std::declval<T&>().set_length_scale(1.0));
template <typename T> using normal_motion_only_member = decltype(bool(std::declval<const T&>().normal_motion_only()));
template <typename T> using prefilter_time_member = decltype(double(std::declval<const T&>().prefilter_time()));
template <typename T> using is_automatic_member = decltype(bool(std::declval<const T&>().is_automatic()));
template <typename T> using threshold_member = decltype(double(std::declval<const T&>().threshold()));
template <typename T> using choose_member = decltype(std::declval<T&>().choose(1.0, 1.0));

template <typename Tensor>
constexpr bool wants_length_scale(const Tensor&) { return has_tensor_member<Tensor, set_length_scale_member>::value; }
template <typename Tensor>
void give_length_scale(Tensor& t, double ell)
{
  if constexpr(has_tensor_member<Tensor, set_length_scale_member>::value) t.set_length_scale(ell);
}

template <typename Tensor>
bool wants_normal_motion(const Tensor& t)
{
  if constexpr(has_tensor_member<Tensor, normal_motion_only_member>::value) return bool(t.normal_motion_only());
  else return false;
}

template <typename Tensor>
double prefilter_time(const Tensor& t)
{
  if constexpr(has_tensor_member<Tensor, prefilter_time_member>::value) return double(t.prefilter_time());
  else return 0.0;
}

template <typename Tensor>
bool is_automatic_tensor(const Tensor& t)
{
  if constexpr(has_tensor_member<Tensor, is_automatic_member>::value) return bool(t.is_automatic());
  else return false;
}

/// the threshold in model units, or 0 for a tensor without one
template <typename Tensor>
double threshold_of(const Tensor& t)
{
  if constexpr(has_tensor_member<Tensor, threshold_member>::value) return double(t.threshold());
  else return 0.0;
}

/// Automatic tensors: their threshold (units of 1/h) and prefilter time (units of h^2) are chosen by the package.
template <typename Tensor>
void choose_tensor(Tensor& t, double lambda, double epsilon)
{
  if constexpr(has_tensor_member<Tensor, choose_member>::value) t.choose(lambda, epsilon);
}


// A tensor chosen at run time (Package_diffusion_tensor): the same questions, asked of the one it holds.
template <typename... Tensors>
bool is_automatic_tensor(const std::variant<Tensors...>& t)
{
  return std::visit([](const auto& held) { return is_automatic_tensor(held); }, t);
}
template <typename... Tensors>
void choose_tensor(std::variant<Tensors...>& t, double lambda, double epsilon)
{
  std::visit([&](auto& held) { choose_tensor(held, lambda, epsilon); }, t);
}

/// `f(t)`, or `f` of the tensor a variant holds: the flow runs on the tensor's own type.
template <typename Tensor, typename F>
decltype(auto) with_tensor(const Tensor& t, F&& f) { return f(t); }
template <typename... Tensors, typename F>
decltype(auto) with_tensor(const std::variant<Tensors...>& t, F&& f) { return std::visit(std::forward<F>(f), t); }

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TENSOR_HOOKS_H
