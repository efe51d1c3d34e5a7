// SPDX-License-Identifier: MIT
// Each label-map format's header, parsed and checked here before VTK or CGAL reads a voxel:
// their readers trust the sizes in a header and allocate for them (a corrupt size is an
// out-of-memory abort or a read past the end), and some ignore the image's direction. What is
// checked is listed at read_label_image_header (label_image.h).
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/io/vtk_xml_check.h"
#include "xfem/io/label_image.h"

namespace xfem {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") + 1 - b);
}

// Up to `n` bytes from the start of `path`, through zlib when `gzipped` (gzread also reads a
// file that is not compressed).
std::string head_of(const std::string& path, std::size_t n, bool gzipped) {
  std::string buf(n, '\0');
  if (gzipped) {
    gzFile f = gzopen(path.c_str(), "rb");
    if (!f) throw Error(path + ": cannot open");
    const int got = gzread(f, buf.data(), static_cast<unsigned>(n));
    gzclose(f);
    if (got < 0) throw Error(path + ": not a readable gzip file");
    buf.resize(static_cast<std::size_t>(got));
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    in.read(buf.data(), static_cast<std::streamsize>(n));
    buf.resize(static_cast<std::size_t>(in.gcount()));
  }
  return buf;
}

// A voxel type: its size in bytes and whether it holds integers.
struct VoxelType {
  int bytes = 0;
  bool integer = false;
};

// The words of a value, split at spaces, commas and parentheses.
std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  for (char c : s) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == '(' || c == ')') {
      if (!w.empty()) out.push_back(w);
      w.clear();
    } else {
      w += c;
    }
  }
  if (!w.empty()) out.push_back(w);
  return out;
}

double number(const std::string& w, const std::string& path, const std::string& field) {
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  if (w.empty() || *end != '\0') throw Error(path + ": " + field + ": '" + w.substr(0, 40) + "' is not a number");
  return v;
}

// Sizes: positive integers, their product within kMaxImageVoxels; 2D and 4D images named.
std::array<std::int64_t, 3> checked_dims(const std::vector<double>& sizes, const std::string& path) {
  std::vector<double> s = sizes;
  if (s.size() == 4 && s[3] == 1) s.pop_back();  // a 4D image of one time point is 3D
  if (s.size() == 2) throw Error(path + ": a 2D image (" + std::to_string(s.size()) + " sizes): a label map to mesh must be 3D");
  if (s.size() != 3)
    throw Error(path + ": an image of dimension " + std::to_string(s.size()) + ": a label map to mesh must be 3D");
  double total = 1;
  for (double v : s) {
    if (!(v >= 1 && v == std::floor(v) && v < 1e12))
      throw Error(path + ": image size " + short_number(v) + " is not a positive integer");
    total *= v;
  }
  if (s[0] < 2 || s[1] < 2 || s[2] < 2)
    throw Error(path + ": image sizes " + short_number(s[0]) + " x " + short_number(s[1]) + " x " + short_number(s[2]) +
                ": a single slice is a 2D image; a label map to mesh must be 3D");
  if (total > kMaxImageVoxels)
    throw Error(path + ": image of " + short_number(total) + " voxels (" + short_number(s[0]) + " x " +
                short_number(s[1]) + " x " + short_number(s[2]) + ") exceeds the limit of " +
                short_number(kMaxImageVoxels) + " (corrupt header?)");
  return {static_cast<std::int64_t>(s[0]), static_cast<std::int64_t>(s[1]), static_cast<std::int64_t>(s[2])};
}

void check_spacing(const Eigen::Vector3d& spacing, const std::string& path) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(spacing[a]) && spacing[a] > 0))
      throw Error(path + ": voxel spacing " + short_number(spacing[a]) + " along axis " + std::to_string(a) +
                  " must be positive and finite");
}

void check_origin(const Eigen::Vector3d& origin, const std::string& path) {
  if (!origin.allFinite()) throw Error(path + ": the image origin is not finite");
}

