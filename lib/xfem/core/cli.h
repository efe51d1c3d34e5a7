// SPDX-License-Identifier: MIT
#pragma once
#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace xfem::cli {

/// A command-line tool: a CLI11 app with the options every xfem tool shares
/// (-h/--help, --version, -q/--quiet, -v/--verbose).
struct Tool {
  CLI::App app;
  std::string name;
  bool quiet = false;
  int verbose = 0;  ///< how often -v was given
  int threads = 0;  ///< --threads (add_threads_option), 0 when not given
  Tool(const std::string& name, const std::string& description);
};

/// Makes a tool; `example` is shown under "Example:" at the end of --help.
std::unique_ptr<Tool> make_tool(const std::string& name, const std::string& description,
                                const std::string& example);

/// Adds --threads N to the tool (the most threads the run uses: parallel loops, OpenBLAS and
/// OpenMP teams; default OMP_NUM_THREADS, else one per core up to 8; thread_limit.h). One line in
/// each tool's main; run() applies it before the tool's body.
void add_threads_option(Tool& tool);

/// Parses the command line and runs `body`. Before parsing, any option value that reads as a
/// non-finite number ("nan", "inf", "1e999") is a usage error, so no numeric option ever sees NaN
/// or Inf; required options show no default in --help; an unknown subcommand or option gets a
/// "did you mean" suggestion. Returns the process exit code: 0 on success,
/// 1 when `body` throws (bad input, failed computation: one line "<tool>: error: <what>" on
/// stderr), 2 on a usage error (with a hint to try --help); either message passes through
/// short_numbers() and printable_line(). An OMP_NUM_THREADS that is set but not a whole number from
/// 1 to kMaxThreads is a usage error (every tool, with or without --threads). --help and --version print to stdout and return 0.
int run(Tool& tool, int argc, char** argv, const std::function<void()>& body);

/// Logging on stderr, prefixed with the tool's name. `info` and `warn` are silenced by -q (which
/// shows errors only); `detail` needs -v.
void info(const std::string& message);
void detail(const std::string& message);
void warn(const std::string& message);

/// A progress callback for long lib/ routines: prints "<tool>: <what> 10% ... 100%" on stderr in
/// steps of 10% (nothing under -q). Call with fraction in [0, 1].
std::function<void(double)> progress(const std::string& what);

/// Option checks with short numbers in their messages ("1e+300", never 309 digits); NaN fails
/// every one of them. `range` is inclusive.
CLI::Validator range(double lo, double hi);
CLI::Validator positive();
CLI::Validator non_negative();

/// Checks an output path before any work: its directory exists and is writable, and its
/// extension is one of `extensions` (lower case with the dot; empty = any). "-" (stdout) passes
/// when `stdout_ok`. Throws xfem::Error "<path>: ..." naming the problem.
void check_output(const std::string& path, const std::vector<std::string>& extensions, bool stdout_ok = false);

/// Checks an output directory before any work: the directory `path` (created later if missing)
/// has a nearest existing ancestor that is a writable directory. Throws xfem::Error "<path>: ...".
void check_output_directory(const std::string& path);

/// The suggestion for a mistyped `word` among `candidates` (closest by edit distance, at most
/// about a third of its letters off), or "" when none is close.
std::string closest(const std::string& word, const std::vector<std::string>& candidates);

/// `text` with every number longer than 20 characters (std::to_string of a large double, e.g.
/// the 309 digits of DBL_MAX in a CLI11 range check) in short form ("1.79769e+308"), and whole
/// numbers without std::to_string's ".000000" ("0.000000" -> "0").
std::string short_numbers(const std::string& text);

/// `text` as one printable line for a message: line breaks and tabs as spaces, other control
/// bytes and bytes that are not UTF-8 (a corrupt file's, quoted) as "\xNN", trailing spaces
/// dropped, cut after `max_chars` characters with "...".
std::string printable_line(const std::string& text, std::size_t max_chars);

/// `v` with three significant digits ("%.3g"): timings, residuals and times in messages.
std::string three_digits(double v);

/// Wall-clock seconds since `start` (from `now()`), for the timings tools report.
double now();

}  // namespace xfem::cli
