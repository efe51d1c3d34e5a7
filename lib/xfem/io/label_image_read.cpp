// SPDX-License-Identifier: MIT
// The voxels of a label map, read by VTK's image readers (NRRD, NIfTI, MetaImage, VTK XML) or by
// CGAL's (INRIMAGE, the format of CGAL's own data), once label_image_header.cpp has checked the
// header. The geometry is the header's, except for NIfTI, whose qform/sform VTK interprets: VTK
// 9.1's NRRD and MetaImage readers keep spacing and origin but drop the direction.
#include <CGAL/Image_3.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNrrdReader.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "xfem/core/error.h"
#include "xfem/io/label_image.h"
#include "xfem/io/vtk_io_detail.h"
#include "xfem/io/vtk_on_demand.h"

namespace xfem {
namespace {

using vtk_io_detail::Ptr;
using vtk_io_detail::VtkMessages;

std::string dims_text(const std::array<std::int64_t, 3>& d) {
  return std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]);
}

// A label as int32: integer values only, within int32's range.
std::int32_t label_value(double v, const std::string& path) {
  if (!(v == std::floor(v) && v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max()))
    throw Error(path + ": voxel value " + short_number(v) + " is not a label (an integer within 32 bits)");
  return static_cast<std::int32_t>(v);
}

// The voxels of VTK's image `data`, which must have the header's sizes and one integer component.
void copy_vtk_voxels(vtkImageData* data, LabelImage& image, const std::string& path) {
  int d[3];
  data->GetDimensions(d);
  const std::array<std::int64_t, 3> got{d[0], d[1], d[2]};
  if (got != image.dims)
    throw Error(path + ": the reader found " + dims_text(got) + " voxels, the header says " + dims_text(image.dims));
  vtkDataArray* scalars = data->GetPointData() ? data->GetPointData()->GetScalars() : nullptr;
  if (!scalars && data->GetPointData() && data->GetPointData()->GetNumberOfArrays() > 0)
    scalars = data->GetPointData()->GetArray(0);
  if (!scalars) throw Error(path + ": the image has no voxel values");
  if (scalars->GetNumberOfComponents() != 1)
    throw Error(path + ": " + std::to_string(scalars->GetNumberOfComponents()) +
                " values per voxel: a label map has one");
  const int type = scalars->GetDataType();
  if (type == VTK_FLOAT || type == VTK_DOUBLE)
    throw Error(path + ": voxel values are floating point: a label map stores integer labels");
  const vtkIdType n = scalars->GetNumberOfTuples();
  if (n != image.voxels())
    throw Error(path + ": the data holds " + std::to_string(n) + " voxels, the header says " + std::to_string(image.voxels()));
  image.labels.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) image.labels[i] = label_value(scalars->GetComponent(i, 0), path);
}

template <class Reader>
vtkImageData* run_vtk(Reader* reader, const VtkMessages& messages, const std::string& path) {
  reader->SetFileName(path.c_str());
  vtk_io_detail::update_or_throw(reader, messages, path, "label map");
  vtkImageData* out = reader->GetOutput();
  if (!out) throw Error(path + ": cannot read label map");
  return out;
}

// NIfTI: VTK's qform or sform (sform when the file sets it) maps VTK's voxel coordinates to the
// NIfTI world (RAS), with the spacing factored out and the slices reordered when qfac is -1.
void nifti_geometry(vtkNIFTIImageReader* reader, vtkImageData* out, LabelImage& image, const std::string& path) {
  // vtkNIFTIImageReader::GetNIFTIHeader() is no virtual function and its library is not linked
  // (vtk_on_demand.h): called by address, `this` as the first argument (the Itanium C++ ABI's
  // convention for a non-virtual member function).
  const auto get_header = reinterpret_cast<vtkNIFTIImageHeader* (*)(vtkNIFTIImageReader*)>(vtk_symbol(
      vtk_io_image_library, "_ZN19vtkNIFTIImageReader14GetNIFTIHeaderEv", path, "label map"));
  vtkNIFTIImageHeader* header = get_header(reader);
  const double slope = header->GetSclSlope(), intercept = header->GetSclInter();
  if (!((slope == 0 || slope == 1) && intercept == 0))
    throw Error(path + ": NIfTI scl_slope " + short_number(slope) + ", scl_inter " + short_number(intercept) +
                ": scaled voxel values are not labels");
  double spacing[3], origin[3];
  out->GetSpacing(spacing);
  out->GetOrigin(origin);
  image.spacing = Eigen::Vector3d(spacing[0], spacing[1], spacing[2]);
  const Eigen::Vector3d vtk_origin(origin[0], origin[1], origin[2]);
  vtkMatrix4x4* m = header->GetSFormCode() > 0 ? reader->GetSFormMatrix() : nullptr;
  if (!m && header->GetQFormCode() > 0) m = reader->GetQFormMatrix();
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  if (m)
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r(i, j) = m->GetElement(i, j);
      t[i] = m->GetElement(i, 3);
    }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (!std::isfinite(r(a, b)) || std::abs(r.col(a).dot(r.col(b)) - (a == b ? 1.0 : 0.0)) > 1e-4)
        throw Error(path + ": the NIfTI orientation is not a rotation (a sheared or scaled sform)");
  if (!t.allFinite()) throw Error(path + ": the NIfTI offset is not finite");
  image.direction = r;
  image.origin = t + r * vtk_origin;
}

