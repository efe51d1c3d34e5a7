// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

// Label maps (segmented scans): 3D images of integer labels, one per voxel, as 3D Slicer,
// ITK-SNAP and the scanners' tools write them. Where each part is:
//   label_image.h            the image in memory, its geometry, the readers' and writer's entries
//   label_image_header.cpp   each format's header parsed and checked before any voxel is read
//   label_image_read.cpp     the voxels, by VTK's readers (NRRD, NIfTI, MetaImage, VTI) or CGAL's (INR)
//   label_image_write.cpp    NRRD (attached header, raw voxels), written by xfem-mesh phantom-image
namespace xfem {

/// A label map: nx x ny x nz voxels (x fastest), each an integer label (0 is background by
/// convention). Voxel (i, j, k) is the sample at the world point
///   origin + direction * (i sx, j sy, k sz)
/// (the voxel's centre, as in NRRD, NIfTI, MetaImage and ITK), in the file's units (millimetres
/// for most scanners' files; xfem-mesh image --scale converts).
struct LabelImage {
  std::array<std::int64_t, 3> dims{0, 0, 0};
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  ///< columns: world directions of i, j, k (orthonormal)
  std::vector<std::int32_t> labels;                         ///< dims[0] * dims[1] * dims[2]
  std::map<int, std::string> names;                         ///< label -> name, where the file names them

  std::int64_t voxels() const { return dims[0] * dims[1] * dims[2]; }
  std::int64_t index(std::int64_t i, std::int64_t j, std::int64_t k) const { return i + dims[0] * (j + dims[1] * k); }
  std::int32_t at(std::int64_t i, std::int64_t j, std::int64_t k) const { return labels[index(i, j, k)]; }
  /// World position of voxel (i, j, k)'s centre (fractional indices allowed).
  Eigen::Vector3d world(const Eigen::Vector3d& ijk) const {
    return origin + direction * ijk.cwiseProduct(spacing);
  }
};

/// Images beyond this many voxels are refused before anything is allocated (2 GB of int32
/// labels; a CT is ~1e8): a corrupt or hostile header cannot make a reader allocate for it.
constexpr double kMaxImageVoxels = 5e8;

/// What a header says, checked against the file before the voxels are read.
struct LabelImageHeader {
  std::string format;  ///< "nrrd", "nifti", "metaimage", "vti", "inr"
  std::array<std::int64_t, 3> dims{0, 0, 0};
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();
  bool geometry_known = false;  ///< the header's spacing, origin and direction are the image's
  std::map<int, std::string> names;
};

/// The image format of `path` by its extension: "nrrd" (.nrrd, .nhdr), "nifti" (.nii, .nii.gz),
/// "metaimage" (.mha, .mhd), "vti", "inr" (.inr, .inr.gz); throws xfem::Error for another.
std::string label_image_format(const std::string& path);

/// Parses and checks the header of `path` (label_image_header.cpp). Throws xfem::Error
/// "<path>: <problem>" (one line) for: an unknown extension, a missing or truncated header, a
/// dimension other than 3 (a 2D image, or 4D unless the 4th size is 1), a size that is not a
/// positive integer, more than kMaxImageVoxels voxels, a voxel type that is not an integer
/// (float labels), a spacing that is not positive and finite, a non-finite origin, a direction
/// that is not orthonormal, an uncompressed data size that disagrees with the header's.
LabelImageHeader read_label_image_header(const std::string& path);

/// Reads the label map `path` (any format of label_image_format): header checked first
/// (read_label_image_header), then the voxels by VTK's or CGAL's reader, whose size must match
/// the header. Label names come from the header where it has them (NRRD's Segment<N>_Name and
/// Segment<N>_LabelValue, as 3D Slicer writes). Throws xfem::Error naming the file.
LabelImage read_label_image(const std::string& path);

/// Reads label names from a side file: one label a line, its integer value first, then its name
/// (a double-quoted string anywhere on the line, as ITK-SNAP's label descriptions have it, or
/// else the second word, as 3D Slicer's colour tables); '#' starts a comment. Throws
/// xfem::Error "<path>:<line>: ..." for a line without both.
std::map<int, std::string> read_label_names(const std::string& path);

/// Writes `image` as NRRD with an attached header (raw little-endian int32 voxels, "space
/// directions" and "space origin" from its geometry, Segment<N>_* key-value pairs for its names),
/// atomically.
void write_label_image_nrrd(const LabelImage& image, const std::string& path);

}  // namespace xfem
