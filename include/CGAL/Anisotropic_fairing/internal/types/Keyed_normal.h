// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Standard normal numbers drawn per vertex from a key of its own (Vertex_keys.h: its input position), not from a
// generator run in the order of a numbering: a vertex gets the same number whatever the numbering of the mesh and
// whichever process of the distributed program holds it, and the numbers do not depend on the standard library
// (std::normal_distribution's are the implementation's). A key is mixed by SplitMix64's finaliser, the two
// uniform numbers it gives are turned into a normal one by the Box-Muller transform.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_KEYED_NORMAL_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_KEYED_NORMAL_H

#include <cmath>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// SplitMix64's finaliser: every bit of `z` moves every bit of the result.
inline std::uint64_t mix_bits(std::uint64_t z)
{
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// The key of a double's value (+0 and -0 alike), to be mixed into a vertex's key.
inline std::uint64_t value_bits(double x)
{
  if(x == 0) x = 0;
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

/// A standard normal number of `key` in the sequence `seed` (`stream`: the how-many-th number of the key).
inline double keyed_normal(std::uint64_t seed, std::uint64_t key, unsigned stream)
{
  const std::uint64_t a = mix_bits(seed ^ mix_bits(key ^ mix_bits(std::uint64_t(stream) + 1)));
  const std::uint64_t b = mix_bits(a);
  const double u = (double(a >> 11) + 0.5) * 0x1.0p-53;   // in (0, 1): the logarithm is finite
  const double v = double(b >> 11) * 0x1.0p-53;
  return std::sqrt(-2 * std::log(u)) * std::cos(6.283185307179586 * v);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_KEYED_NORMAL_H
