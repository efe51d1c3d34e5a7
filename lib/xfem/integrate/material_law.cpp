// SPDX-License-Identifier: MIT
#include "xfem/integrate/material_law.h"

#include "xfem/core/error.h"

namespace xfem {

const char* material_model_name(MaterialModel model) {
  switch (model) {
    case MaterialModel::Linear: return "linear";
    case MaterialModel::Corotational: return "corotational";
    case MaterialModel::NeoHookean: return "neo-hookean";
  }
  return "linear";
}

MaterialModel material_model_named(const std::string& name) {
  for (MaterialModel m : {MaterialModel::Linear, MaterialModel::Corotational, MaterialModel::NeoHookean})
    if (name == material_model_name(m)) return m;
  throw Error("unknown material model \"" + name + "\" (linear, corotational, neo-hookean)");
}

bool stress_at(const MaterialLaw&, const Eigen::Matrix3d&, StressAt&) {
  throw Error("stress_at: not implemented yet");
}

Eigen::Matrix3d cauchy_stress(const Eigen::Matrix3d& P, const Eigen::Matrix3d& F) {
  return P * F.transpose() / F.determinant();
}

}  // namespace xfem
