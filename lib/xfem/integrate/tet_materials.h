// SPDX-License-Identifier: MIT
#pragma once
#include <cstddef>
#include <vector>

#include "xfem/integrate/material_law.h"

namespace xfem {

/// The material of every tet (problem.json `material` and `materials`, one per region of the mesh,
/// core/regions.h). Built by tet_materials() of system/problem.h, which checks the regions.
/// A body of one material has one law and no per-tet table: every tet's law(t) is the same
/// object, so its results are those of the single-material code, bit for bit.
struct TetMaterials {
  std::vector<MaterialLaw> laws;  ///< laws[0]: problem.json's `material` (the regions `materials` does not list)
  std::vector<double> E, nu;      ///< Young's modulus (Pa) and Poisson's ratio of each law
  std::vector<int> of_tet;        ///< index into `laws` of each tet; empty: every tet has laws[0]

  TetMaterials() : TetMaterials(MaterialModel::Linear, 1.0, 0.0) {}
  TetMaterials(MaterialModel model, double young, double poisson) { add(model, young, poisson); }
  /// A body of one material given by its Lame parameters (E and nu unknown: 0).
  explicit TetMaterials(const MaterialLaw& one) : laws{one}, E{0.0}, nu{0.0} {}

  /// Adds a law; returns its index, or that of an equal law already held (same model, E, nu).
  int add(MaterialModel model, double young, double poisson) {
    for (std::size_t k = 0; k < laws.size(); ++k)
      if (laws[k].model == model && E[k] == young && nu[k] == poisson) return static_cast<int>(k);
    laws.push_back(MaterialLaw{model, xfem::lame(young, poisson)});
    E.push_back(young);
    nu.push_back(poisson);
    return static_cast<int>(laws.size() - 1);
  }
  /// The index into `laws` of tet t.
  int index(long t) const { return of_tet.empty() ? 0 : of_tet[static_cast<std::size_t>(t)]; }
  const MaterialLaw& law(long t) const { return laws[static_cast<std::size_t>(index(t))]; }
  const Lame& lame(long t) const { return law(t).lame; }
};

}  // namespace xfem
