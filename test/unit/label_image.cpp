// SPDX-License-Identifier: MIT
// Label maps: each format read back with its voxels and geometry, and hostile headers refused
// with one line naming the file.
#include "xfem/io/label_image.h"

#include <unistd.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageWriter.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "xfem/core/error.h"
#include "xfem/generate/phantom_image.h"

namespace {

namespace fs = std::filesystem;
using xfem::LabelImage;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_label_image_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

// A small image with distinct labels everywhere (so that any axis mix-up shows) and a rotated,
// anisotropic geometry.
LabelImage small_image() {
  LabelImage im;
  im.dims = {12, 4, 3};  // VTK's NRRD reader needs 10 or more along the first axis
  im.spacing = Eigen::Vector3d(0.5, 0.25, 2.0);
  im.origin = Eigen::Vector3d(1, -2, 3);
  im.direction << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // i -> +y, j -> -x
  for (std::int64_t k = 0; k < 3; ++k)
    for (std::int64_t j = 0; j < 4; ++j)
      for (std::int64_t i = 0; i < 12; ++i) im.labels.push_back(static_cast<std::int32_t>(1 + i + 12 * j + 48 * k));
  im.names = {{1, "first"}, {144, "last"}};
  return im;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A VTK image of `im`'s voxels (unsigned char labels), spacing and origin, for VTK's writers.
vtkSmartPointer<vtkImageData> vtk_image(const LabelImage& im) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(static_cast<int>(im.dims[0]), static_cast<int>(im.dims[1]), static_cast<int>(im.dims[2]));
  data->SetSpacing(im.spacing.data());
  data->SetOrigin(im.origin.data());
  auto values = vtkSmartPointer<vtkUnsignedCharArray>::New();
  values->SetName("labels");
  for (std::int32_t l : im.labels) values->InsertNextValue(static_cast<unsigned char>(l));
  data->GetPointData()->SetScalars(values);
  return data;
}

// The message of the xfem::Error `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "";
}

// A NRRD with the header `fields` (after the magic line) and `bytes` of data.
std::string nrrd_with(const std::string& name, const std::string& fields, std::size_t bytes) {
  const std::string path = scratch(name);
  write_text(path, "NRRD0004\n" + fields + "\n" + std::string(bytes, '\1'));
  return path;
}

const char* const good_fields = "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nspacings: 1 1 1\n";

}  // namespace

TEST_CASE("NRRD label maps round-trip with their geometry and names", "[label_image]") {
  const LabelImage im = small_image();
  const std::string path = scratch("small.nrrd");
  xfem::write_label_image_nrrd(im, path);
  const LabelImage back = xfem::read_label_image(path);
  CHECK(back.dims == im.dims);
  CHECK(back.labels == im.labels);
  CHECK((back.spacing - im.spacing).norm() < 1e-15);
  CHECK((back.origin - im.origin).norm() < 1e-15);
  CHECK((back.direction - im.direction).norm() < 1e-15);
  CHECK(back.names == im.names);
  // Voxel (1, 0, 0) lies one spacing along i, which points to +y.
  CHECK((back.world(Eigen::Vector3d(1, 0, 0)) - Eigen::Vector3d(1, -1.5, 3)).norm() < 1e-15);
}

TEST_CASE("MetaImage, NIfTI and VTK XML label maps read with their voxels and geometry", "[label_image]") {
  LabelImage im = small_image();
  im.direction.setIdentity();  // VTK's MetaImage and NIfTI writers write no direction
  const auto data = vtk_image(im);
  SECTION("MetaImage") {
    const std::string path = scratch("small.mha");
    auto w = vtkSmartPointer<vtkMetaImageWriter>::New();
    w->SetInputData(data);
    w->SetFileName(path.c_str());
    w->SetCompression(false);
    w->Write();
    const LabelImage back = xfem::read_label_image(path);
    CHECK(back.labels == im.labels);
    CHECK((back.spacing - im.spacing).norm() < 1e-12);
    CHECK((back.origin - im.origin).norm() < 1e-12);
  }
  SECTION("NIfTI, plain and gzipped") {
    for (const char* name : {"small.nii", "small.nii.gz"}) {
      const std::string path = scratch(name);
      auto w = vtkSmartPointer<vtkNIFTIImageWriter>::New();
      w->SetInputData(data);
      w->SetFileName(path.c_str());
      w->Write();
      const LabelImage back = xfem::read_label_image(path);
      CHECK(back.labels == im.labels);
      CHECK((back.spacing - im.spacing).norm() < 1e-6);  // NIfTI stores float
      CHECK((back.world(Eigen::Vector3d(11, 3, 2)) - im.world(Eigen::Vector3d(11, 3, 2))).norm() < 1e-5);
    }
  }
  SECTION("VTK XML image data, with a direction") {
    im = small_image();
    const auto rotated = vtk_image(im);
    double d[9];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) d[3 * r + c] = im.direction(r, c);
    rotated->SetDirectionMatrix(d);
    const std::string path = scratch("small.vti");
    auto w = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    w->SetInputData(rotated);
    w->SetFileName(path.c_str());
    w->Write();
    const LabelImage back = xfem::read_label_image(path);
    CHECK(back.labels == im.labels);
    CHECK((back.world(Eigen::Vector3d(11, 3, 2)) - im.world(Eigen::Vector3d(11, 3, 2))).norm() < 1e-12);
  }
}

