// SPDX-License-Identifier: MIT
#include "xfem/generate/phantom_image.h"

#include <cmath>

#include "xfem/core/error.h"
#include "xfem/generate/organ_shape.h"

namespace xfem {
namespace {
// The organ's bounding box (organ_shape.h: x in [-0.075, 0.075], y in [-0.05, 0.05], z in
// about [-0.036, 0.039]), rounded out.
const Eigen::Vector3d organ_lo(-0.0755, -0.0505, -0.037), organ_hi(0.0755, 0.0505, 0.0395);
constexpr double margin_voxels = 2;

void check(const PhantomImageSpec& s) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(s.spacing[a]) && s.spacing[a] > 0))
      throw Error("phantom image: spacing " + short_number(s.spacing[a]) + " must be positive and finite");
  if (!s.origin.allFinite()) throw Error("phantom image: origin must be finite");
  if (!s.direction.allFinite() || !(s.direction.transpose() * s.direction - Eigen::Matrix3d::Identity()).isZero(1e-6))
    throw Error("phantom image: the direction matrix must be orthonormal (a rotation or reflection; columns are the "
                "world directions of the image's i, j, k axes)");
  if (!(s.inclusion_radius > 0 && std::isfinite(s.inclusion_radius)))
    throw Error("phantom image: inclusion radius must be positive");
  // Inside the body: the sphere's extreme points along the axes and diagonals.
  for (int a = 0; a < 3; ++a)
    for (double sign : {-1.0, 1.0}) {
      Eigen::Vector3d p = s.inclusion_centre;
      p[a] += sign * s.inclusion_radius;
      if (!(organ_function(p) < 0))
        throw Error("phantom image: the inclusion (radius " + short_number(s.inclusion_radius) +
                    " m) does not lie inside the body");
    }
}
}  // namespace

std::array<std::int64_t, 3> phantom_dims(const PhantomImageSpec& spec) {
  std::array<std::int64_t, 3> d{};
  for (int a = 0; a < 3; ++a) {
    const double n = std::ceil((organ_hi[a] - organ_lo[a]) / spec.spacing[a]) + 1 + 2 * margin_voxels;
    if (!(n <= kMaxImageVoxels)) throw Error("phantom image: spacing " + short_number(spec.spacing[a]) + " m gives too many voxels");
    d[a] = static_cast<std::int64_t>(n);
  }
  return d;
}

Eigen::Vector3d phantom_body_centre(const PhantomImageSpec& spec) {
  // Grid point margin_voxels sits at the box's lower corner.
  return (margin_voxels * spec.spacing - organ_lo);
}

LabelImage phantom_image(const PhantomImageSpec& spec) {
  check(spec);
  LabelImage image;
  image.dims = phantom_dims(spec);
  const double total = static_cast<double>(image.dims[0]) * image.dims[1] * image.dims[2];
  if (total > kMaxImageVoxels)
    throw Error("phantom image: " + short_number(total) + " voxels exceed the limit of " + short_number(kMaxImageVoxels) +
                " (a larger --spacing)");
  image.spacing = spec.spacing;
  image.origin = spec.origin;
  image.direction = spec.direction;
  image.names = {{1, "body"}, {2, "inclusion"}};
  image.labels.assign(static_cast<std::size_t>(image.voxels()), 0);
  const Eigen::Vector3d centre = phantom_body_centre(spec);
  const double r2 = spec.inclusion_radius * spec.inclusion_radius;
  for (std::int64_t k = 0; k < image.dims[2]; ++k)
    for (std::int64_t j = 0; j < image.dims[1]; ++j)
      for (std::int64_t i = 0; i < image.dims[0]; ++i) {
        const Eigen::Vector3d p =
            Eigen::Vector3d(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)).cwiseProduct(spec.spacing) - centre;
        int label = 0;
        if ((p - spec.inclusion_centre).squaredNorm() < r2)
          label = 2;
        else if (organ_function(p) < 0)
          label = 1;
        image.labels[image.index(i, j, k)] = label;
      }
  return image;
}

}  // namespace xfem
