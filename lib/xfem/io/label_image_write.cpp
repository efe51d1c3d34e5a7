// SPDX-License-Identifier: MIT
// NRRD label maps, written directly (VTK 9.1 has no NRRD writer): a text header and the raw
// voxels in the smallest integer type that holds every label, little-endian.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/io/label_image.h"

namespace xfem {
namespace {

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string vector_text(const Eigen::Vector3d& v) { return "(" + exact(v[0]) + "," + exact(v[1]) + "," + exact(v[2]) + ")"; }

template <class T>
void write_voxels(std::ostream& out, const std::vector<std::int32_t>& labels) {
  std::vector<T> buffer(labels.begin(), labels.end());
  out.write(reinterpret_cast<const char*>(buffer.data()), static_cast<std::streamsize>(buffer.size() * sizeof(T)));
}

}  // namespace

void write_label_image_nrrd(const LabelImage& image, const std::string& path) {
  if (static_cast<std::int64_t>(image.labels.size()) != image.voxels())
    throw Error(path + ": label map has " + std::to_string(image.labels.size()) + " labels for " +
                std::to_string(image.voxels()) + " voxels");
  const auto [lo, hi] = std::minmax_element(image.labels.begin(), image.labels.end());
  const bool u8 = image.labels.empty() || (*lo >= 0 && *hi <= 255);
  const bool i16 = !u8 && *lo >= -32768 && *hi <= 32767;
  std::ostringstream h;
  h << "NRRD0004\n# label map written by xfem-mesh (docs/FORMATS.md, \"Label maps\")\n";
  h << "type: " << (u8 ? "uint8" : i16 ? "int16" : "int32") << "\ndimension: 3\nspace dimension: 3\n";
  h << "sizes: " << image.dims[0] << " " << image.dims[1] << " " << image.dims[2] << "\n";
  h << "space directions:";
  for (int a = 0; a < 3; ++a) h << " " << vector_text(image.direction.col(a) * image.spacing[a]);
  h << "\nkinds: domain domain domain\nendian: little\nencoding: raw\n";
  h << "space origin: " << vector_text(image.origin) << "\n";
  int segment = 0;
  for (const auto& [label, name] : image.names) {
    h << "Segment" << segment << "_LabelValue:=" << label << "\n";
    h << "Segment" << segment << "_Name:=" << name << "\n";
    ++segment;
  }
  h << "\n";
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot write");
    out << h.str();
    if (u8)
      write_voxels<std::uint8_t>(out, image.labels);
    else if (i16)
      write_voxels<std::int16_t>(out, image.labels);
    else
      write_voxels<std::int32_t>(out, image.labels);
    out.close();
    if (!out) throw Error(path + ": write failed (disk full?)");
  });
}

}  // namespace xfem
