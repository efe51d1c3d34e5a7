// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/io/matrix_market.h"

namespace xfem {

/// PETSc's binary format (what MatView / VecView write to a PETSC_VIEWER_BINARY and MatLoad /
/// VecLoad read, also in parallel, each rank only its rows; petsc4py and PETSc's
/// lib/petsc/bin/PetscBinaryIO.py read it too). Everything big-endian, 32-bit integers
/// (PETSc built without 64-bit indices), IEEE doubles:
///   matrix (AIJ):  int32 1211216, rows M, columns N, non-zeros nz; int32 row lengths [M];
///                  int32 column indices [nz], 0-based, row by row, increasing in a row;
///                  double values [nz]
///   vector:        int32 1211214, length n; double values [n]
/// Implemented here without PETSc, so that CHOLMOD builds and Python read the same files.
constexpr int kPetscMatClassId = 1211216;
constexpr int kPetscVecClassId = 1211214;

/// Writes the symmetric matrix whose lower triangle `K` holds (its upper triangle is ignored) as
/// a full square AIJ matrix, both triangles (MatLoad into AIJ, what GAMG needs). Not atomic
/// (the system directory is written under a temporary name as a whole).
void write_petsc_symmetric_matrix(const SparseMatrix& K, const std::string& path);

/// Reads a PETSc binary AIJ matrix. Throws xfem::Error naming `path` and what is wrong: wrong
/// class id, negative sizes, a file size that disagrees with the header (truncated or trailing
/// bytes), row lengths not summing to nz, a column index out of range or not increasing in its
/// row, a non-finite value.
SparseMatrix read_petsc_matrix(const std::string& path);

/// The header of a PETSc binary AIJ matrix file, checked against the file's size (what a rank
/// can check before MatLoad without reading the rest). Throws like read_petsc_matrix.
struct PetscMatrixHeader {
  long rows = 0, cols = 0, nonzeros = 0;
};
PetscMatrixHeader read_petsc_matrix_header(const std::string& path);

/// Only some rows of a symmetric matrix's PETSc binary file: a cols x rows matrix whose column d
/// is the file's row d for every d in `rows` (= column d of the symmetric matrix), the other
/// columns empty. Reads the row lengths and those rows alone (what the reactions K u - f on the
/// constrained DOFs need, without the whole K). Throws like read_petsc_matrix, and for a row
/// outside the matrix; does not check the symmetry.
SparseMatrix read_petsc_symmetric_matrix_rows(const std::string& path, const std::vector<long>& rows);

/// Writes / reads a PETSc binary vector (same checks as the matrix reader).
void write_petsc_vector(const Eigen::VectorXd& v, const std::string& path);
Eigen::VectorXd read_petsc_vector(const std::string& path);

}  // namespace xfem
