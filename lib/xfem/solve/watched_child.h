// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

namespace xfem {

/// How a program run by run_watched() ended.
struct WatchedRun {
  bool started = false;          ///< false: it could not be executed (`exec_error` says why)
  std::string exec_error;        ///< strerror of the failed exec
  bool signaled = false;         ///< killed by signal `status`, else exited with `status`
  int status = 0;
  bool printed_error = false;    ///< it printed a line "<own_prefix>error: ..." (passed on)
  std::vector<std::string> other_lines;  ///< its stderr lines not starting with `own_prefix`, held back
};

/// Runs `args` (args[0] found on PATH when `search_path`, else a path) as a child process and
/// waits for it. Its stderr is read line by line: lines starting with `own_prefix` (the tool's own
/// messages, "xfem-solve: ...") are passed on to stderr at once; the others (Open MPI's and
/// PETSc's, often dozens of lines for one problem) are held back for the caller to summarise or
/// pass on. The child dies with this process.
WatchedRun run_watched(const std::vector<std::string>& args, bool search_path, const std::string& own_prefix);

/// The first meaningful line of `lines`: blank lines, rules of dashes or stars and "[host:pid]"
/// or "***" prefixes skipped; a sentence broken over lines joined up to its end (at most 200
/// characters). "" when there is none.
std::string first_meaningful_line(const std::vector<std::string>& lines);

/// "exit status 1", "killed by signal 9 (Killed)".
std::string describe_status(const WatchedRun& run);

}  // namespace xfem