// Directions: unit columns, orthogonal to within 1e-4 (scanners write them rounded).
void check_direction(const Eigen::Matrix3d& d, const std::string& path) {
  if (!d.allFinite()) throw Error(path + ": the image direction is not finite");
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (std::abs(d.col(a).dot(d.col(b)) - (a == b ? 1.0 : 0.0)) > 1e-4)
        throw Error(path + ": the image's axes are not orthonormal (a sheared image); xfem-mesh image "
                           "needs a rotation or reflection as direction");
}

// Bytes from `offset` to the end of `file` must be `expected` (uncompressed voxels).
void check_data_size(const std::string& path, const std::string& file, std::uintmax_t offset, double expected,
                     bool exact) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) throw Error(path + ": cannot open its data file " + file);
  const double have = size >= offset ? static_cast<double>(size - offset) : 0.0;
  if (have < expected || (exact && have != expected))
    throw Error(path + ": the data holds " + short_number(have) + " bytes of voxels, the header says " +
                short_number(expected) + (have < expected ? " (truncated file?)" : " (header and data disagree)"));
}

// zlib's deflate cannot compress more than 1032:1, so compressed data smaller than this share of
// the voxels' bytes cannot hold them: a tiny hostile file would otherwise make the reader
// allocate for (and inflate into) gigabytes.
constexpr double max_deflate_ratio = 1032;
void check_compressed_size(const std::string& path, const std::string& file, std::uintmax_t offset, double expected) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) throw Error(path + ": cannot open its data file " + file);
  const double have = size >= offset ? static_cast<double>(size - offset) : 0.0;
  if (have * max_deflate_ratio < expected)
    throw Error(path + ": " + short_number(have) + " bytes of compressed data cannot hold the header's " +
                short_number(expected) + " bytes of voxels (truncated file?)");
}

const char* float_refusal = ": a label map stores integer labels (this looks like a grey-level image)";

// ---- NRRD -------------------------------------------------------------------------------
VoxelType nrrd_type(const std::string& t, const std::string& path) {
  static const std::map<std::string, VoxelType> types = {
      {"signed char", {1, true}},    {"int8", {1, true}},           {"int8_t", {1, true}},
      {"uchar", {1, true}},          {"unsigned char", {1, true}},  {"uint8", {1, true}},
      {"uint8_t", {1, true}},        {"short", {2, true}},          {"short int", {2, true}},
      {"signed short", {2, true}},   {"signed short int", {2, true}}, {"int16", {2, true}},
      {"int16_t", {2, true}},        {"ushort", {2, true}},         {"unsigned short", {2, true}},
      {"unsigned short int", {2, true}}, {"uint16", {2, true}},     {"uint16_t", {2, true}},
      {"int", {4, true}},            {"signed int", {4, true}},     {"int32", {4, true}},
      {"int32_t", {4, true}},        {"uint", {4, true}},           {"unsigned int", {4, true}},
      {"uint32", {4, true}},         {"uint32_t", {4, true}},       {"float", {4, false}},
      {"double", {8, false}}};
  const auto it = types.find(lower(t));
  if (it == types.end()) throw Error(path + ": voxel type '" + t.substr(0, 40) + "' is not an integer type of 32 bits or fewer");
  if (!it->second.integer) throw Error(path + ": voxel type '" + t + "'" + float_refusal);
  return it->second;
}

