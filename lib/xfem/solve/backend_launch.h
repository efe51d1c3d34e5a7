// SPDX-License-Identifier: MIT
#pragma once
#include <string>

namespace xfem {

/// True in a process that mpirun started (Open MPI, MPICH's PMI or PMIx set these variables).
bool under_mpirun();

/// PETSc and Open MPI take ~40 ms to load on a quiet machine (more than a small CHOLMOD solve), so
/// xfem-solve does not link them: the PETSc backend is the same program built with PETSc,
/// xfem-solve-petsc, next to it. The path of that program, or of this one when `links_petsc`
/// (this program is it; `argv0`: its argv[0], used when /proc/self/exe cannot be read). Throws
/// xfem::Error when the PETSc program is missing or this build has no PETSc. `helper`: the PETSc
/// program's name (xfem-newton's is xfem-newton-petsc).
std::string petsc_program(const char* argv0, bool links_petsc, const std::string& helper = "xfem-solve-petsc");

/// Runs `program` with this process's arguments as a child, under `mpirun -np P` when
/// `processes` > 1 (the ranks see the MPI environment and do not restart again), and ends this
/// process with the child's result: exit 0 when the child exited 0 and wrote `output` ("-":
/// stdout, not checked); the child's exit status when it printed its own "xfem-solve: error:"
/// line. Otherwise (it failed silently, was killed, or exited 0 without writing `output`) throws
/// xfem::Error with its exit status and the first meaningful line of its stderr, which is held
/// back, not passed through (Open MPI prints dozens of lines for one problem). Returns only
/// when the program cannot be started: why.
/// `own_prefix`: how the program's own messages begin ("xfem-newton: " for xfem-newton's).
std::string run_program(const std::string& program, int processes, int argc, char** argv, const std::string& output,
                        const std::string& own_prefix = "xfem-solve: ");

/// xfem-solve's backend for the system directory `dir`: `backend` ("auto", "cholmod" or "petsc")
/// decided from the system's size when "auto" (without reading K: the same choice in every rank
/// of a restart), and `processes` (0: automatic) for PETSc. When PETSc wants more than one
/// process and this process is not under mpirun, restarts the PETSc program under mpirun with the
/// same arguments (falling back to one process, with a warning, when mpirun cannot be started);
/// when this program does not link PETSc (`links_petsc` false) and the backend is PETSc, the
/// PETSc program takes over with the same arguments (it decides again from the same files, so it
/// comes to the same choice). Those restarts are checked by run_program() (`output`: the solution
/// file they must write). Returns the backend this process runs: "cholmod", or "petsc" when it
/// links PETSc.
std::string launch_backend(const std::string& dir, std::string backend, int processes, bool links_petsc, int argc,
                           char** argv, const std::string& output);

/// launch_backend() for a program that decides from its own input (xfem-newton, `dofs` and
/// `enriched` from its mesh): `backend` "auto" (automatic_backend), "cholmod" or "petsc";
/// `processes` (0: automatic) for PETSc; restarts `helper` (the program built with PETSc, e.g.
/// xfem-newton-petsc) under mpirun, or lets it take over on one process, exactly as
/// launch_backend() does, checked by run_program() with `own_prefix`. Returns the backend this
/// process runs.
std::string launch_program_backend(std::string backend, long dofs, bool enriched, int processes, bool links_petsc,
                                   const std::string& helper, const std::string& own_prefix, int argc, char** argv,
                                   const std::string& output);

}  // namespace xfem
