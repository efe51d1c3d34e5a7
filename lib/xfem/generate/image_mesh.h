// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/io/label_image.h"

namespace xfem {

/// How xfem-mesh image meshes a label map (sizes in metres, after `scale`).
struct ImageMeshOptions {
  double size = 0;             ///< target edge length, as the other generators' --size
  double facet_distance = 0;   ///< how far a boundary facet may stray from the labels' boundary; 0: the default
  double scale = 1;            ///< world metres per image unit (0.001 for a millimetre image)
  std::vector<int> labels;     ///< the labels to mesh; empty: every non-zero label
  double smooth = 0;           ///< Gaussian width (m) of the label weights that smooth the boundaries; 0: none
};

/// The facet distance used when none is given: a tenth of the size, but not below a quarter of
/// the smallest voxel spacing (the labels' boundary is only known to a voxel: a smaller distance
/// would refine the mesh to follow the voxels' steps).
double default_facet_distance(const LabelImage& image, const ImageMeshOptions& options);

/// The volume (m^3, after scale) of the voxels that carry a kept label, for the cost estimate.
/// Throws xfem::Error naming a requested label the image does not have (listing those it has).
double kept_voxel_volume(const LabelImage& image, const ImageMeshOptions& options, const std::string& name);

/// A tetrahedral mesh of the voxels of the kept labels (CGAL Mesh_3's labelled-image domain: the
/// boundary between two labels is where the trilinear interpolation of their indicator functions
/// crosses, so that the regions' interfaces are conforming: every interface triangle is a face of
/// one tet on each side). Each tet's label is its region (the cell array "region", Int32,
/// core/regions.h), the image's names of the kept labels the mesh's region names. Points are in world
/// metres: scale * (origin + direction * (index * spacing)); a reflection in the direction keeps
/// tets positively oriented. Criteria as unstructured_mesh.h's (facet angle 25 degrees, radius
/// bounds 0.72 size, radius-edge ratio 3, slivers exuded without time limit, no perturbation);
/// every connected component of every label is seeded (CGAL's initialize_triangulation_from_
/// labeled_image), so small inclusions are not missed. With `smooth` > 0 the boundaries are
/// smoothed by weighted labels (image_smoothing.h, a Gaussian of `smooth` metres): the voxels'
/// steps no longer show in the mesh. Deterministic: the same image and options
/// give the same mesh. Points and tets in Hilbert order (mesh_ordering.h).
/// Throws xfem::Error (naming `name`) for a size or scale that is not positive and finite, labels
/// the image lacks, negative labels (regions are numbered from 1), no voxel to mesh, a name that
/// is not a region name (validate_regions), or an empty result.
TetMesh image_mesh(const LabelImage& image, const ImageMeshOptions& options, const std::string& name);

}  // namespace xfem
