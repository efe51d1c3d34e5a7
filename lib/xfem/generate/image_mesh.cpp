// SPDX-License-Identifier: MIT
#include "xfem/generate/image_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/initialize_triangulation_from_labeled_image.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/refine_mesh_3.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/generate/image_smoothing.h"
#include "xfem/generate/mesh_ordering.h"
#include "xfem/io/vtk_io.h"

namespace xfem {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
namespace params = CGAL::parameters;

// As unstructured_mesh.cpp: radius bounds of 0.72 H give a mean edge length of about H.
constexpr double radius_per_edge = 0.72;

std::set<int> kept_labels(const LabelImage& image, const ImageMeshOptions& o, const std::string& name) {
  std::set<int> present(image.labels.begin(), image.labels.end());
  present.erase(0);
  if (o.labels.empty()) {
    // Every non-zero label becomes a region, and regions are non-negative ids.
    if (!present.empty() && *present.begin() < 0)
      throw Error(name + ": label " + std::to_string(*present.begin()) +
                  " is negative: regions are numbered from 1 (--labels to choose the positive ones)");
    return present;
  }
  std::set<int> kept;
  for (int l : o.labels) {
    if (l <= 0) throw Error(name + ": label " + std::to_string(l) + (l == 0 ? " is the background; it cannot be meshed" : ": regions are numbered from 1"));
    if (!present.count(l)) {
      std::string list;
      for (int p : present) list += (list.empty() ? "" : ", ") + std::to_string(p);
      throw Error(name + ": label " + std::to_string(l) + " is not in the image (its labels: " +
                  (list.empty() ? "none but 0" : list) + ")");
    }
    kept.insert(l);
  }
  return kept;
}

void check_options(const ImageMeshOptions& o) {
  if (!(std::isfinite(o.size) && o.size > 0)) throw Error("mesh size must be positive and finite (got " + short_number(o.size) + ")");
  if (!(std::isfinite(o.scale) && o.scale > 0)) throw Error("--scale must be positive and finite (got " + short_number(o.scale) + ")");
  if (!(std::isfinite(o.smooth) && o.smooth >= 0)) throw Error("--smooth must be positive and finite (got " + short_number(o.smooth) + ")");
  if (!(std::isfinite(o.facet_distance) && o.facet_distance >= 0))
    throw Error("--facet-distance must be positive and finite (got " + short_number(o.facet_distance) + ")");
}

// CGAL's image search prints its progress on standard output; xfem-mesh keeps stdout for data.
class SilenceStdout {
 public:
  SilenceStdout() : previous_(std::cout.rdbuf(sink_.rdbuf())) {}
  ~SilenceStdout() { std::cout.rdbuf(previous_); }
  SilenceStdout(const SilenceStdout&) = delete;
  SilenceStdout& operator=(const SilenceStdout&) = delete;

 private:
  std::ostringstream sink_;
  std::streambuf* previous_;
};

}  // namespace

double default_facet_distance(const LabelImage& image, const ImageMeshOptions& o) {
  return std::max(0.1 * o.size, 0.25 * o.scale * image.spacing.minCoeff());
}

double kept_voxel_volume(const LabelImage& image, const ImageMeshOptions& o, const std::string& name) {
  const std::set<int> kept = kept_labels(image, o, name);
  std::int64_t n = 0;
  for (std::int32_t l : image.labels) n += l != 0 && kept.count(l);
  return static_cast<double>(n) * image.spacing.prod() * o.scale * o.scale * o.scale;
}

