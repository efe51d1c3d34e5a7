// SPDX-License-Identifier: MIT
#include "xfem/post/sweep_frame.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

#include "xfem/core/cli.h"
#include "xfem/core/regions.h"
#include "xfem/geometry/element_split.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

DeformedBody sweep_frame(const CutSolution& step, const Problem& problem) {
  const EnrichedMesh& em = step.em;
  const SplitMesh split = em.cut ? split_mesh(em.mesh, em.side, em.cut_class, *em.cut, em.front.segments())
                                 : unsplit_mesh(em.mesh, em.side);
  DeformedBody frame =
      deformed_body(split, em.cut_class, xfem_displacement(em, step.u), tet_materials(problem, em.mesh, "the body"));
  inherit_regions(em.mesh, split.parent, frame.volume);
  return frame;
}

std::string numbered(const std::string& stem, int k, const std::string& extension) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", k);
  return stem + buf + extension;
}

SnapshotOptions sweep_pictures(const DeformedBody& frame, double scale, int width, int height) {
  SnapshotOptions picture;
  picture.view = cut_view(frame.wound);
  picture.colour_max = colour_top(frame.volume);
  const auto& u = frame.volume.point_data.at("displacement");
  std::array<double, 6> box{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (Eigen::Index p = 0; p < frame.volume.points.rows(); ++p)
    for (int i = 0; i < 3; ++i) {
      const double x = frame.volume.points(p, i) + scale * u(static_cast<std::size_t>(p), i);
      box[2 * i] = std::min(box[2 * i], x);
      box[2 * i + 1] = std::max(box[2 * i + 1], x);
    }
  picture.frame = box;
  picture.scale = scale;
  picture.width = width;
  picture.height = height;
  picture.edges = SnapshotOptions::Edges::Off;  // Auto would switch them off as the cut adds faces
  return picture;
}

std::string FrameFiles::in_dir(const std::string& name) const { return (std::filesystem::path(dir) / name).string(); }

WrittenFrame write_frame(const UncutBody& body, const Problem& problem, const FrameFiles& files, int k,
                         std::unique_ptr<CutSolution> step, double solved) {
  WrittenFrame out;
  const double begin = cli::now();
  const EnrichedMesh& em = step->em;
  complete_solution(body, *step);
  out.frame = sweep_frame(*step, problem);
  out.times.built = cli::now() - begin;
  write_tet_mesh(out.frame.volume, files.in_dir(numbered("step_", k, ".vtu")), files.packing);
  write_triangle_mesh(out.frame.wound, files.in_dir(numbered("step_", k, "_wound.vtp")), files.packing);
  out.times.written = cli::now() - begin;  // what xfem-visualize does
  if (files.solutions) {  // with the fingerprints xfem-solve writes, so xfem-visualize/-rmserror can check a frame's inputs
    Provenance made_for{{"enriched", files.body}, {"problem", files.problem}};
    if (em.cut) made_for["cut"] = fingerprint(em.cut->mesh());
    write_vector(step->u, files.in_dir(numbered("u_", k, ".mtx")), provenance_comments(made_for));
  }
  if (files.cuts && em.cut) write_triangle_mesh(em.cut->mesh(), files.in_dir(numbered("cut_", k, ".vtp")));
  out.k = k;
  out.step = std::move(step);
  out.times.solved = solved;
  return out;
}

}  // namespace xfem
