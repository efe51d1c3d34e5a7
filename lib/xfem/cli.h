// SPDX-License-Identifier: MIT
#pragma once
#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <string>

namespace xfem::cli {

/// A command-line tool: a CLI11 app with the options every xfem tool shares
/// (-h/--help, --version, -q/--quiet, -v/--verbose).
struct Tool {
  CLI::App app;
  std::string name;
  bool quiet = false;
  int verbose = 0;  ///< how often -v was given
  Tool(const std::string& name, const std::string& description);
};

/// Makes a tool; `example` is shown under "Example:" at the end of --help.
std::unique_ptr<Tool> make_tool(const std::string& name, const std::string& description,
                                const std::string& example);

/// Parses the command line and runs `body`. Returns the process exit code: 0 on success,
/// 1 when `body` throws (bad input, failed computation: one line "<tool>: error: <what>" on
/// stderr), 2 on a usage error (with a hint to try --help). --help and --version print to stdout
/// and return 0.
int run(Tool& tool, int argc, char** argv, const std::function<void()>& body);

/// Logging on stderr, prefixed with the tool's name. `info` is silenced by -q; `detail` needs -v;
/// `warn` always shows.
void info(const std::string& message);
void detail(const std::string& message);
void warn(const std::string& message);

/// A progress callback for long lib/ routines: prints "<tool>: <what> 10% ... 100%" on stderr in
/// steps of 10% (nothing under -q). Call with fraction in [0, 1].
std::function<void(double)> progress(const std::string& what);

/// Wall-clock seconds since `start` (from `now()`), for the timings tools report.
double now();

}  // namespace xfem::cli
