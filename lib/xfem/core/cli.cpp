// SPDX-License-Identifier: MIT
#include "xfem/core/cli.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/core/thread_limit.h"
#include "xfem/core/version.h"

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

// Length of the valid UTF-8 sequence starting at text[i] (a byte >= 0x80), 0 when it is not one.
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  const std::size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return 0;
  return n;
}

}  // namespace

std::string short_numbers(const std::string& text) {
  // std::to_string of a double, as CLI11's range checks print their bounds ("0.000000 to
  // 1797693...(309 digits).000000"): a number longer than 20 characters (more than any 64-bit
  // integer) in short form, a whole number without its ".000000".
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/'; };
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = i;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    if (end > i && end < text.size() && text[end] == '.')
      for (++end; end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]));) ++end;
    const bool alone = (i == 0 || !word(text[i - 1])) && (end == text.size() || !word(text[end]));
    const std::string number = text.substr(i, end - i);
    const bool whole = number.size() > 7 && number.compare(number.size() - 7, 7, ".000000") == 0;
    if (alone && (i == 0 || text[i - 1] != '.') && (number.size() > 20 || whole)) {
      // "0.000000" -> "0" (std::to_string's six decimals of a whole number), 309 digits -> "1.79769e+308"
      out += number.size() - (whole ? 7 : 0) > 20 ? xfem::short_number(std::strtod(number.c_str(), nullptr))
                                                  : number.substr(0, number.size() - 7);
      i = end;
    } else if (end > i) {
      out.append(text, i, end - i);
      i = end;
    } else {
      out += text[i++];
    }
  }
  return out;
}

std::string printable_line(const std::string& text, std::size_t max_chars) {
  std::string out;
  std::size_t i = 0;
  for (; i < text.size() && out.size() < max_chars; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 1;
    if (c == '\n' || c == '\r' || c == '\t') {
      out += ' ';
    } else if (c < 0x20 || c == 0x7f || n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out.append(text, i, n);
      i += n - 1;
    }
  }
  if (i < text.size()) out += "...";
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

namespace {

// Errors are printed as one printable line: a message spanning lines (an exception text quoting
// a file) would break the "<tool>: error: <what>" contract that scripts grep for, and the bytes
// of a corrupt file it quotes would reach the terminal raw.
std::string one_line(const std::string& text) { return printable_line(short_numbers(text), 2000); }

// True when `token` is entirely a number that is not finite ("nan", "-inf", "1e999").
bool non_finite_number(const std::string& token) {
  if (token.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(v);
}

bool is_option(const std::string& token) {
  if (token.size() < 2 || token[0] != '-') return false;
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return end != token.c_str() + token.size();  // "-5" and "-inf" are values, "--hi" is not
}

// The option name (with dashes) that a non-finite value is given to, or "" when none is: then
// the tool itself never sees NaN or Inf in a numeric option.
std::string non_finite_option(int argc, char** argv, std::string* value) {
  std::string option;
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") break;
    if (is_option(token)) {
      const std::size_t eq = token.find('=');
      option = token.substr(0, eq);
      if (eq != std::string::npos && non_finite_number(token.substr(eq + 1))) {
        *value = token.substr(eq + 1);
        return option;
      }
      continue;
    }
    if (!option.empty() && non_finite_number(token)) {
      *value = token;
      return option;
    }
  }
  return "";
}

void collect_names(const CLI::App& app, std::vector<std::string>* options, std::vector<std::string>* commands) {
  for (const CLI::Option* o : app.get_options()) {
    for (const auto& n : o->get_lnames()) options->push_back("--" + n);
    for (const auto& n : o->get_snames()) options->push_back("-" + n);
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    commands->push_back(sub->get_name());
    std::vector<std::string> ignored;
    collect_names(*sub, options, &ignored);
  }
}

// "did you mean" for the first unknown subcommand or option on the command line.
std::string suggestion(const CLI::App& app, int argc, char** argv) {
  std::vector<std::string> options, commands;
  collect_names(app, &options, &commands);
  if (!commands.empty() && argc > 1 && argv[1][0] != '-' &&
      std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
    const std::string near = closest(argv[1], commands);
    return "unknown command '" + std::string(argv[1]) + "'" +
           (near.empty() ? "" : " (did you mean '" + near + "'?)");
  }
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (!is_option(token)) continue;
    const std::string name = token.substr(0, token.find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    const std::string near = closest(name, options);
    return "unknown option " + name + (near.empty() ? "" : " (did you mean " + near + "?)");
  }
  return "";
}

// Required options have no default to show: "--hi ... =[0,0,0] REQUIRED" misleads.
void hide_required_defaults(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    if (o->get_required()) o->default_str("");
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) hide_required_defaults(*sub);
}

CLI::Validator number_check(const std::string& name, std::function<bool(double)> ok, const std::string& what) {
  return CLI::Validator(
      [ok, what](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
        if (!ok(v)) return "value " + xfem::short_number(v) + " is not " + what;
        return "";
      },
      name);
}

}  // namespace

CLI::Validator range(double lo, double hi) {
  const std::string span = "in [" + xfem::short_number(lo) + ", " + xfem::short_number(hi) + "]";
  return number_check("FLOAT " + span, [lo, hi](double v) { return v >= lo && v <= hi; }, span);
}
CLI::Validator positive() {
  return number_check("POSITIVE", [](double v) { return std::isfinite(v) && v > 0; }, "a positive number");
}
CLI::Validator non_negative() {
  return number_check("NONNEGATIVE", [](double v) { return std::isfinite(v) && v >= 0; }, "a non-negative number");
}

