// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rule asked when a run ends: never a surface with more folded edges than the input. The run falls back
// to its last surface without new folds; when every step folded it, nothing sound was gained, and an
// unmoved result is no success.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NEW_FOLDS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NEW_FOLDS_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <cstddef>
#include <optional>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Fold_verdict
{
  bool fails;           // no step without new folds: the run fails (FOLDED)
  std::string message;  // else it falls back to step `unfolded_steps`
};

/// `folds` of the run's last surface, `allowed` (the input's), `unfolded_steps`: the last step without more.
inline std::optional<Fold_verdict> new_folds(std::size_t folds, std::size_t allowed, std::size_t unfolded_steps)
{
  if(folds <= allowed) return std::nullopt;
  const std::string counts =
    "the surface folded at " + std::to_string(folds) + " edges (the input at " + std::to_string(allowed) + ")";
  if(unfolded_steps == 0) return Fold_verdict{ true, counts + " from the first step on, even with smaller time steps" };
  return Fold_verdict{ false, counts + "; the run ends on the last surface without new folds (step " +
                                std::to_string(unfolded_steps) + ")" };
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NEW_FOLDS_H
