// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace xfem {

/// Weights that smooth a label map's boundaries for CGAL Mesh_3's weighted labelled-image domain
/// (Stalling et al., "Weighted labels for 3D image segmentation", 1998), as CGAL 5.5's
/// generate_label_weights computes them, without ITK: for each label present (0 included), its
/// indicator (255 on its voxels, 0 elsewhere) blurred by a Gaussian of standard deviation
/// sigma[a] voxels along axis a (truncated at 3 sigma, normalised, edges clamped); the weight of
/// a voxel is the largest blurred indicator, rounded to 0..255. `labels` has dims[0] * dims[1] *
/// dims[2] values, x fastest. Throws xfem::Error for a sigma that is not positive and finite or
/// wider than 20 voxels.
std::vector<std::uint8_t> label_weights(const std::vector<std::int32_t>& labels, const std::array<std::int64_t, 3>& dims,
                                        const std::array<double, 3>& sigma);

}  // namespace xfem
