// SPDX-License-Identifier: MIT
#include "xfem/io/vtk_io_detail.h"

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLWriter.h>

#include <cctype>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <type_traits>

#include "xfem/core/atomic_file.h"
#include "xfem/core/cli.h"
#include "xfem/io/vtk_xml_check.h"

namespace xfem {
namespace vtk_io_detail {
namespace {

DataArray to_array(vtkDataArray* in) {
  DataArray out;
  const int type = in->GetDataType();
  const bool is_float = type == VTK_FLOAT || type == VTK_DOUBLE;
  const bool is_wide = type == VTK_LONG || type == VTK_LONG_LONG || type == VTK_ID_TYPE ||
                       type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG ||
                       type == VTK_UNSIGNED_INT;
  out.type = is_float ? DataArray::Type::Float64 : is_wide ? DataArray::Type::Int64 : DataArray::Type::Int32;
  out.components = in->GetNumberOfComponents();
  const vtkIdType n = in->GetNumberOfTuples();
  out.values.resize(static_cast<std::size_t>(n) * out.components);
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < out.components; ++c) out.values[i * out.components + c] = in->GetComponent(i, c);
  return out;
}

// Copies `in` into a new VTK array of type VtkArray; integer arrays must hold integers that fit,
// since a silent truncation would corrupt ids and flags.
template <class VtkArray>
Ptr<vtkDataArray> to_vtk_typed(const std::string& name, const DataArray& in, const std::string& where) {
  using T = typename VtkArray::ValueType;
  auto out = Ptr<VtkArray>::New();
  out->SetNumberOfComponents(in.components);
  out->SetNumberOfTuples(static_cast<vtkIdType>(in.tuples()));
  T* data = out->GetPointer(0);
  for (std::size_t i = 0; i < in.values.size(); ++i) {
    const double v = in.values[i];
    if constexpr (std::is_integral_v<T>) {
      if (!(v == std::floor(v) && v >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
            v <= static_cast<double>(std::numeric_limits<T>::max())))
        throw Error(where + " array '" + name + "': value " + short_number(v) + " at index " +
                    std::to_string(i) + " is not an integer of its type");
    }
    data[i] = static_cast<T>(v);
  }
  out->SetName(name.c_str());
  // Six components are a symmetric tensor in VTK's order (strain, stress): named, ParaView shows
  // xx .. xz instead of 0 .. 5 (docs/FORMATS.md).
  if (in.components == 6 && in.type == DataArray::Type::Float64) {
    static const char* kNames[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
    for (int c = 0; c < 6; ++c) out->SetComponentName(c, kNames[c]);
  }
  return out;
}

Ptr<vtkDataArray> to_vtk(const std::string& name, const DataArray& in, const std::string& where) {
  switch (in.type) {
    case DataArray::Type::Int32: return to_vtk_typed<vtkIntArray>(name, in, where);
    case DataArray::Type::Int64: return to_vtk_typed<vtkLongLongArray>(name, in, where);
    case DataArray::Type::Float64: break;
  }
  return to_vtk_typed<vtkDoubleArray>(name, in, where);
}

// `tuples` == npos: field data, any length.
void add_arrays(vtkFieldData* out, const DataArrays& arrays, std::size_t tuples, const char* where,
                const std::string& path) {
  for (const auto& [name, array] : arrays) {
    const std::string context = path + ": cannot write " + where;
    if (array.components < 1 || array.values.size() % array.components != 0)
      throw Error(context + " array '" + name + "': " + std::to_string(array.values.size()) +
                  " values do not make tuples of " + std::to_string(array.components) + " components");
    if (tuples != std::string::npos && array.tuples() != tuples)
      throw Error(context + " array '" + name + "': " + std::to_string(array.tuples()) + " tuples for " +
                  std::to_string(tuples) + " items");
    // A NaN or Inf in an output is never a result: refuse it, naming the quantity.
    for (std::size_t i = 0; i < array.values.size(); ++i)
      if (!std::isfinite(array.values[i]))
        throw Error(path + ": refusing to write a non-finite value (" + short_number(array.values[i]) + ") in " +
                    where + " array '" + name + "' at tuple " + std::to_string(i / array.components) +
                    " (overflow: are the inputs' magnitudes sane?)");
    out->AddArray(to_vtk(name, array, context));
  }
}

}  // namespace

std::string MessageCollector::clean(const char* text) {
  std::string m = text ? text : "";
  if (m.rfind("ERROR: In ", 0) == 0 || m.rfind("Warning: In ", 0) == 0) {
    const auto nl = m.find('\n');
    m = nl == std::string::npos ? std::string() : m.substr(nl + 1);
  }
  // The first line that says something: the rest is an object dump ("Debug: Off", "Modified Time").
  const auto start = m.find_first_not_of("\r\n");
  m = start == std::string::npos ? std::string() : m.substr(start, m.find_first_of("\r\n", start) - start);
  // "vtkXMLUnstructuredGridReader (0x5585...): " before the message, and "Algorithm
  // vtkXMLUnstructuredGridReader(0x5585...) returned failure" inside it: every address goes.
  std::string out;
  for (std::size_t i = 0; i < m.size();) {
    const bool paren = m.compare(i, 3, "(0x") == 0, bare = m.compare(i, 2, "0x") == 0;
    if (!paren && !bare) {
      out += m[i++];
      continue;
    }
    std::size_t end = i + (paren ? 3 : 2);
    while (end < m.size() && std::isxdigit(static_cast<unsigned char>(m[end]))) ++end;
    if (end - i < (paren ? 4u : 6u)) {  // "0x1" may be a value VTK quotes; addresses are long
      out += m[i++];
      continue;
    }
    if (paren && end < m.size() && m[end] == ')') ++end;
    while (!out.empty() && out.back() == ' ') out.pop_back();
    i = end;
  }
  // "<Class>: <message>" after the address went: the class names nothing the user knows.
  const auto colon = out.find(": ");
  if (colon != std::string::npos && out.rfind("vtk", 0) == 0 && out.find(' ') > colon) out = out.substr(colon + 2);
  return cli::printable_line(out, 200);
}

DataArrays to_arrays(vtkFieldData* in) {
  DataArrays out;
  if (!in) return out;
  for (int i = 0; i < in->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = in->GetArray(i);  // null for string arrays, which carry nothing we use
    if (a && a->GetName()) out[a->GetName()] = to_array(a);
  }
  return out;
}

Points to_points(vtkPoints* in) {
  Points out(in ? in->GetNumberOfPoints() : 0, 3);
  for (Eigen::Index i = 0; i < out.rows(); ++i) {
    double p[3];
    in->GetPoint(i, p);
    out.row(i) << p[0], p[1], p[2];
  }
  return out;
}

Ptr<vtkPoints> to_vtk(const Points& in, const std::string& name) {
  for (Eigen::Index i = 0; i < in.rows(); ++i)
    if (!in.row(i).allFinite())
      throw Error(name + ": refusing to write point " + std::to_string(i) + ": a coordinate is not finite");
  auto out = Ptr<vtkPoints>::New();
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(in.rows());
  for (Eigen::Index i = 0; i < in.rows(); ++i) out->SetPoint(i, in(i, 0), in(i, 1), in(i, 2));
  return out;
}

std::string cell_type_name(int type) {
  const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
  return std::string(name ? name : "unknown cell") + " (VTK type " + std::to_string(type) + ")";
}

// Name used in messages for "-" (standard input/output).
std::string display_name(const std::string& path) { return path == "-" ? std::string("<stdin>") : path; }

std::string read_stdin() {
  std::ostringstream data;
  data << std::cin.rdbuf();
  return data.str();
}

Ptr<vtkUnstructuredGrid> read_unstructured_grid(const std::string& path, const VtkMessages& messages) {
  const char* what = "tetrahedral mesh";
  if (path == "-") {  // standard input carries VTK XML
    auto reader = Ptr<vtkXMLUnstructuredGridReader>::New();
    reader->ReadFromInputStringOn();
    const std::string text = read_stdin();
    check_vtk_xml_text(display_name(path), text);
    reader->SetInputString(text);
    update_or_throw(reader.Get(), messages, display_name(path), what);
    return reader->GetOutput();
  }
  require_readable(path);
  const std::string ext = extension_of(path);
  if (ext == ".vtu") {
    auto reader = Ptr<vtkXMLUnstructuredGridReader>::New();
    if (!reader->CanReadFile(path.c_str()))
      throw Error(path + ": not a VTK XML unstructured grid (.vtu) file");
    check_vtk_xml_sizes(path);
    reader->SetFileName(path.c_str());
    update_or_throw(reader.Get(), messages, path, what);
    return reader->GetOutput();
  }
  if (ext == ".vtk") {
    check_legacy_sections(path);
    auto reader = Ptr<vtkDataSetReader>::New();
    reader->SetFileName(path.c_str());
    configure_legacy(reader.Get());
    update_or_throw(reader.Get(), messages, path, what);
    auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput());
    if (!grid) throw Error(path + ": not a legacy VTK UNSTRUCTURED_GRID file");
    return grid;
  }
  throw Error(path + ": unknown extension '" + ext + "' for a " + what + " (expected .vtu or .vtk)");
}

namespace {

// Writes `data` with `writer` (appended raw binary, zlib unless told otherwise) to `target`: a
// file, or stdout for "-".
void write_xml(vtkXMLWriter* writer, vtkDataObject* data, const std::string& target, const std::string& path,
               const VtkMessages& messages, Compression compression) {
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  if (compression == Compression::ZLib) {
    writer->SetCompressorTypeToZLib();
    // Level 1: on the 466,560-tet beam it writes about 1.5x faster than VTK's default level 5 for a
    // 6% larger file, and 40x faster than level 9 (docs/PERFORMANCE.md, "I/O").
    writer->SetCompressionLevel(1);
  } else if (compression == Compression::LZ4) {
    writer->SetCompressorTypeToLZ4();
    writer->SetCompressionLevel(1);  // LZ4's fastest (VTK maps level 1 to the largest acceleration)
  } else {
    writer->SetCompressorTypeToNone();
  }
  writer->SetHeaderTypeToUInt64();
  if (target == "-") {
    writer->WriteToOutputStringOn();
  } else {
    writer->SetFileName(target.c_str());
  }
  const int ok = writer->Write();
  messages.throw_if_error(path + ": cannot write");
  if (ok != 1) throw Error(path + ": cannot write (disk full or no permission?)");
  if (target == "-") {
    const std::string out = writer->GetOutputString();
    std::cout.write(out.data(), static_cast<std::streamsize>(out.size()));
    std::cout.flush();
    if (!std::cout) throw Error("<stdout>: cannot write");
  }
}

}  // namespace

void write_vtk_xml(vtkXMLWriter* writer, vtkDataSet* data, const DataArrays& point_data, const DataArrays& cell_data,
                   const DataArrays* field_data, const std::string& path, const std::string& name,
                   Compression compression) {
  VtkMessages messages;
  add_arrays(data->GetPointData(), point_data, static_cast<std::size_t>(data->GetNumberOfPoints()), "point", name);
  add_arrays(data->GetCellData(), cell_data, static_cast<std::size_t>(data->GetNumberOfCells()), "cell", name);
  if (field_data) add_arrays(data->GetFieldData(), *field_data, std::string::npos, "field", name);
  write_atomically(path, [&](const std::string& tmp) { write_xml(writer, data, tmp, name, messages, compression); });
}

}  // namespace vtk_io_detail

Compression compression_named(const std::string& name) {
  if (name == "zlib") return Compression::ZLib;
  if (name == "lz4") return Compression::LZ4;
  if (name == "none") return Compression::None;
  throw Error("unknown compression '" + name + "' (expected zlib, lz4 or none)");
}

}  // namespace xfem
