// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

#include "xfem/core/mesh.h"

namespace xfem {

/// Where to look at a cut from, derived from the wound (both faces of the cut inside the body,
/// as deformed_body writes it: cell array `side` +1 / -1, points of the front shared by both).
struct CutView {
  bool has_cut = false;      ///< false: no wound (a plain mesh): the default isometric view
  bool interior = false;     ///< the cut's border is (almost) all front: it does not reach the
                             ///< surface, so only a section shows it
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< area centroid of the cut, m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< the cut's mean unit normal (H = +1 side)
  /// Unit vector in the cut's plane from the front towards the mouth (where the cut meets the
  /// surface): the direction the opening faces. For an interior cut, an in-plane direction.
  Eigen::Vector3d opening = Eigen::Vector3d::UnitX();
  /// Unit vector from the focal point towards the eye. Cut with a mouth: mostly `opening`, raised
  /// towards `normal` and turned sideways, so the camera looks into the opened gap rather than
  /// along the cut's plane: eye = normalize(opening + 0.8 normal + 0.35 normal x opening).
  /// Interior cut: normalize(normal + opening), 45 degrees to the cut, looking at the section.
  /// No cut: (-1, -1, 1) / sqrt 3 (isometric).
  Eigen::Vector3d eye = Eigen::Vector3d(-1, -1, 1).normalized();
};

/// The view of `wound` (undeformed positions; may be empty). Pure geometry, no rendering.
/// Throws xfem::Error when the wound lacks its cell array `side`.
CutView cut_view(const TriangleMesh& wound);

/// How write_snapshot draws the deformed body (docs/FORMATS.md, "PNG snapshot").
struct SnapshotOptions {
  double scale = 1.0;     ///< displacement magnification (1 = true deformation)
  int width = 1200;       ///< pixels
  int height = 900;       ///< pixels
  std::string title;      ///< first line of the caption (e.g. the file name); may be empty
  /// The material model the von_mises array was computed with, for the colour bar and caption
  /// ("von Mises stress (Cauchy, neo-hookean)"); empty: the linear model's (Hooke) stress.
  std::string stress_model;
  /// Element edges: Auto draws thin light-grey edges when the visible surface has fewer than
  /// 20,000 triangles (a finer mesh would turn grey), On / Off always / never.
  enum class Edges { Auto, On, Off };
  Edges edges = Edges::Auto;
  /// For a series of pictures with one camera and one colour range (xfem-sweep --png): the view
  /// to use instead of cut_view(wound), the top of the colour range instead of colour_top (> 0),
  /// and the box (xmin, xmax, ymin, ymax, zmin, zmax, m) to frame instead of the drawn bounds.
  std::optional<CutView> view;
  double colour_max = 0;
  std::optional<std::array<double, 6>> frame;
};

/// The colour range the snapshot uses for von Mises stress (Pa): 0 to the 95th percentile of the
/// cells' values (the singular peak at the cut front would otherwise wash the picture out), or
/// to the maximum when that percentile is 0. Also written into the ParaView script.
double colour_top(const TetMesh& deformed);

/// Renders `deformed` (an output of deformed_body: point array `displacement`, cell array
/// `von_mises`) and its `wound` (may have no triangles: a plain mesh) to a PNG with VTK offscreen
/// rendering, at x + scale * u. The outer surface of the split mesh (so the opened cut shows as a
/// gap) coloured by von Mises stress with the viridis colour map from 0 to colour_top, values above
/// in the top colour; the wound in its own colour (red); a colour bar stating the range and a
/// caption. The camera follows cut_view(wound): parallel projection from `eye` at the centre of
/// what is drawn, the world's z (or y, if z is the view direction) up on the screen, scaled so
/// that the drawn bounding box fits with a 5 % margin. An interior cut is shown by a section:
/// the body and wound are clipped by the plane through the cut's centre with normal `opening`
/// (containing the cut's normal), the half towards the eye removed. A body of several regions
/// (cell array `region`): every region but the largest is outlined over the body in its own colour
/// (region_boundary: see-through faces and silhouette), named in a legend; one region draws
/// nothing more. Needs an X display (run under
/// `xvfb-run -a`): throws xfem::Error when DISPLAY is unset, or when the arrays are missing.
/// Pixels may differ between GPUs and drivers.
void write_snapshot(const TetMesh& deformed, const TriangleMesh& wound, const std::string& png,
                    const SnapshotOptions& options);

}  // namespace xfem
