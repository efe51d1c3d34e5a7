// SPDX-License-Identifier: MIT
#include "xfem/core/cli.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <limits>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/core/version.h"

namespace {

// Redirects std::cout and std::cerr into strings for its lifetime.
struct Captured {
  std::ostringstream out, err;
  std::streambuf* old_out = std::cout.rdbuf(out.rdbuf());
  std::streambuf* old_err = std::cerr.rdbuf(err.rdbuf());
  ~Captured() {
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
  }
};

struct Result {
  int code = -1;
  bool ran = false;
  std::string out, err;
};

// Runs a test tool "xfem-test" (a required --cut, an optional -o) on `args` with `body`.
Result run_tool(std::vector<std::string> args, const std::function<void()>& body = [] {}) {
  auto tool = xfem::cli::make_tool("xfem-test", "Does nothing, for the CLI helper's tests.",
                                   "xfem-test --cut cut.vtp -o out.vtu");
  std::string cut, output = "-";
  tool->app.add_option("-c,--cut", cut, "cut surface")->required();
  tool->app.add_option("-o,--output", output, "output mesh ('-' = stdout)");
  args.insert(args.begin(), "xfem-test");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  Result r;
  Captured captured;
  r.code = xfem::cli::run(*tool, static_cast<int>(argv.size()), argv.data(), [&] {
    r.ran = true;
    body();
  });
  r.out = captured.out.str();
  r.err = captured.err.str();
  return r;
}

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST_CASE("cli: --help prints usage and the example on stdout and returns 0", "[cli]") {
  const Result r = run_tool({"--help"});
  CHECK(r.code == 0);
  CHECK_FALSE(r.ran);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::Contains("Does nothing, for the CLI helper's tests."));
  for (const char* option : {"--cut", "--output", "--quiet", "--verbose", "--version", "--help"}) {
    INFO(option);
    CHECK_THAT(r.out, Catch::Contains(option));
  }
  CHECK_THAT(r.out, Catch::EndsWith("Example:\n  xfem-test --cut cut.vtp -o out.vtu\n"));
  CHECK(run_tool({"-h"}).code == 0);
}

TEST_CASE("cli: --version prints the tool name and version and returns 0", "[cli]") {
  const Result r = run_tool({"--version"});
  CHECK(r.code == 0);
  CHECK_FALSE(r.ran);
  CHECK_THAT(r.out, Catch::StartsWith(std::string("xfem-test ") + xfem::version));
  CHECK(count_lines(r.out) == 1);
  CHECK(r.err.empty());
}

TEST_CASE("cli: an unknown flag is a usage error, exit 2, with a hint on stderr", "[cli]") {
  const Result r = run_tool({"--cut", "c.vtp", "--bogus"});
  CHECK(r.code == 2);
  CHECK_FALSE(r.ran);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::StartsWith("xfem-test: usage error: ") && Catch::Contains("--bogus") &&
                        Catch::EndsWith(" (try xfem-test --help)\n"));
  CHECK(count_lines(r.err) == 1);
}

TEST_CASE("cli: a missing required option is a usage error, exit 2", "[cli]") {
  const Result r = run_tool({"-o", "x.vtu"});
  CHECK(r.code == 2);
  CHECK_FALSE(r.ran);
  CHECK_THAT(r.err, Catch::StartsWith("xfem-test: usage error: ") && Catch::Contains("--cut is required") &&
                        Catch::EndsWith(" (try xfem-test --help)\n"));
  CHECK(count_lines(r.err) == 1);
}

TEST_CASE("cli: a body throwing xfem::Error exits 1 with one error line", "[cli]") {
  const Result r = run_tool({"--cut", "c.vtp"}, [] { throw xfem::Error("c.vtp: empty surface (0 points, 0 triangles)"); });
  CHECK(r.code == 1);
  CHECK(r.ran);
  CHECK(r.out.empty());
  CHECK(r.err == "xfem-test: error: c.vtp: empty surface (0 points, 0 triangles)\n");
  SECTION("a message spanning lines is printed on one") {
    const Result m = run_tool({"--cut", "c.vtp"}, [] { throw xfem::Error("first\nsecond\n"); });
    CHECK(m.code == 1);
    CHECK(m.err == "xfem-test: error: first second\n");
  }
  SECTION("other exceptions too") {
    const Result m = run_tool({"--cut", "c.vtp"}, [] { throw std::bad_alloc(); });
    CHECK(m.code == 1);
    CHECK(m.err == "xfem-test: error: out of memory\n");
  }
}