TEST_CASE("INRIMAGE label maps read through CGAL", "[label_image]") {
  const LabelImage im = small_image();
  std::string header = "#INRIMAGE-4#{\nXDIM=12\nYDIM=4\nZDIM=3\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\nCPU=decm\n"
                       "VX=0.5\nVY=0.25\nVZ=2\n";
  header += std::string(252 - header.size(), '\n') + "##}\n";
  REQUIRE(header.size() == 256);
  std::string voxels;
  for (std::int32_t l : im.labels) voxels += static_cast<char>(l);
  const std::string path = scratch("small.inr");
  write_text(path, header + voxels);
  const LabelImage back = xfem::read_label_image(path);
  CHECK(back.labels == im.labels);
  CHECK((back.spacing - im.spacing).norm() < 1e-12);
  SECTION("truncated") {
    write_text(path, header + voxels.substr(0, 30));
    CHECK(error_of([&] { xfem::read_label_image(path); }).find("truncated") != std::string::npos);
  }
  SECTION("float voxels") {
    std::string h = header;
    h.replace(h.find("unsigned fixed"), 14, "float         ");
    write_text(path, h + voxels);
    CHECK(error_of([&] { xfem::read_label_image(path); }).find("integer labels") != std::string::npos);
  }
}

TEST_CASE("the phantom label map: body 1 around inclusion 2, at the voxels' centres", "[label_image]") {
  xfem::PhantomImageSpec spec;
  spec.spacing = Eigen::Vector3d(0.004, 0.003, 0.005);
  const LabelImage im = xfem::phantom_image(spec);
  const Eigen::Vector3d c = xfem::phantom_body_centre(spec);
  // The voxel nearest the inclusion's centre is 2, the body's centre 1, a corner 0.
  const auto voxel = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d ijk = (p + c).cwiseQuotient(spec.spacing);
    return im.at(std::llround(ijk[0]), std::llround(ijk[1]), std::llround(ijk[2]));
  };
  CHECK(voxel(spec.inclusion_centre) == 2);
  CHECK(voxel(Eigen::Vector3d(-0.04, 0, 0)) == 1);
  CHECK(im.at(0, 0, 0) == 0);
  CHECK(im.labels.size() == static_cast<std::size_t>(im.voxels()));
  // Two voxels of background on every side: no label touches the grid's faces.
  for (std::int64_t k = 0; k < im.dims[2]; ++k)
    for (std::int64_t j = 0; j < im.dims[1]; ++j)
      for (std::int64_t i = 0; i < im.dims[0]; ++i)
        if (i < 2 || j < 2 || k < 2 || i >= im.dims[0] - 2 || j >= im.dims[1] - 2 || k >= im.dims[2] - 2)
          REQUIRE(im.at(i, j, k) == 0);
  spec.inclusion_radius = 0.05;
  CHECK(error_of([&] { xfem::phantom_image(spec); }).find("does not lie inside the body") != std::string::npos);
}