LabelImageHeader nrrd_header(const std::string& path) {
  const std::string text = head_of(path, 1 << 20, false);
  if (text.compare(0, 4, "NRRD") != 0) throw Error(path + ": not a NRRD file (no NRRD magic)");
  std::map<std::string, std::string> fields, keys;
  std::size_t pos = text.find('\n');
  std::size_t header_end = std::string::npos;
  while (pos != std::string::npos && pos + 1 <= text.size()) {
    const std::size_t next = text.find('\n', pos + 1);
    if (next == std::string::npos) break;  // a line without its end: the header is cut
    std::string line = text.substr(pos + 1, next - pos - 1);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = next;
    if (line.empty()) {
      header_end = next + 1;
      break;
    }
    if (line[0] == '#') continue;
    const std::size_t kv = line.find(":=");
    const std::size_t colon = line.find(": ");
    if (kv != std::string::npos && (colon == std::string::npos || kv < colon)) {
      keys[trim(line.substr(0, kv))] = trim(line.substr(kv + 2));
    } else if (colon != std::string::npos) {
      fields[lower(trim(line.substr(0, colon)))] = trim(line.substr(colon + 2));
    } else {
      throw Error(path + ": NRRD header line '" + line.substr(0, 40) + "' is neither 'field: value' nor 'key:=value'");
    }
  }
  const bool detached = fields.count("data file") || fields.count("datafile");
  if (!detached && header_end == std::string::npos)
    throw Error(path + ": NRRD header has no end (no blank line before the data: truncated file?)");
  // A header is text: VTK 9.1's reader loops for ever on a NUL byte in it (found by fuzz_nrrd).
  const std::size_t header_size = header_end == std::string::npos ? pos : header_end;
  for (std::size_t i = 0; i < header_size; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 32 && c != '\n' && c != '\r' && c != '\t') {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02x", c);
      throw Error(path + ": NRRD header holds the control byte " + code + " at byte " + std::to_string(i) +
                  " (a header is text: corrupt file?)");
    }
  }
  for (const char* f : {"dimension", "type", "sizes", "encoding"})
    if (!fields.count(f)) throw Error(path + ": NRRD header has no '" + f + "' field");
  LabelImageHeader h;
  h.format = "nrrd";
  const double dimension = number(fields["dimension"], path, "dimension");
  const VoxelType type = nrrd_type(fields["type"], path);
  // VTK 9.1's reader reads that many numbers per vector of 'space origin' and 'space directions',
  // whatever they hold: another count made it read out of bounds (SIGSEGV, found by fuzz_nrrd).
  if (fields.count("space dimension") && number(fields["space dimension"], path, "space dimension") != 3)
    throw Error(path + ": NRRD 'space dimension' is " + fields["space dimension"].substr(0, 20) +
                ", not 3 (a 3D label map)");
  std::vector<double> sizes;
  for (const auto& w : words(fields["sizes"])) sizes.push_back(number(w, path, "sizes"));
  if (static_cast<double>(sizes.size()) != dimension)
    throw Error(path + ": NRRD 'sizes' has " + std::to_string(sizes.size()) + " values for dimension " +
                short_number(dimension));
  h.dims = checked_dims(sizes, path);
  if (fields.count("space directions")) {
    const std::vector<std::string> w = words(fields["space directions"]);
    if (w.size() < 9) throw Error(path + ": NRRD 'space directions' needs three 3-vectors");
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d v;
      for (int c = 0; c < 3; ++c) v[c] = number(w[3 * a + c], path, "space directions");
      h.spacing[a] = v.norm();
      check_spacing(h.spacing, path);
      h.direction.col(a) = v / h.spacing[a];
    }
  } else if (fields.count("spacings")) {
    const std::vector<std::string> w = words(fields["spacings"]);
    if (w.size() < 3) throw Error(path + ": NRRD 'spacings' needs three values");
    for (int a = 0; a < 3; ++a) h.spacing[a] = number(w[a], path, "spacings");
  }
  check_spacing(h.spacing, path);
  check_direction(h.direction, path);
  if (fields.count("space origin")) {
    const std::vector<std::string> w = words(fields["space origin"]);
    if (w.size() != 3) throw Error(path + ": NRRD 'space origin' needs one 3-vector");
    for (int c = 0; c < 3; ++c) h.origin[c] = number(w[c], path, "space origin");
  }
  check_origin(h.origin, path);
  h.geometry_known = true;
  const std::string encoding = lower(fields["encoding"]);
  if (encoding != "raw" && encoding != "gzip" && encoding != "gz")
    throw Error(path + ": NRRD encoding '" + encoding.substr(0, 20) + "' is not supported (raw or gzip)");
  {
    const double expected = static_cast<double>(h.dims[0]) * h.dims[1] * h.dims[2] * type.bytes;
    std::string file = path;
    std::uintmax_t offset = header_end;
    if (detached) {
      const std::string name = fields.count("data file") ? fields["data file"] : fields["datafile"];
      if (name.rfind("LIST", 0) == 0 || name.find('%') != std::string::npos || words(name).size() > 1)
        throw Error(path + ": NRRD data in several files is not supported (one detached data file)");
      file = (fs::path(path).parent_path() / name).string();
      offset = 0;
    }
    if ((fields.count("byte skip") && fields["byte skip"] != "0") || (fields.count("line skip") && fields["line skip"] != "0"))
      throw Error(path + ": NRRD byte skip and line skip are not supported");
    if (encoding == "raw")
      check_data_size(path, file, offset, expected, true);
    else
      check_compressed_size(path, file, offset, expected);
  }
  // VTK's reader takes a first axis of 9 or fewer samples for a vector's components, and reads
  // the rows of a left-anterior-superior space upside down: refused rather than misread.
  if (h.dims[0] <= 9)
    throw Error(path + ": a NRRD image " + std::to_string(h.dims[0]) +
                " voxels wide along its first axis is read by VTK as vector components: not supported (10 or more)");
  if (fields.count("space")) {
    const std::string space = lower(fields["space"]);
    if (space == "left-anterior-superior" || space == "las" || space == "3d-left-handed")
      throw Error(path + ": NRRD space '" + fields["space"] + "' is not supported (VTK's reader flips its rows)");
    if (space.find("time") != std::string::npos) throw Error(path + ": NRRD space with time is not a 3D label map");
  }
  // 3D Slicer's segmentation files name their labels: Segment<N>_LabelValue and Segment<N>_Name.
  for (const auto& [key, value] : keys) {
    if (!(key.rfind("Segment", 0) == 0 && ends_with(key, "_Name"))) continue;
    const std::string stem = key.substr(0, key.size() - 5);
    const auto label = keys.find(stem + "_LabelValue");
    if (label == keys.end()) continue;
    char* end = nullptr;
    const long v = std::strtol(label->second.c_str(), &end, 10);
    if (*end == '\0' && !label->second.empty()) h.names[static_cast<int>(v)] = value;
  }
  return h;
}

