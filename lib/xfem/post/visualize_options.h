// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/snapshot.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/system/problem.h"

namespace xfem {

/// xfem-visualize's command line (README, --help).
struct VisualizeOptions {
  std::string input, solution, problem_path, output, faces, png, title, reactions_path, script, contact_pressure;
  std::string edges = "auto", compression = "zlib";
  std::vector<std::string> cut_paths;
  std::vector<double> view;
  double scale = 1.0, wound_offset = 1e-4;
  int width = 1200, height = 900;
  bool no_edges = false;
};

/// Declares every option of xfem-visualize on `app`, filling `o`.
void add_visualize_options(CLI::App& app, VisualizeOptions& o);

/// Checks the output paths and the display a --png needs (xfem::Error naming the file).
void check_visualize_outputs(const VisualizeOptions& o);

/// The picture's options and camera from `o` (a --view replaces the camera cut_view(wound) chose).
SnapshotOptions snapshot_options(const VisualizeOptions& o, const Problem& problem, const TriangleMesh& wound,
                                 CutView& camera);

/// Reports on stderr the cut's opening (u+ - u-) . n over the points doubled on the cut (one cut
/// only: the pieces of several cuts carry side codes, no +-1 pairs) and the largest penetration
/// of the faces, max(0, -min opening), m.
void report_cut_opening(const EnrichedMesh& em, const SplitMesh& split, const DeformedBody& body);

/// --contact-pressure: reads xfem-solve's nodal contact pressure and puts it on the wound as the
/// cell array `contact_pressure` (Float64, Pa; wound_pressure.h); reports its largest value.
void add_contact_pressure(const std::string& path, const EnrichedMesh& em, const SplitMesh& split, DeformedBody& body);

/// The values of the wound's cell array `contact_pressure` (add_contact_pressure), empty without it.
std::vector<double> wound_pressure_values(const DeformedBody& body);

}  // namespace xfem
