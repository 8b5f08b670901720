// The vertex coordinates of a FaceGraph as one flat vector (x0 y0 z0 x1 ...), in vertices(m) order,
// and the two comparisons the fairing tests make with them: bit for bit, and the largest difference.

#ifndef AF_TEST_SUPPORT_MESH_COORDINATES_H
#define AF_TEST_SUPPORT_MESH_COORDINATES_H

#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace AF_test {

template <class Mesh>
std::vector<double> coordinates(const Mesh& m)
{
  std::vector<double> c;
  for(auto v : vertices(m))
  {
    const auto& p = get(CGAL::vertex_point, m, v);
    for(int k = 0; k < 3; ++k) c.push_back(CGAL::to_double(p[k]));
  }
  return c;
}

inline bool byte_identical(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// Largest |a_i - b_i|; infinite when the sizes differ.
inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double d = a.size() == b.size() ? 0.0 : HUGE_VAL;
  for(std::size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

} // namespace AF_test

#endif // AF_TEST_SUPPORT_MESH_COORDINATES_H