TEST_CASE("cli: a successful body exits 0 and sees the parsed options", "[cli]") {
  const Result r = run_tool({"--cut", "c.vtp", "-o", "out.vtu"}, [] { xfem::cli::info("working"); });
  CHECK(r.code == 0);
  CHECK(r.ran);
  CHECK(r.out.empty());  // logs never go to stdout: it carries data
  CHECK(r.err == "xfem-test: working\n");
}

TEST_CASE("cli: -q silences info, progress and warnings (errors only); -v enables detail", "[cli]") {
  auto body = [] {
    xfem::cli::info("an info");
    xfem::cli::detail("a detail");
    xfem::cli::warn("a warning");
    xfem::cli::progress("meshing")(1.0);
  };
  const Result normal = run_tool({"--cut", "c.vtp"}, body);
  CHECK(normal.err == "xfem-test: an info\nxfem-test: warning: a warning\nxfem-test: meshing 100%\n");
  const Result quiet = run_tool({"-q", "--cut", "c.vtp"}, body);
  CHECK(quiet.code == 0);
  CHECK(quiet.err.empty());
  const Result verbose = run_tool({"-v", "--cut", "c.vtp"}, body);
  CHECK(verbose.code == 0);
  CHECK_THAT(verbose.err, Catch::StartsWith("xfem-test: options:\n") && Catch::Contains("cut=\"c.vtp\"\n") &&
                              Catch::Contains("output='-'\n") &&
                              Catch::Contains("xfem-test: a detail\n"));
}

TEST_CASE("cli: -q together with -v is a usage error", "[cli]") {
  const Result r = run_tool({"-q", "-v", "--cut", "c.vtp"});
  CHECK(r.code == 2);
  CHECK_FALSE(r.ran);
  CHECK(r.err == "xfem-test: usage error: -q and -v exclude each other (try xfem-test --help)\n");
}

TEST_CASE("cli: progress prints at most 11 lines, 0% to 100% in steps of 10", "[cli]") {
  const Result r = run_tool({"--cut", "c.vtp"}, [] {
    auto progress = xfem::cli::progress("solving");
    for (int i = 0; i <= 1000; ++i) progress(i / 1000.0);
    progress(1.5);  // overshoot and nonsense are clamped, not printed as 150%
    progress(-1);
  });
  CHECK(count_lines(r.err) == 11);
  CHECK_THAT(r.err, Catch::StartsWith("xfem-test: solving 0%\nxfem-test: solving 10%\n") &&
                        Catch::EndsWith("xfem-test: solving 90%\nxfem-test: solving 100%\n"));
  const Result sparse = run_tool({"--cut", "c.vtp"}, [] {
    auto progress = xfem::cli::progress("solving");
    progress(0.55);
    progress(1.0);
  });
  CHECK(sparse.err == "xfem-test: solving 50%\nxfem-test: solving 100%\n");
}

TEST_CASE("cli: logging outside run() has no tool prefix", "[cli]") {
  run_tool({"--cut", "c.vtp"});
  Captured captured;
  xfem::cli::info("plain");
  xfem::cli::warn("careful");
  CHECK(captured.err.str() == "plain\nwarning: careful\n");
}

TEST_CASE("cli: a non-finite number given to any option is a usage error", "[cli]") {
  for (const char* value : {"nan", "NaN", "inf", "-inf", "1e999", "-1e400"}) {
    const Result r = run_tool({"--cut", "c.vtp", "-o", value});
    CHECK(r.code == 2);
    CHECK_FALSE(r.ran);
    CHECK(r.err == std::string("xfem-test: usage error: -o ") + value + ": not a finite number (try xfem-test --help)\n");
  }
  const Result eq = run_tool({"--cut=nan"});
  CHECK(eq.code == 2);
  CHECK_THAT(eq.err, Catch::Contains("--cut nan: not a finite number"));
  CHECK(run_tool({"--cut", "c.vtp", "-o", "-5"}).code == 0);  // finite negative numbers are values
}

