// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A deviation bound's fidelity of each vertex's own (internal/flow/Output_fidelity.h) in the distributed step:
// the process owning a held vertex i adds its part of the step's matrix, t_a mu_i D_i w_a w_b for the pairs
// (a, b) of free vertices of its mask (y_i = sum_a w_a z_a: its limit mask, or itself), and of the right-hand
// side, t_a w_a mu_i D_i (y0_i - sum_b w_b z_b); rows owned elsewhere travel to their owners (ADD_VALUES).
// D_i is the lumped mass (with the local time scale), as the library's Step_solver takes it.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_FIDELITY_H
#define AF_DISTRIBUTED_DISTRIBUTED_FIDELITY_H

#include "Distributed_layout.h"
#include "Face_partition.h"

#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <petscmat.h>

#include <utility>
#include <vector>

namespace af_distributed {

class Distributed_fidelity
{
public:
  /// `fidelity`, `anchor` (y0): the run's (Flow_loop.h); `held`: per real vertex, the rows not solved for.
  Distributed_fidelity(const CGAL::Anisotropic_fairing::internal::Output_fidelity& fidelity,
                       const CGAL::Anisotropic_fairing::internal::Control_matrix& anchor,
                       const Distributed_layout& d, const std::vector<bool>& held)
    : fidelity_(fidelity), anchor_(anchor), d_(d), held_(held)
  {}

  /// A += the fidelity's part, for mu (per real vertex; empty: none) and the step's t; `Mw`: M with the time
  /// scale (its row sums: D); `lumped`: a vector of Mw's rows. A is assembled again.
  void add_to_matrix(Mat A, Mat Mw, Vec lumped, const std::vector<double>& mu, const std::vector<double>& t)
  {
    held_mass_.clear();
    if(mu.empty()) return;
    petsc_check(MatGetRowSum(Mw, lumped), "MatGetRowSum");
    const PetscScalar* D = nullptr;
    petsc_check(VecGetArrayRead(lumped, &D), "VecGetArrayRead");
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k)
    {
      const int i = d_.owned_vertices[k];
      if(mu[std::size_t(i)] == 0) continue;
      const auto& m = fidelity_.mask(i);
      if(!fidelity_.real_mask(m, held_.size())) continue;
      const double h = mu[std::size_t(i)] * double(D[k]);
      held_mass_.emplace_back(i, h);
      for(const auto& a : m)
        for(const auto& b : m)
          if(!held_[std::size_t(a.first)] && !held_[std::size_t(b.first)])
            petsc_check(MatSetValue(A, d_.petsc_row[std::size_t(a.first)], d_.petsc_row[std::size_t(b.first)],
                                    t[std::size_t(a.first)] * h * a.second * b.second, ADD_VALUES),
                        "MatSetValue");
    }
    petsc_check(VecRestoreArrayRead(lumped, &D), "VecRestoreArrayRead");
    petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  }

  /// b += the fidelity's part in column c of X (every row), then b assembled.
  void add_to_right_hand_side(Vec b, const CGAL::Anisotropic_fairing::internal::Control_matrix& X,
                              const std::vector<double>& t, int c) const
  {
    for(const auto& held : held_mass_)
    {
      const auto& m = fidelity_.mask(held.first);
      double e = anchor_(held.first, c);
      for(const auto& a : m) e -= a.second * X(a.first, c);
      e *= held.second;
      for(const auto& a : m)
        if(!held_[std::size_t(a.first)])
          petsc_check(VecSetValue(b, d_.petsc_row[std::size_t(a.first)], t[std::size_t(a.first)] * a.second * e,
                                  ADD_VALUES),
                      "VecSetValue");
    }
    petsc_check(VecAssemblyBegin(b), "VecAssemblyBegin");
    petsc_check(VecAssemblyEnd(b), "VecAssemblyEnd");
  }

private:
  const CGAL::Anisotropic_fairing::internal::Output_fidelity& fidelity_;
  const CGAL::Anisotropic_fairing::internal::Control_matrix& anchor_;
  const Distributed_layout& d_;
  const std::vector<bool>& held_;
  std::vector<std::pair<int, double>> held_mass_;   // this process's held vertices and their mu_i D_i
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_FIDELITY_H
