// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "xfem/core/json_io.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

/// One connected piece of the (possibly cut) body, as xfem-assemble sees it: the solver names a
/// piece without a Dirichlet condition when the system is singular.
struct Piece {
  long tets = 0;            ///< tets (or tet halves) in the piece
  bool constrained = false; ///< does any Dirichlet condition act on it?
};

/// How K, f and the coordinates are stored in the system directory.
///   Petsc: PETSc's binary format (K.petsc: full AIJ matrix; f.petsc, coordinates.petsc: vectors;
///          lib/xfem/petsc_binary.h): compact, exact, and loaded by MatLoad in parallel (each
///          rank reads only its rows). The default.
///   MatrixMarket: text (K.mtx, f.mtx, coordinates.mtx), for scipy.io.mmread and other readers.
enum class SystemFormat { Petsc, MatrixMarket };

/// The assembled system K u = f with its Dirichlet data (the contract between xfem-assemble and
/// xfem-solve; the directory layout is documented in docs/FORMATS.md):
///   K.petsc | K.mtx          3N x 3N (K.mtx: Matrix Market `coordinate real symmetric`, lower triangle)
///   f.petsc | f.mtx          3N
///   dirichlet.mtx  Matrix Market `coordinate real general`, 3N x 1: one entry per constrained
///                  scalar DOF (row 3k + i + 1, the prescribed value in metres)
///   coordinates.petsc | coordinates.mtx  optional, 3 NP: entry 3k + i is coordinate i of mesh
///                  point k in metres (the rigid-body modes for PETSc's GAMG)
///   dirichlet_conditions.json, provenance.json  optional (xfem-assemble writes both)
///   system.json    format, np, ns, nb, n, dofs (= 3N), nonzeros, fixed, pieces, coordinates,
///                  generator, and `files`: the manifest, each other file's size in bytes and the
///                  fnv1a64 of its bytes; written last: the marker that the directory is complete,
///                  and what ties its files to each other (read_linear_system checks it)
/// Scalar unknown of component i of the 3-vector U_k is 3k + i (docs/FORMATS.md).
struct LinearSystem {
  SparseMatrix K;                    ///< 3N x 3N; at least the lower triangle is filled
  Eigen::VectorXd f;                 ///< 3N, newtons
  std::vector<long> fixed;           ///< constrained scalar DOFs, strictly increasing
  std::vector<double> fixed_values;  ///< prescribed values, metres, same order as `fixed`
  long np = 0, ns = 0, nb = 0, n = 0; ///< N = NP + NS + 4 NB 3-vectors (paper 3.3)
  std::vector<Piece> pieces;         ///< may be empty (unknown)
  /// NP x 3 mesh point coordinates in metres (row k = point k = original 3-vector k), or empty
  /// (0 x 3 / 0 x 0: unknown). Lets the PETSc backend build the rigid-body near-null space.
  Eigen::MatrixXd coordinates;
};

/// Writes `system` as directory `dir`, atomically as a whole: the files go into a temporary
/// directory next to it (".NAME.tmpPID"), system.json last, which then takes the place of `dir`
/// (rename; an existing `dir` is swapped out and removed only after the new one is in place).
/// A failed write removes the temporary directory and leaves an existing `dir` untouched; an
/// interrupted one leaves at most the temporary directory. Refuses to replace an existing
/// directory holding files that are not part of a system. Parent directories are created.
/// `generator` goes into system.json ("xfem-assemble 0.1.0"). `write_more`, when given, writes
/// further files into the temporary directory it is passed (before system.json, so that the
/// manifest covers them and they appear with the system, never after it): xfem-assemble's
/// dirichlet_conditions.json and provenance.json.
void write_linear_system(const LinearSystem& system, const std::string& dir, const std::string& generator,
                         SystemFormat format = SystemFormat::Petsc,
                         const std::function<void(const std::string& tmp_dir)>& write_more = {});

/// Checks `system` is consistent (N = NP + NS + 4 NB, K square 3N x 3N, f 3N, fixed strictly
/// increasing and < 3N, one value per fixed DOF, coordinates NP x 3 or empty); throws
/// xfem::Error naming `where` and the problem. write/read call it.
void check_linear_system(const LinearSystem& system, const std::string& where);

/// Reads a directory written by write_linear_system (either format) and checks it is consistent
/// (sizes agree with dofs = 3N, fixed DOFs in range, K symmetric). K comes back as its full
/// symmetric matrix. Throws xfem::Error naming the file and the problem, e.g.
/// "out/system/f.mtx: 12 rows, expected 3N = 24 (is this xfem-assemble output?)"; a directory
/// without system.json is refused as incomplete. Then every file is checked against system.json's
/// manifest (size and fnv1a64 of its bytes; a listed file missing, a system file not listed, or
/// a system.json without a manifest, written before manifests existed, are refused): a file
/// truncated, edited or copied from another assembly is never solved.
/// With `with_matrix` false, K is left empty (0 x 0): for the PETSc backend, whose ranks load
/// only their rows of K themselves (system_matrix_file); a binary K's header is still checked, and
/// K's bytes against the manifest, before any rank loads it. With `check_manifest` false the
/// manifest is not checked: for a quick look at the sizes by a process that does not solve (the
/// launcher of the PETSc ranks, each of which reads the system again and checks it).
LinearSystem read_linear_system(const std::string& dir, bool with_matrix = true, bool check_manifest = true);

/// The format of the system in `dir` (from its system.json; Matrix Market when it names none, as
/// in directories written before the binary format). Throws like read_linear_system.
SystemFormat system_format(const std::string& dir);

/// The file holding K in `dir`: DIR/K.petsc or DIR/K.mtx.
std::string system_matrix_file(const std::string& dir, SystemFormat format);

}  // namespace xfem
