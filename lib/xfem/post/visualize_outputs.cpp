// SPDX-License-Identifier: MIT
#include "xfem/post/visualize_outputs.h"

#include <vector>

#include "xfem/core/atomic_file.h"
#include "xfem/io/surface_write.h"

namespace xfem {
namespace {

Fingerprint chain(Fingerprint seed, Fingerprint f) { return fnv1a64(&f, sizeof f, seed); }

}  // namespace

Fingerprint visualize_inputs_fingerprint(const EnrichedMesh& em, const Eigen::VectorXd& u,
                                         const std::string& problem_path, double wound_offset,
                                         const std::vector<double>& wound_pressure) {
  Fingerprint f = fnv1a64(u.data(), sizeof(double) * static_cast<std::size_t>(u.size()));
  f = chain(f, fingerprint(em.mesh));
  if (em.cut) f = chain(f, fingerprint(em.cut->mesh()));
  for (const CutLayer& layer : em.cuts)  // several cuts (em.cut may be the first of them again: harmless)
    if (layer.cut) f = chain(f, fingerprint(layer.cut->mesh()));
  f = chain(f, fingerprint_json_file(problem_path));
  f = fnv1a64(&wound_offset, sizeof wound_offset, f);
  // Unchanged without --contact-pressure (an empty array chains nothing).
  return wound_pressure.empty() ? f : fnv1a64(wound_pressure.data(), sizeof(double) * wound_pressure.size(), f);
}

void write_visualize_outputs(DeformedBody& body, const std::string& volume_path, const std::string& wound_path,
                             Compression packing, Fingerprint inputs) {
  store_fingerprint(body.volume.field_data, "inputs_fingerprint", inputs);
  DataArrays wound_fields;
  store_fingerprint(wound_fields, "inputs_fingerprint", inputs);
  std::vector<FileWriter> files{{volume_path, [&](const std::string& tmp) { write_tet_mesh(body.volume, tmp, packing); }}};
  if (!wound_path.empty())
    files.push_back({wound_path, [&](const std::string& tmp) { write_triangle_mesh(body.wound, wound_fields, tmp, packing); }});
  write_atomically_together(files);
}

}  // namespace xfem