// ---- MetaImage ------------------------------------------------------------------------------
LabelImageHeader metaimage_header(const std::string& path) {
  const std::string text = head_of(path, 1 << 20, false);
  std::map<std::string, std::string> fields;
  std::size_t pos = 0, header_end = std::string::npos;
  while (pos < text.size()) {
    const std::size_t next = text.find('\n', pos);
    if (next == std::string::npos) break;
    std::string line = text.substr(pos, next - pos);
    pos = next + 1;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) throw Error(path + ": MetaImage header line '" + line.substr(0, 40) + "' has no '='");
    const std::string key = trim(line.substr(0, eq));
    fields[key] = trim(line.substr(eq + 1));
    if (key == "ElementDataFile") {
      header_end = pos;
      break;
    }
  }
  if (header_end == std::string::npos)
    throw Error(path + ": MetaImage header has no ElementDataFile line (truncated file, or not a MetaImage?)");
  for (const char* f : {"NDims", "DimSize", "ElementType"})
    if (!fields.count(f)) throw Error(path + ": MetaImage header has no '" + f + "'");
  LabelImageHeader h;
  h.format = "metaimage";
  const double ndims = number(fields["NDims"], path, "NDims");
  std::vector<double> sizes;
  for (const auto& w : words(fields["DimSize"])) sizes.push_back(number(w, path, "DimSize"));
  if (static_cast<double>(sizes.size()) != ndims)
    throw Error(path + ": MetaImage DimSize has " + std::to_string(sizes.size()) + " values for NDims " + short_number(ndims));
  h.dims = checked_dims(sizes, path);
  static const std::map<std::string, VoxelType> types = {
      {"MET_CHAR", {1, true}},   {"MET_UCHAR", {1, true}}, {"MET_SHORT", {2, true}},   {"MET_USHORT", {2, true}},
      {"MET_INT", {4, true}},    {"MET_UINT", {4, true}},  {"MET_LONG", {4, true}},    {"MET_ULONG", {4, true}},
      {"MET_FLOAT", {4, false}}, {"MET_DOUBLE", {8, false}}};
  const auto type = types.find(fields["ElementType"]);
  if (type == types.end())
    throw Error(path + ": voxel type '" + fields["ElementType"].substr(0, 40) + "' is not an integer type of 32 bits or fewer");
  if (!type->second.integer) throw Error(path + ": voxel type '" + fields["ElementType"] + "'" + float_refusal);
  if (fields.count("ElementNumberOfChannels") && fields["ElementNumberOfChannels"] != "1")
    throw Error(path + ": an image of several channels per voxel is not a label map");
  const auto vector3 = [&](const char* key, Eigen::Vector3d& v) {
    if (!fields.count(key)) return false;
    const auto w = words(fields[key]);
    if (w.size() < 3) throw Error(path + ": MetaImage " + key + " needs three values");
    for (int c = 0; c < 3; ++c) v[c] = number(w[c], path, key);
    return true;
  };
  if (!vector3("ElementSpacing", h.spacing)) vector3("ElementSize", h.spacing);
  check_spacing(h.spacing, path);
  if (!vector3("Offset", h.origin) && !vector3("Origin", h.origin)) vector3("Position", h.origin);
  check_origin(h.origin, path);
  for (const char* key : {"TransformMatrix", "Rotation", "Orientation"}) {
    if (!fields.count(key)) continue;
    const auto w = words(fields[key]);
    if (w.size() != 9) throw Error(path + ": MetaImage " + key + " needs nine values");
    // Written as ITK writes it: the direction of axis i is values 3i..3i+2.
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) h.direction(c, a) = number(w[3 * a + c], path, key);
    break;
  }
  check_direction(h.direction, path);
  h.geometry_known = true;
  const bool compressed = fields.count("CompressedData") && lower(fields["CompressedData"]) == "true";
  const std::string data = fields["ElementDataFile"];
  if (data == "LIST" || data.find('%') != std::string::npos)
    throw Error(path + ": MetaImage data in several files is not supported (LOCAL or one data file)");
  const double expected = static_cast<double>(h.dims[0]) * h.dims[1] * h.dims[2] * type->second.bytes;
  const std::string file = data == "LOCAL" ? path : (fs::path(path).parent_path() / data).string();
  const std::uintmax_t offset = data == "LOCAL" ? header_end : 0;
  if (compressed)
    check_compressed_size(path, file, offset, expected);
  else
    check_data_size(path, file, offset, expected, true);
  return h;
}

