// SPDX-License-Identifier: MIT
#include "xfem/cli.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <memory>

#include "xfem/version.h"

namespace xfem::cli {
namespace {
// The running tool; logging is process-wide, like stderr itself.
const Tool* current = nullptr;

std::string prefix() { return current ? current->name + ": " : std::string(); }

// Makes `current` point at the running tool for the duration of run(), so that logging after
// the tool is gone (in tests, another tool) never reads a dangling pointer.
struct CurrentTool {
  explicit CurrentTool(const Tool& tool) : previous(current) { current = &tool; }
  ~CurrentTool() { current = previous; }
  const Tool* previous;
};

// Errors are printed as one line: a message spanning lines (an exception text quoting a file)
// would break the "<tool>: error: <what>" contract that scripts grep for.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}
}  // namespace

Tool::Tool(const std::string& tool_name, const std::string& description)
    : app(description, tool_name), name(tool_name) {}

std::unique_ptr<Tool> make_tool(const std::string& name, const std::string& description,
                                const std::string& example) {
  auto tool = std::make_unique<Tool>(name, description);
  // Defaults show in --help and in the -v echo of the effective options.
  tool->app.option_defaults()->always_capture_default();
  tool->app.set_version_flag("--version", name + " " + version + (have_petsc ? " (petsc)" : ""));
  tool->app.add_flag("-q,--quiet", tool->quiet, "no progress or info on stderr (warnings and errors still show)");
  tool->app.add_flag("-v,--verbose", tool->verbose, "more detail on stderr (repeatable)");
  if (!example.empty()) tool->app.footer("Example:\n  " + example);
  return tool;
}

int run(Tool& tool, int argc, char** argv, const std::function<void()>& body) {
  const CurrentTool scope(tool);
  try {
    tool.app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return tool.app.exit(e);  // help text to stdout, 0
  } catch (const CLI::CallForAllHelp& e) {
    return tool.app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return tool.app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool.name << ": usage error: " << one_line(e.what()) << " (try " << tool.name << " --help)\n";
    return 2;
  }
  if (tool.quiet && tool.verbose) {
    std::cerr << tool.name << ": usage error: -q and -v exclude each other (try " << tool.name
              << " --help)\n";
    return 2;
  }
  if (tool.verbose) std::cerr << tool.name << ": options:\n" << tool.app.config_to_str(true, false);
  try {
    body();
  } catch (const std::bad_alloc&) {
    std::cerr << tool.name << ": error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << tool.name << ": error: " << one_line(e.what()) << "\n";
    return 1;
  }
  return 0;
}

void info(const std::string& message) {
  if (current && current->quiet) return;
  std::cerr << prefix() << message << "\n";
}

void detail(const std::string& message) {
  if (!current || current->verbose == 0) return;
  std::cerr << prefix() << message << "\n";
}

void warn(const std::string& message) { std::cerr << prefix() << "warning: " << message << "\n"; }

std::function<void(double)> progress(const std::string& what) {
  auto last = std::make_shared<int>(-1);
  return [what, last](double fraction) {
    if (current && current->quiet) return;
    // Clamped, so that a caller overshooting 1 (or passing NaN) still prints at most 11 lines.
    const double f = fraction >= 0 ? std::min(fraction, 1.0) : 0.0;
    const int step = static_cast<int>(f * 10.0 + 1e-9);
    if (step <= *last) return;
    *last = step;
    std::cerr << prefix() << what << " " << step * 10 << "%\n";
  };
}

double now() {
  using clock = std::chrono::steady_clock;
  static const auto start = clock::now();
  return std::chrono::duration<double>(clock::now() - start).count();
}

}  // namespace xfem::cli
