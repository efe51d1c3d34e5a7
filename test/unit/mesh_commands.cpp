// SPDX-License-Identifier: MIT
#include "xfem/generate/mesh_commands.h"

#include <catch2/catch.hpp>

#include "xfem/generate/cut_commands.h"

TEST_CASE("xfem-mesh's commands register in their order", "[generate]") {
  CLI::App app;
  auto commands = xfem::add_volume_mesh_commands(app);
  for (auto& c : xfem::add_cut_commands(app)) commands.push_back(std::move(c));
  std::vector<std::string> names;
  for (const auto& c : commands) {
    names.push_back(c.app->get_name());
    CHECK(c.run);
    CHECK(c.app->get_option("--output")->get_required());
    CHECK(c.app->get_option("--allow-large"));
  }
  CHECK(names == std::vector<std::string>{"box", "unstructured-box", "organ", "surface", "image", "phantom-image", "cut-rect", "cut-sine",
                                          "cut-disc", "cut-zigzag", "cut-merge", "cut-sweep"});
}

TEST_CASE("cut-rect and cut-sweep refuse incomplete options when parsed", "[generate]") {
  CLI::App app;
  const auto commands = xfem::add_cut_commands(app);
  CHECK_THROWS_AS(app.parse("cut-rect --corner 0 0 0 -o x.vtp", false), CLI::RequiredError);
  CLI::App sweep_app;
  const auto sweep_commands = xfem::add_cut_commands(sweep_app);
  CHECK_THROWS_AS(sweep_app.parse("cut-sweep --path 0 1 0 0 0 --depth 1 --resolution 1 -o x.vtp", false),
                  CLI::ValidationError);
}
