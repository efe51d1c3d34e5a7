// SPDX-License-Identifier: MIT
#include "xfem/core/atomic_file.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "xfem/core/error.h"

namespace fs = std::filesystem;

namespace {

std::string scratch_dir(const std::string& test) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_atomic_" + std::to_string(::getpid())) / test;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace

TEST_CASE("atomic_file: the writer sees a temporary in the target's directory, renamed on success", "[atomic_file]") {
  const auto dir = scratch_dir("success");
  const std::string target = dir + "/out.vtu";
  std::string seen;
  xfem::write_atomically(target, [&](const std::string& tmp) {
    seen = tmp;
    CHECK(fs::path(tmp).parent_path() == fs::path(dir));
    CHECK(xfem::extension_of(tmp) == ".vtu");  // VTK writers pick their format by extension
    CHECK_FALSE(fs::exists(target));           // the final name appears only when complete
    write_text(tmp, "complete");
  });
  CHECK(seen != target);
  CHECK(slurp(target) == "complete");
  CHECK(listing(dir) == std::vector<std::string>{"out.vtu"});
}

TEST_CASE("atomic_file: a failing writer leaves no file and no temporary", "[atomic_file]") {
  const auto dir = scratch_dir("failure");
  const std::string target = dir + "/out.mtx";
  CHECK_THROWS_WITH(xfem::write_atomically(target,
                                           [](const std::string& tmp) {
                                             write_text(tmp, "half a fi");
                                             throw xfem::Error("out.mtx: solver diverged");
                                           }),
                    "out.mtx: solver diverged");
  CHECK(listing(dir).empty());
  SECTION("an existing file of that name is kept intact") {
    write_text(target, "previous result");
    CHECK_THROWS_AS(xfem::write_atomically(target,
                                           [](const std::string& tmp) {
                                             write_text(tmp, "partial");
                                             throw std::runtime_error("boom");
                                           }),
                    std::runtime_error);
    CHECK(slurp(target) == "previous result");
    CHECK(listing(dir) == std::vector<std::string>{"out.mtx"});
  }
}

TEST_CASE("atomic_file: a writer that produces nothing is an error, not an empty success", "[atomic_file]") {
  const auto dir = scratch_dir("nothing");
  CHECK_THROWS_WITH(xfem::write_atomically(dir + "/out.json", [](const std::string&) {}),
                    Catch::StartsWith(dir + "/out.json: cannot rename temporary file"));
  CHECK(listing(dir).empty());
}

TEST_CASE("atomic_file: a missing target directory is an error naming it", "[atomic_file]") {
  const auto dir = scratch_dir("no_dir");
  bool called = false;
  CHECK_THROWS_WITH(xfem::write_atomically(dir + "/sub/out.vtu", [&](const std::string&) { called = true; }),
                    dir + "/sub/out.vtu: directory " + dir + "/sub does not exist");
  CHECK_FALSE(called);
}

TEST_CASE("atomic_file: '-' is passed through to the writer (stdout)", "[atomic_file]") {
  std::string seen;
  xfem::write_atomically("-", [&](const std::string& tmp) { seen = tmp; });
  CHECK(seen == "-");
}

TEST_CASE("atomic_file: a bare file name writes in the current directory", "[atomic_file]") {
  const auto dir = scratch_dir("cwd");
  const auto old = fs::current_path();
  fs::current_path(dir);
  xfem::write_atomically("plain.txt", [](const std::string& tmp) { write_text(tmp, "x"); });
  fs::current_path(old);
  CHECK(listing(dir) == std::vector<std::string>{"plain.txt"});
}

TEST_CASE("atomic_file: require_readable names missing files and directories", "[atomic_file]") {
  const auto dir = scratch_dir("readable");
  CHECK_THROWS_WITH(xfem::require_readable(dir + "/none.vtu"), dir + "/none.vtu: cannot open for reading (does it exist?)");
  CHECK_THROWS_WITH(xfem::require_readable(dir), dir + ": is a directory, expected a file");
  write_text(dir + "/ok.vtu", "");
  CHECK_NOTHROW(xfem::require_readable(dir + "/ok.vtu"));
}

TEST_CASE("atomic_file: extension_of is the lower-case last extension with its dot", "[atomic_file]") {
  CHECK(xfem::extension_of("a/b/mesh.VTU") == ".vtu");
  CHECK(xfem::extension_of("cut.tar.STL") == ".stl");
  CHECK(xfem::extension_of("dir.d/noext") == "");
  CHECK(xfem::extension_of("-") == "");
}

TEST_CASE("atomic_file: files written together appear only when all are written", "[atomic_file]") {
  const auto dir = scratch_dir("together");
  const std::string a = dir + "/deformed.vtu", b = dir + "/wound.vtp";
  write_text(a, "old body");
  write_text(b, "old wound");
  // The second writer fails: neither target changes (the first one's new content was written
  // to its temporary only), and no temporary is left.
  CHECK_THROWS_WITH(xfem::write_atomically_together(
                        {{a, [](const std::string& tmp) { write_text(tmp, "new body"); }},
                         {b, [](const std::string& tmp) {
                            write_text(tmp, "half a wou");
                            throw xfem::Error("wound.vtp: disk full");
                          }}}),
                    "wound.vtp: disk full");
  CHECK(slurp(a) == "old body");
  CHECK(slurp(b) == "old wound");
  CHECK(listing(dir) == std::vector<std::string>{"deformed.vtu", "wound.vtp"});
  // Both written: while the second is written the first is not yet in place.
  xfem::write_atomically_together({{a, [](const std::string& tmp) {
                                      CHECK(xfem::extension_of(tmp) == ".vtu");
                                      write_text(tmp, "new body");
                                    }},
                                   {b, [&](const std::string& tmp) {
                                      CHECK(slurp(a) == "old body");
                                      CHECK(fs::path(tmp).parent_path() == fs::path(dir));
                                      write_text(tmp, "new wound");
                                    }}});
  CHECK(slurp(a) == "new body");
  CHECK(slurp(b) == "new wound");
  CHECK(listing(dir) == std::vector<std::string>{"deformed.vtu", "wound.vtp"});
}