TEST_CASE("hostile label maps are refused with one line naming the file", "[label_image][hostile]") {
  const auto refused = [](const std::string& path, const std::string& what) {
    const std::string e = error_of([&] { xfem::read_label_image(path); });
    INFO(e);
    CHECK(e.rfind(path, 0) == 0);
    CHECK(e.find(what) != std::string::npos);
    CHECK(e.find('\n') == std::string::npos);
  };
  refused(nrrd_with("truncated.nrrd", good_fields, 10), "truncated");
  refused(nrrd_with("longer.nrrd", good_fields, 30), "disagree");
  refused(nrrd_with("dims.nrrd", "type: uint8\ndimension: 3\nsizes: 4 3\nencoding: raw\n", 24), "'sizes' has 2 values");
  refused(nrrd_with("2d.nrrd", "type: uint8\ndimension: 2\nsizes: 4 3\nencoding: raw\n", 12), "2D image");
  refused(nrrd_with("slice.nrrd", "type: uint8\ndimension: 3\nsizes: 4 3 1\nencoding: raw\n", 12), "2D image");
  refused(nrrd_with("nan.nrrd", "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nspacings: 1 nan 1\n", 24),
          "spacing nan");
  refused(nrrd_with("nandir.nrrd",
                    "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nspace directions: (1,0,0) (0,nan,0) (0,0,1)\n", 24),
          "spacing nan");
  refused(nrrd_with("zero.nrrd", "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nspacings: 1 0 1\n", 24),
          "must be positive");
  refused(nrrd_with("huge.nrrd", "type: uint8\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n", 24),
          "exceeds the limit");
  refused(nrrd_with("negative.nrrd", "type: uint8\ndimension: 3\nsizes: 4 -3 2\nencoding: raw\n", 24), "not a positive integer");
  refused(nrrd_with("float.nrrd", "type: float\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n", 96), "integer labels");
  refused(nrrd_with("int64.nrrd", "type: int64\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n", 192), "not an integer type");
  refused(nrrd_with("sheared.nrrd",
                    "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nspace directions: (1,0,0) (1,1,0) (0,0,1)\n", 24),
          "not orthonormal");
  refused(nrrd_with("narrow.nrrd", good_fields, 24), "vector components");
  refused(nrrd_with("hex.nrrd", "type: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: hex\n", 48), "not supported");
  {
    const std::string path = scratch("noend.nrrd");
    write_text(path, "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n");
    refused(path, "no end");
  }
  {
    const std::string path = scratch("gzip.nrrd");  // gzip data that is not gzip: VTK's reader fails
    write_text(path, "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 10 3 2\nencoding: gzip\n\nnot gzip at all");
    refused(path, "cannot read label map");
  }
  {
    // A few bytes of "gzip" claiming 4e8 voxels: refused before the reader inflates or allocates.
    const std::string path = scratch("bomb.nrrd");
    write_text(path, "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1000 1000 400\nencoding: gzip\n\nxxxxxxxx");
    refused(path, "bytes of compressed data cannot hold the header's 4e+08 bytes of voxels");
  }
  {
    const std::string path = scratch("bomb.mha");
    write_text(path, "NDims = 3\nDimSize = 1000 1000 400\nElementType = MET_UCHAR\nCompressedData = True\n"
                     "ElementDataFile = LOCAL\nxxxxxxxx");
    refused(path, "cannot hold");
  }
  {
    const std::string path = scratch("skip.nrrd");
    write_text(path, "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 10 3 2\nencoding: raw\nbyte skip: -1\n\n" + std::string(60, '\1'));
    refused(path, "byte skip");
  }
  {
    const std::string path = scratch("empty.nii");
    write_text(path, std::string(100, '\0'));
    refused(path, "NIfTI header is truncated");
  }
  {
    const std::string path = scratch("notmeta.mha");
    write_text(path, "NDims = 3\nDimSize = 4 3 2\n");
    refused(path, "no ElementDataFile");
  }
  {
    const std::string path = scratch("meta2d.mha");
    write_text(path, "NDims = 2\nDimSize = 4 3\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + std::string(12, '\1'));
    refused(path, "2D image");
  }
  {
    const std::string path = scratch("metashort.mha");
    write_text(path, "NDims = 3\nDimSize = 4 3 2\nElementType = MET_USHORT\nElementDataFile = LOCAL\n" + std::string(24, '\1'));
    refused(path, "truncated");
  }
  {
    const std::string path = scratch("metafloat.mha");
    write_text(path, "NDims = 3\nDimSize = 4 3 2\nElementType = MET_FLOAT\nElementDataFile = LOCAL\n" + std::string(96, '\1'));
    refused(path, "integer labels");
  }
  {
    const std::string path = scratch("huge.vti");
    write_text(path, "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 99999 0 99999 0 99999\" Spacing=\"1 1 1\">");
    refused(path, "exceeds the limit");
    write_text(path, "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 999 0 999 0 99\" Spacing=\"1 1 1\">");
    refused(path, "cannot hold");
  }
  {
    const std::string path = scratch("image.png");
    write_text(path, "x");
    refused(path, "unknown label-map format");
  }
  // A header cut anywhere before its end is refused, never read past.
  const LabelImage im = small_image();
  const std::string good = scratch("good.nrrd");
  xfem::write_label_image_nrrd(im, good);
  const std::string bytes = read_all(good);
  for (std::size_t n = 0; n < bytes.size(); n += 7) {
    const std::string cut = scratch("cut.nrrd");
    write_text(cut, bytes.substr(0, n));
    CHECK_THROWS_AS(xfem::read_label_image(cut), xfem::Error);
  }
}

TEST_CASE("label names from a side file: Slicer's colour tables and ITK-SNAP's descriptions", "[label_image]") {
  const std::string path = scratch("names.txt");
  write_text(path, "# a comment\n0 Background 0 0 0 0\n1 liver 221 130 101 255\n    2   255    0    0        1  1  1    \"tumour core\"\n");
  const auto names = xfem::read_label_names(path);
  CHECK(names == std::map<int, std::string>{{0, "Background"}, {1, "liver"}, {2, "tumour core"}});
  write_text(path, "one liver\n");
  CHECK(error_of([&] { xfem::read_label_names(path); }).find(":1: 'one' is not an integer label") != std::string::npos);
}
