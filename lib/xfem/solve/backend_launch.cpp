// SPDX-License-Identifier: MIT
#include "xfem/solve/backend_launch.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/thread_limit.h"
#include "xfem/core/version.h"
#include "xfem/io/petsc_binary.h"
#include "xfem/solve/petsc_solver.h"
#include "xfem/solve/watched_child.h"
#include "xfem/system/linear_system.h"

namespace xfem {

bool under_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

std::string petsc_program(const char* argv0, bool links_petsc, const std::string& helper_name) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path me = ec ? std::filesystem::path(argv0) : self;
  if (links_petsc) return me.string();
  const auto helper = me.parent_path() / helper_name;
  if (!have_petsc || !std::filesystem::exists(helper))
    throw Error("the PETSc backend needs " + helper.string() + (have_petsc ? ", which is missing" :
                ": this build has no PETSc (CMake did not find it)") +
                ": use --backend cholmod, or install libpetsc-real-dev and rebuild");
  return helper.string();
}

namespace {

// The command line that runs `program` with this process's arguments, under
// `mpirun -np P` when `processes` > 1 (the ranks see the MPI environment and do not restart again).
std::vector<std::string> command_line(const std::string& program, int processes, int argc, char** argv) {
  std::vector<std::string> args;
  if (processes > 1) {
    // --quiet: no banner of mpirun's own when a rank exits with an error (the rank's one line says it).
    args = {"mpirun", "--quiet", "-np", std::to_string(processes), "--oversubscribe", "--bind-to", "none"};
    // Waiting ranks yield the core instead of busy-polling (unless the user chose otherwise): on
    // a machine whose cores other jobs share, polling ranks took 1.7x the wall time (256k
    // reference, 2 ranks, load 9: 25.8 and 36.3 s polling against 14.1 and 22.3 s yielding).
    ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
    if (::geteuid() == 0) {  // Open MPI refuses root unless told twice
      args.push_back("--allow-run-as-root");
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    }
  }
  args.push_back(program);
  for (int k = 1; k < argc; ++k) args.emplace_back(argv[k]);
  ::setenv("XFEM_OPTIONS_SHOWN", "1", 1);  // -v: this process has printed them (cli.cpp)
  return args;
}

// Identifies the file at `path` (or its absence), to tell whether a child wrote it.
struct FileStamp {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  timespec mtime{};
  explicit FileStamp(const std::string& path) {
    struct stat st;
    exists = ::stat(path.c_str(), &st) == 0;
    if (exists) dev = st.st_dev, ino = st.st_ino, mtime = st.st_mtim;
  }
  bool operator==(const FileStamp& o) const {
    return exists == o.exists && dev == o.dev && ino == o.ino && mtime.tv_sec == o.mtime.tv_sec &&
           mtime.tv_nsec == o.mtime.tv_nsec;
  }
};

// This process becomes `program` with the same arguments (execv); returns only by throwing.
[[noreturn]] void become(const std::string& program, int argc, char** argv) {
  const std::vector<std::string> args = command_line(program, 1, argc, argv);
  std::vector<char*> cargs;
  for (const auto& a : args) cargs.push_back(const_cast<char*>(a.c_str()));
  cargs.push_back(nullptr);
  std::fflush(stderr);
  ::execv(program.c_str(), cargs.data());
  throw Error("cannot start " + program + ": " + std::strerror(errno));
}

}  // namespace

std::string run_program(const std::string& program, int processes, int argc, char** argv, const std::string& output,
                        const std::string& own_prefix) {
  const std::vector<std::string> args = command_line(program, processes, argc, argv);
  const std::string what = processes > 1 ? "mpirun -np " + std::to_string(processes) + " " +
                                               std::filesystem::path(program).filename().string()
                                         : program;
  const FileStamp before(output);
  const WatchedRun run = run_watched(args, processes > 1, own_prefix);
  if (!run.started) return run.exec_error;
  const bool written = output == "-" || (FileStamp(output).exists && !(FileStamp(output) == before));
  if (!run.signaled && run.status == 0 && written) {
    for (const std::string& line : run.other_lines) std::cerr << line << "\n";  // e.g. PETSc's warnings
    std::exit(0);
  }
  // The child's own one-line error is the message (Open MPI's follow-up texts add nothing).
  if (run.printed_error && !run.signaled && run.status != 0) std::exit(run.status);
  std::string said = first_meaningful_line(run.other_lines);
  said = said.empty() ? "it printed nothing" : "\"" + said + "\"";
  const std::string hint = processes > 1 ? " (do the MPI processes start and reach each other? --np 1 or --backend "
                                           "cholmod solve without mpirun)"
                                         : " (can Open MPI start? --backend cholmod solves without MPI)";
  if (!run.signaled && run.status == 0)
    throw Error(what + " exited 0 without writing " + output + ": " + said +
                " (is the mpirun on PATH Open MPI's launcher?)");
  throw Error(what + " failed (" + describe_status(run) + "), no output written: " + said + hint);
}

