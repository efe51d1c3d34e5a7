// SPDX-License-Identifier: MIT
// Classifies a tet mesh against a cut (paper 3.3): node sides and enrichments, cut tets, front.
#include <memory>
#include <string>

#include "xfem/enrich/classification.h"
#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/core/json_io.h"
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/enrich/cut_files.h"
#include "xfem/core/version.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-classify",
      "Classify a tetrahedral mesh against a cut surface (paper 3.3): every edge cut or not, every tet\n"
      "uncut / partially / completely cut, every node's side of the cut (+1/-1) and enrichment\n"
      "(none / sign / branch), and the cut front inside the body. Writes them as arrays on the mesh\n"
      "(docs/FORMATS.md, classified.vtu); degenerate geometry by the rules of docs/CLASSIFICATION.md.",
      "xfem-classify beam.vtu --cut cut.vtp -o classified.vtu --summary counts.json");
  std::string body, output, summary;
  std::vector<std::string> cut_paths;
  double tip_radius = 0.0, tiny_support = 1e-7;
  auto& app = tool->app;
  app.add_option("body", body, "tetrahedral mesh of the body (.vtu/.vtk, or gmsh .msh 2.2/4.x: its physical groups become point arrays group_<name>)")->required();
  app.add_option("-c,--cut", cut_paths,
                 "cut surface of triangles (.vtp/.vtu/.vtk/.stl/.obj/.off/.msh); without it the mesh is plain (e.g. a "
                 "cut-aligned mesh with doubled nodes): everything uncut, no enrichment. Several cuts: repeat --cut "
                 "(cut 0, 1, ... in that order), or one file whose triangles carry the cell array cut_id (one cut per "
                 "value, increasing); docs/FORMATS.md \"Several cuts\"")
      ->allow_extra_args(false);
  app.add_option("-o,--output", output, "classified mesh (.vtu)")->required();
  app.add_option("--summary", summary, "also write the counts as JSON ('-' = stdout)");
  app.add_option("--tip-radius", tip_radius,
                 "also branch-enrich every node within this distance of the cut front (metres; "
                 "default 0 = the paper's rule: nodes of partially cut tets only)")
      ->check(xfem::cli::non_negative());
  app.add_option("--tiny-support", tiny_support,
                 "sign-enrich a node only if at least this fraction of its support's volume lies on the other "
                 "side of the cut (dimensionless, default 1e-7, a decade above where xfem-solve starts to warn of a near-singular K; 1e-4 is common with iterative solvers but breaks the exact representation of a cut body: see docs/CLASSIFICATION.md)")
      ->check(xfem::cli::range(0.0, 0.5));
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".vtu"});
    if (!summary.empty()) xfem::cli::check_output(summary, {".json"}, true);
    std::vector<std::string> warnings;
    xfem::TetMesh mesh = xfem::read_tet_mesh(body, &warnings);
    std::vector<std::string> cut_names;
    std::vector<xfem::TriangleMesh> meshes = xfem::read_cuts(cut_paths, cut_names, &warnings);
    for (const auto& w : warnings) xfem::cli::warn(w);
    const std::string cut_path = cut_names.empty() ? std::string() : cut_names[0];
    // What every --summary starts with (`cut`: the path, or the list of paths of several cuts).
    const auto summary_header = [&](const xfem::Json& cut) {
      xfem::Json j;
      j["generator"] = std::string("xfem-classify ") + xfem::version;
      j["body"] = body;
      j["cut"] = cut;
      j["tip_radius"] = tip_radius;
      j["tiny_support"] = tiny_support;
      return j;
    };
    xfem::ClassifyOptions options;
    options.tip_radius = tip_radius;
    options.tiny_support = tiny_support;
    options.progress = xfem::cli::progress("classifying");
    if (meshes.size() > 1) {  // several cuts (docs/FORMATS.md "Several cuts")
      std::vector<xfem::CutSurface> surfaces;
      for (auto& m : meshes) surfaces.emplace_back(m);
      std::vector<const xfem::CutSurface*> cuts;
      for (const auto& c : surfaces) cuts.push_back(&c);
      const xfem::CutsClassification c = [&] {
        try {
          return xfem::classify_cuts(mesh, cuts, options);
        } catch (const xfem::Error& e) {
          throw xfem::Error(body + ": " + e.what());
        }
      }();
      xfem::store_cuts_classification(c, mesh);
      xfem::store_cut_fingerprints(meshes, mesh);
      xfem::write_tet_mesh(mesh, output);
      xfem::Json j = summary_header(cut_names);
      xfem::report_cuts_classification(c, cut_names, j);
      if (!summary.empty()) xfem::write_json(j, summary);
      return;
    }
    std::unique_ptr<xfem::CutSurface> cut;
    if (!meshes.empty()) cut = std::make_unique<xfem::CutSurface>(std::move(meshes[0]));

    const double start = xfem::cli::now();
    const xfem::Classification c = [&] {
      try {
        return cut ? xfem::classify(mesh, *cut, options) : xfem::classify_without_cut(mesh);
      } catch (const xfem::Error& e) {  // the library says "cut: ...": name the file
        const std::string m = e.what();
        if (m.rfind("cut: ", 0) == 0) throw xfem::Error(cut_path + m.substr(3));
        throw;
      }
    }();
    const double seconds = xfem::cli::now() - start;
    if (cut && c.counts.partial + c.counts.complete == 0)
      xfem::cli::info("the cut does not enter " + body + ": nothing is enriched");
    if (c.counts.sign_tiny > 0)
      xfem::cli::detail(std::to_string(c.counts.sign_tiny) +
                        " nodes are not sign enriched: less than --tiny-support of their support lies on the "
                        "other side of the cut (their sign function would be nearly zero and K near-singular; "
                        "the cut still opens through their neighbours' enrichment)");

    xfem::store_classification(c, mesh);
    if (cut) xfem::store_fingerprint(mesh.field_data, "cut_fingerprint", xfem::fingerprint(cut->mesh()));
    xfem::write_tet_mesh(mesh, output);

    const auto names = xfem::count_names();
    const auto values = xfem::count_values(c.counts);
    std::string line;
    for (std::size_t i = 0; i < names.size(); ++i) line += (i ? ", " : "") + names[i] + " " + std::to_string(values[i]);
    xfem::cli::detail(line);
    xfem::cli::info(std::to_string(c.counts.partial) + " partially and " + std::to_string(c.counts.complete) +
                    " completely cut tets of " + std::to_string(c.counts.tets) + "; " + std::to_string(c.counts.sign) +
                    " sign, " + std::to_string(c.counts.branch) + " branch nodes; " +
                    std::to_string(c.counts.front_segments) + " front segments (" + std::to_string(seconds) + " s)");
    if (!summary.empty()) {
      xfem::Json j = summary_header(cut_path);
      for (std::size_t i = 0; i < names.size(); ++i) j[names[i]] = values[i];
      xfem::write_json(j, summary);
    }
  });
}
