// SPDX-License-Identifier: MIT
#include "xfem/generate/image_commands.h"

#include <array>
#include <cmath>
#include <map>
#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/generate/generation_limits.h"
#include "xfem/generate/image_mesh.h"
#include "xfem/generate/phantom_image.h"
#include "xfem/io/label_image.h"
#include "xfem/io/vtk_io.h"

namespace xfem {
namespace {

struct ImageOptions {
  MeshCommandOutput out;
  std::string input, names;
  ImageMeshOptions mesh;
};

struct PhantomOptions {
  MeshCommandOutput out;
  std::array<double, 3> spacing{0.001, 0.001, 0.001}, origin{0, 0, 0}, centre{0.02, 0, 0};
  std::vector<double> direction;
  double radius = 0.015;
};

// One line per region: its label, name, tets and volume, and the image's voxel volume beside it.
void report_regions(const TetMesh& mesh, const LabelImage& image, double scale) {
  const std::vector<int> region = tet_regions(mesh);
  std::map<int, std::pair<long, double>> tets;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    auto& r = tets[region[static_cast<std::size_t>(t)]];
    ++r.first;
    r.second += signed_volume(mesh, static_cast<int>(t));
  }
  std::map<int, long> voxels;
  for (std::int32_t l : image.labels) ++voxels[l];
  const double voxel_volume = image.spacing.prod() * scale * scale * scale;
  for (const auto& [label, r] : tets) {
    const auto name = mesh.region_names.find(label);
    cli::info("region " + std::to_string(label) + (name != mesh.region_names.end() ? " (" + name->second + ")" : "") + ": " +
              std::to_string(r.first) + " tets, " + cli::three_digits(r.second) + " m^3 (voxels: " +
              cli::three_digits(static_cast<double>(voxels[label]) * voxel_volume) + " m^3)");
  }
}

MeshCommand image_command(CLI::App& app) {
  auto o = std::make_shared<ImageOptions>();
  auto* cmd = add_mesh_command(
      app, "image",
      "unstructured tet mesh of a label map (segmented scan: .nrrd/.nhdr, .nii/.nii.gz, .mha/.mhd, .vti, .inr/.inr.gz), "
      "one region per label (cell array region; the labels' names, from the image or --names, as region names), "
      "conforming interfaces between labels (CGAL Mesh_3)",
      "image liver.nrrd --scale 0.001 --labels 1,2 --size 0.005 -o liver.vtu", o->out);
  cmd->add_option("input", o->input, "label map: integer labels, 0 is background")->required();
  cmd->add_option("--size", o->mesh.size, "target edge length, m (tet count grows like 1/size^3)")->required()->check(cli::positive());
  cmd->add_option("--labels", o->mesh.labels, "labels to mesh, comma-separated (default: every non-zero label)")->delimiter(',');
  cmd->add_option("--scale", o->mesh.scale,
                  "metres per image unit, applied to spacing and origin: 0.001 for a millimetre image (most scanners' "
                  "files). Default 1: the image's units are taken as metres, as xfem-mesh phantom-image writes them")
      ->check(cli::positive());
  cmd->add_option("--facet-distance", o->mesh.facet_distance,
                  "how far boundary facets may stray from the labels' boundary, m (default: max(size/10, a quarter of "
                  "the smallest voxel spacing))")
      ->check(cli::positive());
  cmd->add_option("--smooth", o->mesh.smooth,
                  "smooth the label boundaries by weighted labels (a Gaussian of this width, m; e.g. the largest voxel "
                  "spacing): the voxels' steps no longer show (default: none)")
      ->check(cli::positive());
  cmd->add_option("--names", o->names, "label names: lines 'LABEL NAME' or ITK-SNAP's 'LABEL ... \"NAME\"' (default: "
                                       "the names in the image, e.g. 3D Slicer's Segment<N>_Name)");
  return {cmd, [o] {
            cli::check_output(o->out.path, {".vtu"});
            LabelImage image = read_label_image(o->input);
            if (!o->names.empty())
              for (const auto& [label, name] : read_label_names(o->names)) image.names[label] = name;
            const double volume = kept_voxel_volume(image, o->mesh, o->input);
            const Eigen::Vector3d extent = image.spacing.cwiseProduct(Eigen::Vector3d(
                static_cast<double>(image.dims[0]), static_cast<double>(image.dims[1]), static_cast<double>(image.dims[2]))) *
                o->mesh.scale;
            cli::info(o->input + ": " + std::to_string(image.dims[0]) + " x " + std::to_string(image.dims[1]) + " x " +
                      std::to_string(image.dims[2]) + " voxels, " + cli::three_digits(extent[0]) + " x " +
                      cli::three_digits(extent[1]) + " x " + cli::three_digits(extent[2]) + " m");
            if (extent.maxCoeff() > 3)
              cli::warn(o->input + ": the image spans " + cli::three_digits(extent.maxCoeff()) +
                        " m: are its units millimetres? (--scale 0.001)");
            check_element_estimate(tets_for(volume, o->mesh.size), "tets", o->out.allow_large);
            const double start = cli::now();
            TetMesh mesh = image_mesh(image, o->mesh, o->input);
            cli::info("meshed in " + cli::three_digits(cli::now() - start) + " s");
            report_regions(mesh, image, o->mesh.scale);
            write_tet_mesh(mesh, o->out.path);
            cli::info(std::to_string(mesh.tets.rows()) + " tets, " + std::to_string(mesh.points.rows()) + " points -> " +
                      o->out.path);
          }};
}

MeshCommand phantom_image_command(CLI::App& app) {
  auto o = std::make_shared<PhantomOptions>();
  auto* cmd = add_mesh_command(
      app, "phantom-image",
      "synthetic label map (NRRD, metres): the organ-like body as label 1 'body' with a spherical inclusion as label 2 "
      "'inclusion', for tests and examples of xfem-mesh image",
      "phantom-image --spacing 0.002 0.002 0.003 -o phantom.nrrd", o->out);
  cmd->add_option("--spacing", o->spacing, "voxel spacing along i, j, k, m (default 0.001 0.001 0.001)")->check(cli::positive());
  cmd->add_option("--origin", o->origin, "world position of voxel (0,0,0)'s centre, m (default 0 0 0)");
  cmd->add_option("--direction", o->direction,
                  "nine numbers: the world directions of the i, j and k axes, one after another (orthonormal; default "
                  "identity)")
      ->expected(9);
  cmd->add_option("--inclusion-radius", o->radius, "the inclusion's radius, m (default 0.015)")->check(cli::positive());
  cmd->add_option("--inclusion-centre", o->centre, "the inclusion's centre relative to the body's, m (default 0.02 0 0)");
  return {cmd, [o] {
            cli::check_output(o->out.path, {".nrrd"});
            check_extent(o->origin, "--origin");
            PhantomImageSpec spec;
            spec.spacing = Eigen::Vector3d(o->spacing[0], o->spacing[1], o->spacing[2]);
            spec.origin = Eigen::Vector3d(o->origin[0], o->origin[1], o->origin[2]);
            if (!o->direction.empty())
              for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 3; ++c) spec.direction(c, a) = o->direction[static_cast<std::size_t>(3 * a + c)];
            spec.inclusion_centre = Eigen::Vector3d(o->centre[0], o->centre[1], o->centre[2]);
            spec.inclusion_radius = o->radius;
            const auto d = phantom_dims(spec);
            check_element_estimate(static_cast<double>(d[0]) * d[1] * d[2], "voxels", o->out.allow_large);
            const LabelImage image = phantom_image(spec);
            write_label_image_nrrd(image, o->out.path);
            cli::info(std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) +
                      " voxels, labels 1 body, 2 inclusion -> " + o->out.path);
          }};
}

}  // namespace

std::vector<MeshCommand> add_image_commands(CLI::App& app) { return {image_command(app), phantom_image_command(app)}; }

}  // namespace xfem
