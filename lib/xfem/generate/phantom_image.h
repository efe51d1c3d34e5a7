// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/io/label_image.h"

namespace xfem {

/// A synthetic label map for tests and examples (xfem-mesh phantom-image): the organ-like body
/// of organ_shape.h as label 1 ("body") with a spherical inclusion as label 2 ("inclusion"),
/// sampled at the voxels' centres, in metres.
///
/// The shapes live in the image's own frame (index times spacing, as a scanner sees its
/// patient): the body's centre is the point `body_centre()` of that frame, the middle of the
/// grid, which holds the body with two voxels to spare on every side. The image is then placed
/// in the world by `origin` and `direction`, so that the inclusion's centre is at
///   origin + direction * (body_centre + inclusion_centre).
struct PhantomImageSpec {
  Eigen::Vector3d spacing{0.001, 0.001, 0.001};  ///< metres, per axis (anisotropic allowed)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  ///< orthonormal columns
  Eigen::Vector3d inclusion_centre{0.02, 0.0, 0.0};         ///< relative to the body's centre, m
  double inclusion_radius = 0.015;                          ///< m; the sphere must lie inside the body
};

/// The grid's sizes for `spec` and the body's centre in the image frame (metres).
std::array<std::int64_t, 3> phantom_dims(const PhantomImageSpec& spec);
Eigen::Vector3d phantom_body_centre(const PhantomImageSpec& spec);

/// The label map. Throws xfem::Error for a spacing that is not positive and finite, a direction
/// that is not orthonormal, an inclusion that does not lie inside the body, or a grid beyond
/// kMaxImageVoxels.
LabelImage phantom_image(const PhantomImageSpec& spec);

}  // namespace xfem