TEST_CASE("cli: a mistyped option or subcommand gets a suggestion", "[cli]") {
  const Result r = run_tool({"--cutt", "c.vtp"});
  CHECK(r.code == 2);
  CHECK(r.err == "xfem-test: usage error: unknown option --cutt (did you mean --cut?) (try xfem-test --help)\n");
  CHECK(xfem::cli::closest("boxx", {"box", "organ", "cut-disc"}) == "box");
  CHECK(xfem::cli::closest("unstructured-bx", {"box", "unstructured-box"}) == "unstructured-box");
  CHECK(xfem::cli::closest("zzzzzz", {"box", "organ"}).empty());
}

TEST_CASE("cli: required options show no default in --help", "[cli]") {
  const Result r = run_tool({"--help"});
  CHECK_THAT(r.out, Catch::Contains("REQUIRED"));
  CHECK_THAT(r.out, !Catch::Contains("=\"\" REQUIRED") && !Catch::Contains("=[] REQUIRED"));
}

TEST_CASE("cli: range checks print numbers in short form and reject NaN", "[cli]") {
  const CLI::Validator v = xfem::cli::range(1, std::numeric_limits<double>::max());
  std::string text = "0.5";
  CHECK(v(text) == "value 0.5 is not in [1, 1.79769e+308]");
  text = "nan";
  CHECK_FALSE(v(text).empty());
  text = "2";
  CHECK(v(text).empty());
  std::string neg = "-5";
  CHECK(xfem::cli::non_negative()(neg) == "value -5 is not a non-negative number");
  std::string zero = "0";
  CHECK_FALSE(xfem::cli::positive()(zero).empty());
}

TEST_CASE("cli: outputs are checked before any work", "[cli]") {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_unit_cli";
  std::filesystem::create_directories(dir);
  CHECK_NOTHROW(xfem::cli::check_output((dir / "a.vtu").string(), {".vtu"}));
  CHECK_THROWS_WITH(xfem::cli::check_output((dir / "missing" / "a.vtu").string(), {".vtu"}),
                    Catch::EndsWith("does not exist"));
  CHECK_THROWS_WITH(xfem::cli::check_output((dir / "a.txt").string(), {".vtu", ".vtp"}),
                    Catch::EndsWith("a.txt: unknown extension '.txt' (expected .vtu, .vtp)"));
  CHECK_THROWS_WITH(xfem::cli::check_output("-", {".vtu"}), Catch::Contains("cannot go to stdout"));
  CHECK_NOTHROW(xfem::cli::check_output("-", {".json"}, true));
}

TEST_CASE("cli: messages carry short numbers and printable bytes only", "[cli][messages]") {
  using xfem::cli::printable_line;
  using xfem::cli::short_numbers;
  // CLI11's range check of a positive number: std::to_string of DBL_MIN and DBL_MAX.
  const std::string dbl_max = std::to_string(std::numeric_limits<double>::max());
  REQUIRE(dbl_max.size() == 316);  // 309 digits and ".000000"
  CHECK(short_numbers("Value -1 not in range " + std::to_string(std::numeric_limits<double>::min()) + " to " + dbl_max) ==
        "Value -1 not in range 0 to 1.79769e+308");
  CHECK(short_numbers("-" + dbl_max + ")") == "-1.79769e+308)");
  // What is not std::to_string's stays: integers up to 20 digits, decimals, names and paths.
  CHECK(short_numbers("18446744073709551615 rows, 0.5 m, 1.000001, x123456789012345678901234, "
                      "/tmp/123456789012345678901234/u.mtx") ==
        "18446744073709551615 rows, 0.5 m, 1.000001, x123456789012345678901234, /tmp/123456789012345678901234/u.mtx");
  // Control bytes and bytes that are not UTF-8 as \xNN; UTF-8 text and line breaks as they read.
  CHECK(printable_line("count '2\x01\xff' in caf\xc3\xa9.vtu\nline 2\t", 100) == "count '2\\x01\\xff' in caf\xc3\xa9.vtu line 2");
  CHECK(printable_line("\x7f\xc3", 100) == "\\x7f\\xc3");
  CHECK(printable_line(std::string(50, 'a'), 10) == "aaaaaaaaaa...");
  // Through a tool: one printable line with short numbers on stderr.
  Captured io;
  auto tool = xfem::cli::make_tool("t", "test", "");
  char name[] = "t";
  char* argv[] = {name};
  const int code = xfem::cli::run(*tool, 1, argv, [&] { throw xfem::Error("bad\x02 " + dbl_max); });
  CHECK(code == 1);
  CHECK(io.err.str() == "t: error: bad\\x02 1.79769e+308\n");
}