TetMesh image_mesh(const LabelImage& image, const ImageMeshOptions& o, const std::string& name) {
  check_options(o);
  const std::set<int> kept = kept_labels(image, o, name);
  if (kept.empty()) throw Error(name + ": no voxel carries a label to mesh (every voxel is 0)");
  // The image in CGAL's frame: voxel (i, j, k) at (i, j, k) * spacing * scale, labels not kept set to 0.
  const Eigen::Vector3d h = image.spacing * o.scale;
  _image* raw = _createImage(static_cast<std::size_t>(image.dims[0]), static_cast<std::size_t>(image.dims[1]),
                             static_cast<std::size_t>(image.dims[2]), 1, h[0], h[1], h[2], 4, WK_FIXED, SGN_SIGNED);
  if (!raw) throw Error(name + ": cannot allocate the image for the mesher");
  const CGAL::Image_3 cgal_image(raw);  // owns raw
  auto* voxels = static_cast<std::int32_t*>(raw->data);
  for (std::size_t i = 0; i < image.labels.size(); ++i) {
    const std::int32_t l = image.labels[i];
    voxels[i] = kept.count(l) ? l : 0;
  }
  // Weighted labels when smoothing (CGAL's weights image: unsigned char, the image's sizes).
  CGAL::Image_3 weights;
  if (o.smooth > 0) {
    const std::vector<std::uint8_t> w =
        label_weights(std::vector<std::int32_t>(voxels, voxels + image.labels.size()), image.dims,
                      {o.smooth / h[0], o.smooth / h[1], o.smooth / h[2]});
    _image* raw_weights = _createImage(static_cast<std::size_t>(image.dims[0]), static_cast<std::size_t>(image.dims[1]),
                                       static_cast<std::size_t>(image.dims[2]), 1, h[0], h[1], h[2], 1, WK_FIXED,
                                       SGN_UNSIGNED);
    if (!raw_weights) throw Error(name + ": cannot allocate the smoothing weights");
    std::memcpy(raw_weights->data, w.data(), w.size());
    weights = CGAL::Image_3(raw_weights);
  }
  // Surface points located by bisection to 1e-6 of the image's diagonal (CGAL: 1e-3).
  CGAL::Random domain_random(0);
  const Domain domain = Domain::create_labeled_image_mesh_domain(cgal_image, params::relative_error_bound = 1e-6,
                                                                 params::p_rng = &domain_random,
                                                                 params::weights = weights);
  const double facet_distance = o.facet_distance > 0 ? o.facet_distance : default_facet_distance(image, o);
  const Criteria criteria(params::facet_angle = 25, params::facet_size = radius_per_edge * o.size,
                          params::facet_distance = facet_distance, params::cell_radius_edge_ratio = 3,
                          params::cell_size = radius_per_edge * o.size);
  C3t3 c3t3;
  {
    // The seeds shoot rays in random directions from CGAL's default generator: reset, so that the
    // same image gives the same mesh however many were made before in this process.
    CGAL::get_default_random() = CGAL::Random(0);
    SilenceStdout quiet;
    ::initialize_triangulation_from_labeled_image(c3t3, domain, cgal_image, criteria, std::int32_t());
  }
  CGAL::refine_mesh_3(c3t3, domain, criteria, params::no_perturb(), params::exude(params::time_limit = 0));

  // Tets of the complex with their subdomain (the label) and the vertices they use, in world metres.
  const Eigen::Vector3d origin = image.origin * o.scale;
  const bool reflected = image.direction.determinant() < 0;
  std::map<Tr::Vertex_handle, int> ids;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector4i> tets;
  std::vector<int> regions;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Eigen::Vector4i t;
    for (int k = 0; k < 4; ++k) {
      const Tr::Vertex_handle v = c->vertex(k);
      auto [it, added] = ids.emplace(v, static_cast<int>(points.size()));
      if (added) {
        const auto& p = v->point();
        const Eigen::Vector3d q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
        points.push_back(origin + image.direction * q);
      }
      t[k] = it->second;
    }
    if (reflected) std::swap(t[1], t[2]);  // a reflection turns every tet inside out
    tets.push_back(t);
    regions.push_back(static_cast<int>(c3t3.subdomain_index(c)));
  }
  if (tets.empty()) throw Error(name + ": the mesher produced no tetrahedra (is the size too large for the labels?)");
  TetMesh mesh;
  mesh.points.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) mesh.points.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t i = 0; i < tets.size(); ++i) mesh.tets.row(static_cast<Eigen::Index>(i)) = tets[i].transpose();
  set_tet_regions(mesh, regions);
  for (int label : kept) {
    const auto named = image.names.find(label);
    if (named != image.names.end()) mesh.region_names[label] = named->second;
  }
  validate_regions(mesh, name);
  std::vector<std::string> warnings;
  validate_tet_mesh(mesh, name, &warnings);
  return spatially_ordered(mesh);
}

}  // namespace xfem