void read_inr(const std::string& path, LabelImage& image) {
  CGAL::Image_3 inr;
  if (!inr.read(path.c_str())) throw Error(path + ": cannot read INRIMAGE file (truncated or corrupt?)");
  const std::array<std::int64_t, 3> got{static_cast<std::int64_t>(inr.xdim()), static_cast<std::int64_t>(inr.ydim()),
                                        static_cast<std::int64_t>(inr.zdim())};
  if (got != image.dims) throw Error(path + ": the reader found " + dims_text(got) + " voxels, the header says " + dims_text(image.dims));
  const _image* im = inr.image();
  if (im->wordKind != WK_FIXED) throw Error(path + ": voxel values are floating point: a label map stores integer labels");
  image.labels.resize(static_cast<std::size_t>(image.voxels()));
  const bool sign = im->sign == SGN_SIGNED;
  for (std::size_t i = 0; i < image.labels.size(); ++i) {
    double v = 0;
    switch (im->wdim) {
      case 1: v = sign ? static_cast<const std::int8_t*>(im->data)[i] : static_cast<const std::uint8_t*>(im->data)[i]; break;
      case 2: v = sign ? static_cast<const std::int16_t*>(im->data)[i] : static_cast<const std::uint16_t*>(im->data)[i]; break;
      case 4: v = sign ? static_cast<const std::int32_t*>(im->data)[i] : static_cast<const std::uint32_t*>(im->data)[i]; break;
      default: throw Error(path + ": INRIMAGE word of " + std::to_string(im->wdim) + " bytes is not supported");
    }
    image.labels[i] = label_value(v, path);
  }
}

}  // namespace

LabelImage read_label_image(const std::string& path) {
  const LabelImageHeader header = read_label_image_header(path);
  LabelImage image;
  image.dims = header.dims;
  image.spacing = header.spacing;
  image.origin = header.origin;
  image.direction = header.direction;
  image.names = header.names;
  if (header.format == "inr") {
    read_inr(path, image);
    return image;
  }
  VtkMessages messages;
  if (header.format == "nrrd") {
    auto reader = Ptr<vtkNrrdReader>::Take(
        vtk_new_on_demand<vtkNrrdReader>(vtk_io_image_library, "_ZN13vtkNrrdReader3NewEv", path, "label map"));
    copy_vtk_voxels(run_vtk(reader.Get(), messages, path), image, path);
  } else if (header.format == "metaimage") {
    auto reader = Ptr<vtkMetaImageReader>::Take(
        vtk_new_on_demand<vtkMetaImageReader>(vtk_io_image_library, "_ZN18vtkMetaImageReader3NewEv", path, "label map"));
    copy_vtk_voxels(run_vtk(reader.Get(), messages, path), image, path);
  } else if (header.format == "vti") {
    auto reader = Ptr<vtkXMLImageDataReader>::New();
    copy_vtk_voxels(run_vtk(reader.Get(), messages, path), image, path);
  } else {
    auto reader = Ptr<vtkNIFTIImageReader>::Take(
        vtk_new_on_demand<vtkNIFTIImageReader>(vtk_io_image_library, "_ZN19vtkNIFTIImageReader3NewEv", path, "label map"));
    vtkImageData* out = run_vtk(reader.Get(), messages, path);
    copy_vtk_voxels(out, image, path);
    nifti_geometry(reader.Get(), out, image, path);
  }
  return image;
}

std::map<int, std::string> read_label_names(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open");
  std::map<int, std::string> names;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line = line.substr(0, hash);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    char* end = nullptr;
    const long label = std::strtol(first.c_str(), &end, 10);
    if (*end != '\0' || label < std::numeric_limits<std::int32_t>::min() || label > std::numeric_limits<std::int32_t>::max())
      throw Error(path + ":" + std::to_string(number) + ": '" + first.substr(0, 30) + "' is not an integer label");
    std::string name;
    const std::size_t q = line.find('"');
    if (q != std::string::npos) {
      const std::size_t e = line.find('"', q + 1);
      if (e == std::string::npos) throw Error(path + ":" + std::to_string(number) + ": unterminated quoted name");
      name = line.substr(q + 1, e - q - 1);
    } else {
      words >> name;
    }
    if (name.empty()) throw Error(path + ":" + std::to_string(number) + ": label " + first + " has no name");
    names[static_cast<int>(label)] = name;
  }
  return names;
}

}  // namespace xfem