void check_output(const std::string& path, const std::vector<std::string>& extensions, bool stdout_ok) {
  namespace fs = std::filesystem;
  if (path == "-") {
    if (stdout_ok) return;
    throw Error("-: this output cannot go to stdout; give a file name");
  }
  if (!extensions.empty() &&
      std::find(extensions.begin(), extensions.end(), extension_of(path)) == extensions.end()) {
    std::string list;
    for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
    throw Error(path + ": unknown extension '" + extension_of(path) + "' (expected " + list + ")");
  }
  const fs::path target(path);
  if (fs::is_directory(target)) throw Error(path + ": is a directory, expected a file name");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw Error(path + ": directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK) != 0) throw Error(path + ": directory " + dir.string() + " is not writable");
}

void check_output_directory(const std::string& path) {
  // The directory is created if missing: its nearest existing ancestor must be writable.
  std::filesystem::path dir = std::filesystem::absolute(path);
  while (!std::filesystem::exists(dir) && dir.has_parent_path() && dir != dir.parent_path()) dir = dir.parent_path();
  if (!std::filesystem::is_directory(dir)) throw Error(path + ": " + dir.string() + " is not a directory");
  if (::access(dir.c_str(), W_OK) != 0) throw Error(path + ": directory " + dir.string() + " is not writable");
}

std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    // Levenshtein distance, one row at a time.
    std::vector<std::size_t> row(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= word.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= c.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (word[i - 1] == c[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    if (row[c.size()] < best_distance) {
      best_distance = row[c.size()];
      best = c;
    }
  }
  return best;
}

Tool::Tool(const std::string& tool_name, const std::string& description)
    : app(description, tool_name), name(tool_name) {}

std::unique_ptr<Tool> make_tool(const std::string& name, const std::string& description,
                                const std::string& example) {
  auto tool = std::make_unique<Tool>(name, description);
  // Defaults show in --help and in the -v echo of the effective options.
  tool->app.option_defaults()->always_capture_default();
  tool->app.set_version_flag("--version", name + " " + version + (have_petsc ? " (petsc)" : ""));
  tool->app.add_flag("-q,--quiet", tool->quiet, "errors only on stderr: no progress, info or warnings");
  tool->app.add_flag("-v,--verbose", tool->verbose, "more detail on stderr (repeatable)");
  if (!example.empty()) tool->app.footer("Example:\n  " + example);
  return tool;
}

void add_threads_option(Tool& tool) {
  tool.app
      .add_option("--threads", tool.threads,
                  "the most threads to use (parallel loops, BLAS and OpenMP teams; the results are the same "
                  "for any count): default OMP_NUM_THREADS, else one per core, at most 8")
      ->check(CLI::Range(1, kMaxThreads))
      ->option_text("N");
}

int run(Tool& tool, int argc, char** argv, const std::function<void()>& body) {
  const CurrentTool scope(tool);
  hide_required_defaults(tool.app);
  std::string bad_value;
  const std::string bad_option = non_finite_option(argc, argv, &bad_value);
  if (!bad_option.empty()) {
    std::cerr << tool.name << ": usage error: " << bad_option << " " << bad_value
              << ": not a finite number (try " << tool.name << " --help)\n";
    return 2;
  }
  // A bad OMP_NUM_THREADS before the command line's own errors (it would be the next one), but not
  // in the way of --help and --version.
  std::string bad_threads;
  bool asks_help = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    asks_help = asks_help || a == "-h" || a == "--help" || a == "--version";
  }
  if (!asks_help && threads_from_environment(&bad_threads) < 0) {
    std::cerr << tool.name << ": usage error: " << printable_line(bad_threads, 200) << " (set a count or unset it)\n";
    return 2;
  }
  try {
    tool.app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return tool.app.exit(e);  // help text to stdout, 0
  } catch (const CLI::CallForAllHelp& e) {
    return tool.app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return tool.app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::string hint = suggestion(tool.app, argc, argv);
    std::cerr << tool.name << ": usage error: " << (hint.empty() ? one_line(e.what()) : hint) << " (try "
              << tool.name << " --help)\n";
    return 2;
  }
  if (tool.quiet && tool.verbose) {
    std::cerr << tool.name << ": usage error: -q and -v exclude each other (try " << tool.name
              << " --help)\n";
    return 2;
  }
  // --threads, else OMP_NUM_THREADS, passed on to the libraries' teams (VTK's does not read it).
  if (const int n = tool.threads > 0 ? tool.threads : threads_from_environment(); n > 0) set_thread_limit(n);
  // The options once per command: not again in the processes xfem-solve restarts itself as
  // (it sets XFEM_OPTIONS_SHOWN), nor in every rank of a user's mpirun.
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  if (tool.verbose && !std::getenv("XFEM_OPTIONS_SHOWN") && !(rank && std::string(rank) != "0"))
    std::cerr << tool.name << ": options:\n" << tool.app.config_to_str(true, false);
  try {
    body();
  } catch (const std::bad_alloc&) {
    std::cerr << tool.name << ": error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << tool.name << ": error: " << one_line(e.what()) << "\n";
    return 1;
  }
  if (std::getenv("XFEM_COUNT_THREADS"))  // the test hook of thread_limit.h
    std::cerr << tool.name << ": threads: at most " << thread_count_peak() << " at once\n";
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

void warn(const std::string& message) {
  if (current && current->quiet) return;
  std::cerr << prefix() << "warning: " << message << "\n";
}

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

std::string three_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

double now() {
  using clock = std::chrono::steady_clock;
  static const auto start = clock::now();
  return std::chrono::duration<double>(clock::now() - start).count();
}

}  // namespace xfem::cli
