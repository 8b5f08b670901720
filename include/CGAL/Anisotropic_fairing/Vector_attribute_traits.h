// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_ANISOTROPIC_FAIRING_VECTOR_ATTRIBUTE_TRAITS_H
#define CGAL_ANISOTROPIC_FAIRING_VECTOR_ATTRIBUTE_TRAITS_H

#include <CGAL/IO/Color.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Point_2.h>
#include <CGAL/Point_3.h>
#include <CGAL/Vector_2.h>
#include <CGAL/Vector_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingLimitSurface

Reads and writes the components of a per-vertex attribute value of type `V` as doubles, so that
any vertex property map can carry a vector-valued function on the surface.

Models are provided for arithmetic types (integers rounded and clamped to their range), `std::array<T,N>`,
`std::vector<T>`,
`Eigen::Matrix<T,N,1>` (fixed or dynamic `N`), `CGAL::Point_2`, `CGAL::Point_3`,
`CGAL::Vector_2`, `CGAL::Vector_3` of any kernel, and `CGAL::IO::Color` (red, green and blue, each
clamped to 0..255 and rounded when written; alpha is kept). Specialize it for other types:

\code
template <> struct Vector_attribute_traits<My_type> {
  static constexpr int static_dimension = 2;                    // -1 if only known at run time
  static std::size_t dimension(const My_type& v);
  static double get(const My_type& v, std::size_t i);
  static My_type make(const My_type& prototype, const double* values); // a value with these components
};
\endcode
`make()` receives the vertex's previous value as `prototype`, so that immutable types can be rebuilt
and components that are not faired (such as a colour's alpha) can be kept.
*/
template <typename V, typename Enable = void>
struct Vector_attribute_traits;

/// \cond SKIP_IN_MANUAL
template <typename T>
struct Vector_attribute_traits<T, typename std::enable_if<std::is_arithmetic<T>::value>::type>
{
  static constexpr int static_dimension = 1;
  static std::size_t dimension(const T&) { return 1; }
  static double get(const T& v, std::size_t) { return double(v); }
  static T make(const T&, const double* x)
  {
    if(std::is_integral<T>::value)   // rounded, and clamped rather than wrapped around
    {
      const double lo = double((std::numeric_limits<T>::min)()), hi = double((std::numeric_limits<T>::max)());
      if(!(x[0] > lo)) return (std::numeric_limits<T>::min)();   // also NaN
      if(x[0] >= hi) return (std::numeric_limits<T>::max)();
      return T(std::llround(x[0]));
    }
    return T(x[0]);
  }
};

template <typename T, std::size_t N>
struct Vector_attribute_traits<std::array<T, N>>
{
  static constexpr int static_dimension = int(N);
  static std::size_t dimension(const std::array<T, N>&) { return N; }
  static double get(const std::array<T, N>& v, std::size_t i) { return double(v[i]); }
  static std::array<T, N> make(const std::array<T, N>& p, const double* x)
  {
    std::array<T, N> r;
    for(std::size_t i = 0; i < N; ++i) r[i] = Vector_attribute_traits<T>::make(p[i], x + i);
    return r;
  }
};

template <typename T, typename A>
struct Vector_attribute_traits<std::vector<T, A>>
{
  static constexpr int static_dimension = -1;
  static std::size_t dimension(const std::vector<T, A>& v) { return v.size(); }
  static double get(const std::vector<T, A>& v, std::size_t i) { return double(v[i]); }
  static std::vector<T, A> make(const std::vector<T, A>& p, const double* x)
  {
    std::vector<T, A> r(p.size());
    for(std::size_t i = 0; i < p.size(); ++i) r[i] = Vector_attribute_traits<T>::make(p[i], x + i);
    return r;
  }
};

template <typename T, int N, int Options, int MaxN>
struct Vector_attribute_traits<Eigen::Matrix<T, N, 1, Options, MaxN, 1>>
{
  typedef Eigen::Matrix<T, N, 1, Options, MaxN, 1> V;
  static constexpr int static_dimension = (N == Eigen::Dynamic) ? -1 : N;
  static std::size_t dimension(const V& v) { return std::size_t(v.size()); }
  static double get(const V& v, std::size_t i) { return double(v[Eigen::Index(i)]); }
  static V make(const V& p, const double* x)
  {
    V r(p.size());
    for(Eigen::Index i = 0; i < p.size(); ++i) r[i] = T(x[i]);
    return r;
  }
};

// CGAL points and vectors: immutable, so rebuilt from their coordinates
template <typename T, int D>
struct Cartesian_attribute_traits
{
  static constexpr int static_dimension = D;
  static std::size_t dimension(const T&) { return D; }
  static double get(const T& p, std::size_t i) { return CGAL::to_double(p[int(i)]); }
  static T make(const T&, const double* x) { return build(x, std::integral_constant<int, D>()); }
private:
  static T build(const double* x, std::integral_constant<int, 2>) { return T(x[0], x[1]); }
  static T build(const double* x, std::integral_constant<int, 3>) { return T(x[0], x[1], x[2]); }
};

template <typename K>
struct Vector_attribute_traits<CGAL::Point_3<K>> : Cartesian_attribute_traits<CGAL::Point_3<K>, 3> {};
template <typename K>
struct Vector_attribute_traits<CGAL::Vector_3<K>> : Cartesian_attribute_traits<CGAL::Vector_3<K>, 3> {};
template <typename K>
struct Vector_attribute_traits<CGAL::Point_2<K>> : Cartesian_attribute_traits<CGAL::Point_2<K>, 2> {};
template <typename K>
struct Vector_attribute_traits<CGAL::Vector_2<K>> : Cartesian_attribute_traits<CGAL::Vector_2<K>, 2> {};

template <>
struct Vector_attribute_traits<CGAL::IO::Color>
{
  static constexpr int static_dimension = 3;
  static std::size_t dimension(const CGAL::IO::Color&) { return 3; }
  static double get(const CGAL::IO::Color& c, std::size_t i) { return double(c[int(i)]); }
  static CGAL::IO::Color make(const CGAL::IO::Color& p, const double* x)
  {
    auto channel = [](double v) {
      if(!(v > 0)) return (unsigned char)0;          // also maps NaN to 0
      return (unsigned char)std::lround((std::min)(v, 255.0));
    };
    return CGAL::IO::Color(channel(x[0]), channel(x[1]), channel(x[2]), p.alpha());
  }
};

namespace internal {
// whether Vector_attribute_traits<V> is defined (a complete type)
template <typename V, typename = void>
struct has_vector_attribute_traits : std::false_type {};
template <typename V>
struct has_vector_attribute_traits<V, decltype(void(sizeof(Vector_attribute_traits<V>)))> : std::true_type {};
} // namespace internal
/// \endcond

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_VECTOR_ATTRIBUTE_TRAITS_H