// ---- NIfTI-1 --------------------------------------------------------------------------------
template <class T>
T field_at(const std::string& h, std::size_t offset, bool swap) {
  T v;
  char bytes[sizeof(T)];
  std::memcpy(bytes, h.data() + offset, sizeof(T));
  if (swap) std::reverse(bytes, bytes + sizeof(T));
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

LabelImageHeader nifti_header(const std::string& path, bool gzipped) {
  const std::string head = head_of(path, 352, gzipped);
  if (head.size() < 348) throw Error(path + ": NIfTI header is truncated (" + std::to_string(head.size()) + " of 348 bytes)");
  bool swap = false;
  if (field_at<std::int32_t>(head, 0, false) != 348) {
    swap = true;
    if (field_at<std::int32_t>(head, 0, true) != 348) throw Error(path + ": not a NIfTI-1 file (sizeof_hdr is not 348)");
  }
  const std::string magic = head.substr(344, 3);
  if (magic != "n+1" && magic != "ni1") throw Error(path + ": not a NIfTI-1 file (no n+1 magic)");
  LabelImageHeader h;
  h.format = "nifti";
  const int ndim = field_at<std::int16_t>(head, 40, swap);
  if (ndim < 1 || ndim > 7) throw Error(path + ": NIfTI dim[0] = " + std::to_string(ndim) + " is not a dimension");
  std::vector<double> sizes;
  for (int a = 1; a <= ndim; ++a) sizes.push_back(field_at<std::int16_t>(head, 40 + 2 * a, swap));
  while (sizes.size() > 3 && sizes.back() == 1) sizes.pop_back();
  h.dims = checked_dims(sizes, path);
  const int datatype = field_at<std::int16_t>(head, 70, swap);
  static const std::map<int, VoxelType> types = {{2, {1, true}},   {256, {1, true}}, {4, {2, true}},  {512, {2, true}},
                                                 {8, {4, true}},   {768, {4, true}}, {16, {4, false}}, {64, {8, false}}};
  const auto type = types.find(datatype);
  if (type == types.end())
    throw Error(path + ": NIfTI datatype " + std::to_string(datatype) + " is not an integer type of 32 bits or fewer");
  if (!type->second.integer) throw Error(path + ": NIfTI datatype " + std::to_string(datatype) + float_refusal);
  for (int a = 0; a < 3; ++a) h.spacing[a] = std::abs(field_at<float>(head, 80 + 4 * (a + 1), swap));
  check_spacing(h.spacing, path);
  const double vox_offset = field_at<float>(head, 108, swap);
  if (!(vox_offset >= 348 && vox_offset < 1e9)) throw Error(path + ": NIfTI vox_offset " + short_number(vox_offset) + " is not a data offset");
  const double expected = static_cast<double>(h.dims[0]) * h.dims[1] * h.dims[2] * type->second.bytes;
  if (magic != "n+1")
    throw Error(path + ": a NIfTI header without its image (.hdr/.img pair) is not supported: one .nii or .nii.gz file");
  if (gzipped)
    check_compressed_size(path, path, 0, expected);
  else
    check_data_size(path, path, static_cast<std::uintmax_t>(vox_offset), expected, false);
  // The orientation (qform/sform) is VTK's to interpret (label_image_read.cpp).
  return h;
}

// ---- INRIMAGE -------------------------------------------------------------------------------
LabelImageHeader inr_header(const std::string& path, bool gzipped) {
  const std::string head = head_of(path, 256, gzipped);
  if (head.compare(0, 12, "#INRIMAGE-4#") != 0) throw Error(path + ": not an INRIMAGE file (no #INRIMAGE-4# magic)");
  std::size_t end = head.find("##}");
  if (end == std::string::npos) throw Error(path + ": INRIMAGE header has no end ('##}'; truncated file?)");
  std::map<std::string, std::string> fields;
  std::istringstream lines(head.substr(0, end));
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) fields[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  LabelImageHeader h;
  h.format = "inr";
  std::vector<double> sizes;
  for (const char* f : {"XDIM", "YDIM", "ZDIM"}) {
    if (!fields.count(f)) throw Error(path + ": INRIMAGE header has no " + f);
    sizes.push_back(number(fields[f], path, f));
  }
  h.dims = checked_dims(sizes, path);
  if (fields.count("VDIM") && fields["VDIM"] != "1") throw Error(path + ": an image of several values per voxel is not a label map");
  const std::string type = fields["TYPE"];
  if (type.find("float") != std::string::npos) throw Error(path + ": voxel type '" + type + "'" + float_refusal);
  if (type.find("fixed") == std::string::npos) throw Error(path + ": INRIMAGE TYPE '" + type.substr(0, 30) + "' is not an integer type");
  const double bits = fields.count("PIXSIZE") ? std::atof(fields["PIXSIZE"].c_str()) : 8;
  if (!(bits == 8 || bits == 16 || bits == 32)) throw Error(path + ": INRIMAGE PIXSIZE " + short_number(bits) + " bits is not 8, 16 or 32");
  int axis = 0;
  for (const char* f : {"VX", "VY", "VZ"}) {
    if (fields.count(f)) h.spacing[axis] = number(fields[f], path, f);
    ++axis;
  }
  check_spacing(h.spacing, path);
  h.geometry_known = true;  // INRIMAGE has no origin or direction: voxel (0,0,0) at the origin
  const double expected = static_cast<double>(h.dims[0]) * h.dims[1] * h.dims[2] * bits / 8;
  if (gzipped)
    check_compressed_size(path, path, 0, expected);
  else
    check_data_size(path, path, 256, expected, false);
  return h;
}

// ---- VTK XML image data -----------------------------------------------------------------------
std::string xml_attribute(const std::string& tag, const std::string& name) {
  const std::size_t p = tag.find(" " + name + "=\"");
  if (p == std::string::npos) return "";
  const std::size_t b = p + name.size() + 3;
  const std::size_t e = tag.find('"', b);
  return e == std::string::npos ? "" : tag.substr(b, e - b);
}

LabelImageHeader vti_header(const std::string& path) {
  const std::string text = head_of(path, 1 << 20, false);
  const std::size_t p = text.find("<ImageData");
  if (p == std::string::npos) throw Error(path + ": not a VTK image (no <ImageData> element; truncated file?)");
  const std::size_t e = text.find('>', p);
  if (e == std::string::npos) throw Error(path + ": the <ImageData> element has no end (truncated file?)");
  const std::string tag = text.substr(p, e - p);
  const auto values = [&](const char* name, std::size_t n) {
    std::vector<double> v;
    for (const auto& w : words(xml_attribute(tag, name))) v.push_back(number(w, path, name));
    if (v.size() != n) throw Error(path + ": <ImageData> " + name + " needs " + std::to_string(n) + " numbers");
    return v;
  };
  LabelImageHeader h;
  h.format = "vti";
  const std::vector<double> extent = values("WholeExtent", 6);
  std::vector<double> sizes;
  for (int a = 0; a < 3; ++a) sizes.push_back(extent[2 * a + 1] - extent[2 * a] + 1);
  h.dims = checked_dims(sizes, path);
  if (!xml_attribute(tag, "Spacing").empty()) {
    const auto s = values("Spacing", 3);
    h.spacing = Eigen::Vector3d(s[0], s[1], s[2]);
  }
  check_spacing(h.spacing, path);
  if (!xml_attribute(tag, "Origin").empty()) {
    const auto o = values("Origin", 3);
    h.origin = Eigen::Vector3d(o[0], o[1], o[2]);
  }
  check_origin(h.origin, path);
  if (!xml_attribute(tag, "Direction").empty()) {
    const auto d = values("Direction", 9);  // row-major, as vtkImageData's direction matrix
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) h.direction(r, c) = d[3 * r + c];
  }
  check_direction(h.direction, path);
  // Every count and binary array header against the file's size, as for .vtu (vtk_xml_check.h):
  // VTK 9.1's reader allocates what a compressed array's header claims (found by fuzz_vti).
  check_vtk_xml_sizes(path);
  // Whatever the encoding (raw, base64, zlib, ASCII), each voxel takes at least one byte before
  // compression: a file too small for that is truncated or lies about its extent.
  check_compressed_size(path, path, 0, static_cast<double>(h.dims[0]) * h.dims[1] * h.dims[2]);
  // The voxels' index frame starts at the extent's lower corner.
  h.origin += h.direction * Eigen::Vector3d(extent[0], extent[2], extent[4]).cwiseProduct(h.spacing);
  h.geometry_known = true;
  return h;
}

}  // namespace

std::string label_image_format(const std::string& path) {
  const std::string p = lower(path);
  if (ends_with(p, ".nrrd") || ends_with(p, ".nhdr")) return "nrrd";
  if (ends_with(p, ".nii") || ends_with(p, ".nii.gz")) return "nifti";
  if (ends_with(p, ".mha") || ends_with(p, ".mhd")) return "metaimage";
  if (ends_with(p, ".vti")) return "vti";
  if (ends_with(p, ".inr") || ends_with(p, ".inr.gz")) return "inr";
  throw Error(path + ": unknown label-map format (expected .nrrd, .nhdr, .nii, .nii.gz, .mha, .mhd, .vti, .inr or .inr.gz)");
}

LabelImageHeader read_label_image_header(const std::string& path) {
  const std::string format = label_image_format(path);
  require_readable(path);
  if (fs::is_directory(path)) throw Error(path + ": is a directory, not an image");
  const bool gz = ends_with(lower(path), ".gz");
  if (format == "nrrd") return nrrd_header(path);
  if (format == "metaimage") return metaimage_header(path);
  if (format == "nifti") return nifti_header(path, gz);
  if (format == "inr") return inr_header(path, gz);
  return vti_header(path);
}

}  // namespace xfem
