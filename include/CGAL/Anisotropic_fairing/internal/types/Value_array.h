// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of a matrix over a Sparse_structure (M, L, a step's system): a vector of doubles whose
// resize leaves new entries unwritten. The parallel loop that fills the array then touches its memory
// first, on every core: a fresh array of tens of megabytes costs page faults and the kernel's zeroing,
// which std::vector's resize would pay on one thread before the loop starts.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VALUE_ARRAY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VALUE_ARRAY_H

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// std::allocator whose value-initialisation (`construct(p)`) is default-initialisation: a double is
/// left unwritten. Every other construction is std::allocator's.
template <typename T>
struct Unwritten_allocator : std::allocator<T>
{
  typedef T value_type;
  template <typename U> struct rebind { typedef Unwritten_allocator<U> other; };
  Unwritten_allocator() noexcept = default;
  template <typename U> Unwritten_allocator(const Unwritten_allocator<U>&) noexcept {}
  template <typename U> void construct(U* p) noexcept { ::new(static_cast<void*>(p)) U; }
  template <typename U, typename... Args> void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T, typename U>
bool operator==(const Unwritten_allocator<T>&, const Unwritten_allocator<U>&) noexcept { return true; }
template <typename T, typename U>
bool operator!=(const Unwritten_allocator<T>&, const Unwritten_allocator<U>&) noexcept { return false; }

/// Values over a structure's entries: whoever resizes it writes every new entry (assign() and the
/// constructor with a value still write that value).
typedef std::vector<double, Unwritten_allocator<double>> Value_array;

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VALUE_ARRAY_H
