// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/io/matrix_market.h"
#include "xfem/system/contact_operator.h"

namespace xfem {

/// The contact pressure xfem-solve --contact-pressure writes (docs/FORMATS.md "contact
/// pressure"): Matrix Market `coordinate real general`, NP x C (C: the highest cut in contact + 1),
/// entry (i, k) the pressure of contact node i on cut k, Pa (>= 0; every contact node present,
/// zeros included). Between the nodes the pressure is interpolated with the linear shape
/// functions (the multipliers' space: one per node, docs/METHOD.md "Contact").
void write_contact_pressure(const ContactOperator& c, const Eigen::VectorXd& pressure, long np, const std::string& path);

/// Reads it back for a mesh of `np` nodes and `cuts` cuts (1 for a mesh with one cut). Throws
/// xfem::Error naming the file for another number of rows, more columns than cuts, or a value
/// that is negative or not finite.
SparseMatrix read_contact_pressure(const std::string& path, long np, int cuts);

}  // namespace xfem