std::string launch_backend(const std::string& dir, std::string backend, int processes, bool links_petsc, int argc,
                           char** argv, const std::string& output) {
  const bool mpi_child = under_mpirun();
  if (backend == "auto" || (backend == "petsc" && !mpi_child)) {
    // The choice from the system without K (cheap), the same in every rank of a restart.
    // No manifest check here: the process that solves reads the system again and checks it (each
    // PETSc rank before it loads its rows of K), and an mtx K's own errors come first there.
    const LinearSystem head = read_linear_system(dir, false, false);
    const long dofs = 3 * head.n;
    if (backend == "auto") backend = processes > 1 ? "petsc" : automatic_backend(dofs, head.n > head.np);
    if (backend == "petsc" && !mpi_child) {
      const int wanted = processes > 0 ? processes
                                       : automatic_processes(dofs, thread_limit());
      if (wanted > 1) {
        const std::string program = petsc_program(argv[0], links_petsc);
        // The checks a rank would fail on, here once: one error line instead of one per rank.
        const std::string k_path = system_matrix_file(dir, system_format(dir));
        if (system_format(dir) == SystemFormat::Petsc) {
          const PetscMatrixHeader h = read_petsc_matrix_header(k_path);
          if (h.rows != dofs || h.cols != dofs)
            throw Error(k_path + ": " + std::to_string(h.rows) + " x " + std::to_string(h.cols) +
                        ", expected 3N x 3N = " + std::to_string(dofs) + " x " + std::to_string(dofs));
        }
        cli::detail("starting " + std::to_string(wanted) + " PETSc processes under mpirun");
        run_program(program, wanted, argc, argv, output);
        cli::warn("cannot start mpirun (Open MPI's launcher not on PATH?): solving on 1 process");
      }
    }
  }
  // One process (or one rank of a user's mpirun): the PETSc program takes over with the same
  // arguments; it decides again from the same files, so it comes to the same choice.
  if (!links_petsc && backend == "petsc") {
    const std::string program = petsc_program(argv[0], links_petsc);
    if (mpi_child) become(program, argc, argv);  // a rank of the user's mpirun: the PETSc program becomes this rank
    throw Error("cannot start " + program + ": " + run_program(program, 1, argc, argv, output));
  }
  return backend;
}

std::string launch_program_backend(std::string backend, long dofs, bool enriched, int processes, bool links_petsc,
                                   const std::string& helper, const std::string& own_prefix, int argc, char** argv,
                                   const std::string& output) {
  const bool mpi_child = under_mpirun();
  if (backend == "auto") backend = processes > 1 ? "petsc" : automatic_backend(dofs, enriched);
  if (backend != "petsc") return backend;
  if (!mpi_child) {
    const int wanted = processes > 0 ? processes : automatic_processes(dofs, thread_limit());
    if (wanted > 1) {
      const std::string program = petsc_program(argv[0], links_petsc, helper);
      cli::detail("starting " + std::to_string(wanted) + " PETSc processes under mpirun");
      run_program(program, wanted, argc, argv, output, own_prefix);
      cli::warn("cannot start mpirun (Open MPI's launcher not on PATH?): solving on 1 process");
    }
  }
  if (links_petsc) return backend;
  // One process (or one rank of a user's mpirun): the PETSc program takes over with the same arguments.
  const std::string program = petsc_program(argv[0], links_petsc, helper);
  if (mpi_child) become(program, argc, argv);
  throw Error("cannot start " + program + ": " + run_program(program, 1, argc, argv, output, own_prefix));
}

}  // namespace xfem
