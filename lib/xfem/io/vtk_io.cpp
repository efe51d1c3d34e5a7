// SPDX-License-Identifier: MIT
#include "xfem/io/vtk_io.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLogger.h>
#include <vtkLongLongArray.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <type_traits>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <queue>

#include "xfem/core/atomic_file.h"
#include "xfem/core/boundary_groups.h"
#include "xfem/io/vtk_xml_check.h"
#include "xfem/core/error.h"
#include "xfem/io/gmsh_io.h"

namespace xfem {
namespace {

template <class T>
using Ptr = vtkSmartPointer<T>;

// VTK reports problems through vtkOutputWindow (which prints on stderr) and carries on. While a
// VtkMessages guard lives, that window is replaced by this collector, so a tool prints exactly
// one error line of its own and the first error VTK raised becomes an xfem::Error.
class MessageCollector : public vtkOutputWindow {
 public:
  static MessageCollector* New() {
    auto* window = new MessageCollector;
    window->InitializeObjectBase();
    return window;
  }
  void DisplayErrorText(const char* text) override { errors.push_back(clean(text)); }
  void DisplayWarningText(const char* text) override { warnings.push_back(clean(text)); }
  void DisplayGenericWarningText(const char* text) override { warnings.push_back(clean(text)); }
  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  std::vector<std::string> errors, warnings;

 private:
  // VTK formats "ERROR: In <source file>, line <n>\n<Class> (0x<address>): <message>\n\n".
  // Keep <message>: the source location means nothing to a user and the address changes
  // from run to run, which would make error texts non-deterministic.
  static std::string clean(const char* text) {
    std::string m = text ? text : "";
    if (m.rfind("ERROR: In ", 0) == 0 || m.rfind("Warning: In ", 0) == 0) {
      const auto nl = m.find('\n');
      m = nl == std::string::npos ? std::string() : m.substr(nl + 1);
    }
    const auto address = m.find(" (0x");
    const auto colon = m.find("): ", address == std::string::npos ? 0 : address);
    if (address != std::string::npos && colon != std::string::npos && m.find(' ') == address)
      m = m.substr(colon + 3);
    // One printable line: VTK quotes the offending input, which may be binary garbage.
    for (char& c : m)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = c == '\n' ? ' ' : '?';
    while (!m.empty() && m.back() == ' ') m.pop_back();
    if (m.size() > 200) m = m.substr(0, 200) + "...";
    return m;
  }
};

// Routes VTK's messages to a MessageCollector for the guard's lifetime and restores the previous
// output window afterwards. The output window is process-wide, so guards are serialised.
class VtkMessages {
 public:
  VtkMessages() : lock_(mutex()) {
    previous_ = vtkOutputWindow::GetInstance();
    collector_ = Ptr<MessageCollector>::New();
    vtkOutputWindow::SetInstance(collector_);
    display_ = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOn();  // off would also suppress the messages we need
    // VTK's logger prints errors on stderr itself, besides handing them to the output window.
    // With no log files or callbacks registered its cutoff is the stderr verbosity.
    logger_ = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~VtkMessages() {
    vtkLogger::SetStderrVerbosity(logger_);
    vtkObject::SetGlobalWarningDisplay(display_);
    vtkOutputWindow::SetInstance(previous_);
  }
  VtkMessages(const VtkMessages&) = delete;
  VtkMessages& operator=(const VtkMessages&) = delete;

  /// Throws "<context>: <first VTK error>" if VTK reported an error since the guard was made.
  void throw_if_error(const std::string& context) const {
    if (!collector_->errors.empty()) throw Error(context + ": " + collector_->errors.front());
  }
  const std::vector<std::string>& warnings() const { return collector_->warnings; }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  Ptr<vtkOutputWindow> previous_;
  Ptr<MessageCollector> collector_;
  int display_ = 1;
  vtkLogger::Verbosity logger_ = vtkLogger::VERBOSITY_INFO;
};

template <class Algorithm>
void update_or_throw(Algorithm* algorithm, const VtkMessages& messages, const std::string& path,
                     const char* what) {
  try {
    algorithm->Update();
  } catch (const std::bad_alloc&) {
    // A corrupt size (e.g. a compressed block header of a .vtu) makes VTK allocate for it.
    throw Error(path + ": cannot read " + what + ": a size in the file is too large to allocate (corrupt file?)");
  } catch (const std::length_error&) {
    throw Error(path + ": cannot read " + what + ": a size in the file is too large to allocate (corrupt file?)");
  }
  messages.throw_if_error(path + ": cannot read " + what);
}

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

DataArrays to_arrays(vtkFieldData* in) {
  DataArrays out;
  if (!in) return out;
  for (int i = 0; i < in->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = in->GetArray(i);  // null for string arrays, which carry nothing we use
    if (a && a->GetName()) out[a->GetName()] = to_array(a);
  }
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
        throw Error(where + " array '" + name + "': value " + std::to_string(v) + " at index " +
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

// Copies the point ids of cell `i` (of `expected` points, VTK type `type_id`) into `row`,
// checking that the cell is of that type and its ids are in range.
template <class Row>
void copy_cell(int type, vtkIdType npts, const vtkIdType* ids, vtkIdType i, int type_id, const char* kind,
               vtkIdType np, const std::string& name, Row&& row) {
  const int expected = static_cast<int>(row.size());
  if (type != type_id)
    throw Error(name + ": cell " + std::to_string(i) + " is a " + cell_type_name(type) + ", expected " + kind +
                " only (VTK type " + std::to_string(type_id) + ")");
  if (npts != expected)
    throw Error(name + ": cell " + std::to_string(i) + " has " + std::to_string(npts) + " points, a " +
                cell_type_name(type) + " has " + std::to_string(expected));
  for (int k = 0; k < expected; ++k) {
    if (ids[k] < 0 || ids[k] >= np)
      throw Error(name + ": cell " + std::to_string(i) + " uses point " + std::to_string(ids[k]) +
                  ", out of range [0, " + std::to_string(np) + ")");
    row[k] = static_cast<int>(ids[k]);
  }
}

// VTK 9.1's legacy reader fills a POINTS section that ends early with invented points, reads a
// huge count as an allocation, and crashes (null stream) on a cell section shorter than its
// header says. So each section header is checked against what the file holds before VTK sees it:
// POINTS n (3n numbers), CELLS / POLYGONS / LINES / VERTICES / TRIANGLE_STRIPS n size (size
// numbers, size >= 2n... at least one id per cell), CELL_TYPES n (n numbers).
void check_legacy_sections(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t binary_at = text.find("\nBINARY");
  const char* end = text.data() + text.size();
  // Point ids are checked against the POINTS count: VTK's legacy reader, which is not built with
  // the sanitizers, writes out of bounds for an id beyond the points (found by fuzzing).
  long long point_count = -1;
  const auto check_id = [&](double id, long long cell) {  // cell: 1-based count of the section's cells
    if (!(id >= 0 && id == std::floor(id) && (point_count < 0 || id < static_cast<double>(point_count))))
      throw Error(path + ": cell " + std::to_string(cell - 1) + " uses point " + short_number(id) + ", out of range [0, " +
                  std::to_string(std::max(point_count, 0LL)) + ")");
  };
  // VTK's legacy reader trusts what it parses (it is not built with the sanitizers, and it wrote
  // past its arrays or followed null pointers on the files fuzzing made of ours): an ASCII file
  // must be text, and a line starting with a keyword's letters must be that keyword.
  if (text.compare(0, 14, "# vtk DataFile") != 0) return;  // not legacy VTK: VTK's reader says so
  if (binary_at == std::string::npos)
    for (std::size_t i = 0; i < text.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      // Lines are what this check reads and whitespace what VTK reads: a vertical tab, a form feed
      // or a lone carriage return would let a keyword hide inside a line.
      const bool lone_cr = c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n');
      if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c >= 0x7f || lone_cr)
        throw Error(path + ": byte " + std::to_string(i) + " is not text, in an ASCII legacy VTK file");
    }
  static const char* const kKeywords[] = {"points", "cells", "cell_types", "polygons", "lines", "vertices",
                                          "triangle_strips", "point_data", "cell_data", "field", "scalars",
                                          "vectors", "normals", "tensors", "lookup_table", "color_scalars",
                                          "texture_coordinates", "global_ids", "pedigree_ids", "metadata", "dataset",
                                          "offsets", "connectivity"};
  std::size_t line_start = 0;
  for (int line = 0; line_start < text.size(); ++line) {
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    // Data lines start with a digit or a sign; line 1 is the title (free text).
    if (line == 1 || !std::isalpha(static_cast<unsigned char>(text[line_start]))) {
      line_start = line_end + 1;
      continue;
    }
    const std::string head = text.substr(line_start, std::min<std::size_t>(line_end - line_start, 200));
    std::istringstream header(head);
    std::string keyword;
    header >> keyword;
    std::string lower = keyword;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // VTK compares only a keyword's first letters: "CELLS2 10" is CELLS, and "10" and the next
    // line's count became its counts.
    for (const char* k : kKeywords)
      if (lower.compare(0, std::strlen(k), k) == 0 && lower != k)
        throw Error(path + ": unknown keyword '" + keyword.substr(0, 40) + "' in the legacy VTK file (did you mean '" +
                    std::string(k) + "'?)");
    const bool points = lower == "points", types = lower == "cell_types";
    const bool cells = lower == "cells" || lower == "polygons" || lower == "lines" || lower == "vertices" ||
                       lower == "triangle_strips";
    std::vector<std::string> words;
    for (std::string w; header >> w;) words.push_back(w);
    for (std::string w : words) {  // one keyword per line: VTK would take one that follows
      for (char& c : w) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      for (const char* k : {"points", "cells", "cell_types", "polygons", "lines", "vertices", "triangle_strips",
                            "point_data", "cell_data"})
        if (w.compare(0, std::strlen(k), k) == 0)
          throw Error(path + ": a second keyword in the line of " + keyword + " in the legacy VTK file");
    }
    if (points && words.size() == 2) {
      static const char* const kTypes[] = {"bit", "unsigned_char", "char", "unsigned_short", "short", "unsigned_int",
                                           "int", "unsigned_long", "long", "float", "double", "vtkidtype",
                                           "vtktypeint64", "vtktypeuint64"};
      std::string t = words[1];
      for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; }))
        throw Error(path + ": POINTS of unknown type '" + words[1].substr(0, 20) + "' in the legacy VTK file");
    }
    if (points || types || cells) {
      // The counts as whole numbers, nothing after them but the points' type.
      const std::size_t counts = cells ? 2 : 1;
      bool ok = words.size() == counts + (points ? 1 : 0);
      for (std::size_t i = 0; ok && i < counts; ++i)
        ok = !words[i].empty() && words[i].size() <= 18 &&
             std::all_of(words[i].begin(), words[i].end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!ok) throw Error(path + ": malformed " + keyword + " line in the legacy VTK file");
      const long long n = std::stoll(words[0]), size = cells ? std::stoll(words[1]) : -1;
      const std::string type = points ? words[1] : std::string();
      if (n > static_cast<long long>(text.size()) || size > static_cast<long long>(text.size()))
        throw Error(path + ": " + keyword + " claims " + std::to_string(n) + " items, more than the file can hold");
      const std::size_t data = std::min(line_end + 1, text.size());
      const bool new_cells = cells && text.compare(data, 7, "OFFSETS") == 0 &&  // VTK 5.1 layout
                             text.compare(0, 24, "# vtk DataFile Version 5") == 0;
      if (cells && !new_cells && size < 2 * n)
        throw Error(path + ": " + keyword + " " + std::to_string(n) + " " + std::to_string(size) +
                    ": too few values for that many cells");
      const long long want = points ? 3 * n : cells ? size : n;
      const long long left = static_cast<long long>(text.size() - data);
      if (points) point_count = n;
      if (binary_at != std::string::npos && binary_at < line_start) {
        const long long bytes = points ? (type == "double" ? 8 : 4) : 4;
        if (!new_cells && want > left / bytes)
          throw Error(path + ": " + keyword + " claims " + std::to_string(n) + " items but the file holds fewer");
        if (cells && !new_cells) {  // big-endian int32: each cell "k id_1 .. id_k"
          const auto value = [&](long long i) {
            const unsigned char* b = reinterpret_cast<const unsigned char*>(text.data() + data + 4 * i);
            return static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                             (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
          };
          long long i = 0, cell = 0;
          while (i < want) {
            const std::int32_t k = value(i);
            if (k < 1 || k > 1000 || ++cell > n || i + 1 + k > want)
              throw Error(path + ": " + keyword + " section: cell " + std::to_string(cell) +
                          " has an impossible point count or there are more cells than " + std::to_string(n));
            for (std::int32_t j = 1; j <= k; ++j) check_id(value(i + j), cell);
            i += 1 + k;
          }
        }
      } else if (!new_cells) {
        long long numbers = 0;  // ASCII: count the numbers up to the next keyword
        long long next_cell = 0, cells_seen = 0;  // cell sections: each cell is "k id_1 .. id_k"
        const char* p = text.data() + data;
        while (p < end && numbers < want) {
          while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
          if (p == end || std::isalpha(static_cast<unsigned char>(*p))) break;
          const char* token = p;
          while (p < end && !std::isspace(static_cast<unsigned char>(*p))) ++p;
          const std::string word(token, std::min<std::size_t>(p - token, 40));
          char* stop = nullptr;
          std::strtod(word.c_str(), &stop);
          if (stop != word.c_str() + word.size()) {
            std::string shown(token, std::min<std::size_t>(p - token, 20));
            for (char& c : shown)  // one printable line
              if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
            throw Error(path + ": " + keyword + " section: '" + shown + "' is not a number");
          }
          if ((cells || types) && !std::all_of(word.begin(), word.end(), [](char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+'; })) {
            std::string shown = word.substr(0, 20);
            throw Error(path + ": " + keyword + " section: '" + shown + "' is not a whole number");
          }
          if (cells && numbers == next_cell) {  // a cell's point count
            const double k = std::strtod(word.c_str(), nullptr);
            if (!(k >= 1 && k <= 1000) || ++cells_seen > n)
              throw Error(path + ": " + keyword + " section: cell " + std::to_string(cells_seen) +
                          " has an impossible point count or there are more cells than " + std::to_string(n));
            next_cell = numbers + 1 + static_cast<long long>(k);
          } else if (cells) {
            check_id(std::strtod(word.c_str(), nullptr), cells_seen);
          }
          ++numbers;
        }
        if (cells && numbers == want && (next_cell != want || cells_seen != n))
          throw Error(path + ": " + keyword + " " + std::to_string(n) + " " + std::to_string(size) +
                      ": the cells' point counts do not add up to the section's size");
        if (numbers < want)
          throw Error(path + ": " + keyword + " claims " + std::to_string(n) +
                      (points ? " points but only " : " items but only ") + std::to_string(numbers) +
                      (points ? " coordinates" : " values") + " follow (" + std::to_string(want) + " expected)");
      }
    }
    line_start = line_end + 1;
  }
}

template <class Reader>
void configure_legacy(Reader* reader) {
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
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

// Writes `data` with `writer` (appended raw binary, zlib unless told otherwise) to `target`: a
// file, or stdout for "-".
void write_xml(vtkXMLWriter* writer, vtkDataObject* data, const std::string& target, const std::string& path,
               const VtkMessages& messages, Compression compression = Compression::ZLib) {
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

// Cells a mesher writes beside the tets of a volume mesh: its geometry points, edges and
// boundary triangles. Other cell types stay errors (copy_cell names them).
bool is_lower_dimensional(int type) {
  return type == VTK_VERTEX || type == VTK_POLY_VERTEX || type == VTK_LINE || type == VTK_POLY_LINE ||
         type == VTK_TRIANGLE;
}

// The cell array naming the boundary group of each triangle: "group", or meshio's
// "gmsh:physical" (a gmsh mesh converted by meshio). Null when there is none.
const DataArray* triangle_groups(const DataArrays& cell_data) {
  for (const char* name : {"group", "gmsh:physical"}) {
    const auto it = cell_data.find(name);
    if (it != cell_data.end() && it->second.components == 1) return &it->second;
  }
  return nullptr;
}

// A mixed-cell grid (gmsh's VTK export, meshio's conversion): tets are the body, triangles
// join the group their "group" cell value names, vertices and lines carry nothing.
TetMesh read_mixed_grid(vtkUnstructuredGrid* grid, const std::string& name, std::vector<std::string>* warnings) {
  MixedMesh mixed;
  mixed.points = to_points(grid->GetPoints());
  mixed.point_data = to_arrays(grid->GetPointData());
  mixed.cell_data = to_arrays(grid->GetCellData());
  mixed.field_data = to_arrays(grid->GetFieldData());
  const DataArray* group = triangle_groups(mixed.cell_data);
  const vtkIdType nc = grid->GetNumberOfCells(), np = grid->GetNumberOfPoints();
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCells()->GetCellAtId(i, npts, ids);
    const int type = grid->GetCellType(i);
    if (type == VTK_TRIANGLE && group) {
      std::array<int, 3> triangle;
      copy_cell(type, npts, ids, i, VTK_TRIANGLE, "triangles", np, name, triangle);
      const double g = (*group)(static_cast<std::size_t>(i));
      if (!(g == std::floor(g) && std::abs(g) < 1e9))
        throw Error(name + ": cell " + std::to_string(i) + " has group " + std::to_string(g) + ", not an integer");
      auto& members = mixed.groups[std::to_string(static_cast<long>(g))];
      members.insert(members.end(), triangle.begin(), triangle.end());
    } else if (!is_lower_dimensional(type)) {
      std::array<int, 4> tet;
      copy_cell(type, npts, ids, i, VTK_TETRA, "tetrahedra, triangles, lines or vertices", np, name, tet);
      mixed.tets.push_back(tet);
      mixed.tet_cells.push_back(static_cast<long>(i));
    }
  }
  // The group's value is now a point set: its cell array would mean nothing on the tets.
  if (group) mixed.cell_data.erase(mixed.cell_data.count("group") ? "group" : "gmsh:physical");
  TetMesh mesh = body_of(mixed, name);
  validate_tet_mesh(mesh, name, warnings);
  return mesh;
}

bool has_lower_dimensional_cells(vtkUnstructuredGrid* grid) {
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
    if (is_lower_dimensional(grid->GetCellType(i))) return true;
  return false;
}

}  // namespace

int validate_tet_mesh(TetMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows(), nt = mesh.tets.rows();
  if (np == 0 || nt == 0) throw Error(name + ": empty mesh (" + std::to_string(np) + " points, " +
                                      std::to_string(nt) + " tetrahedra)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k)
      if (mesh.tets(t, k) < 0 || mesh.tets(t, k) >= np)
        throw Error(name + ": tetrahedron " + std::to_string(t) + " uses point " +
                    std::to_string(mesh.tets(t, k)) + ", out of range [0, " + std::to_string(np) + ")");
  // Zero volume is judged relative to the tet's own longest edge, so the test is scale-free.
  long degenerate = 0, inverted = 0, first_degenerate = -1, first_inverted = -1;
  for (Eigen::Index t = 0; t < nt; ++t) {
    const auto& c = mesh.tets.row(t);
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        longest = std::max(longest, (mesh.points.row(c[a]) - mesh.points.row(c[b])).squaredNorm());
    const double v6 = 6.0 * signed_volume(mesh, static_cast<int>(t));
    if (std::abs(v6) <= 1e-12 * std::pow(longest, 1.5)) {
      if (degenerate++ == 0) first_degenerate = t;
    } else if (v6 < 0) {
      if (inverted++ == 0) first_inverted = t;
      std::swap(mesh.tets(t, 1), mesh.tets(t, 2));
    }
  }
  if (degenerate)
    throw Error(name + ": " + std::to_string(degenerate) + " tetrahedra have zero volume (first: tetrahedron " +
                std::to_string(first_degenerate) + ")");
  if (inverted && warnings)
    warnings->push_back(name + ": " + std::to_string(inverted) +
                        " inverted tetrahedra reoriented (first: tetrahedron " + std::to_string(first_inverted) + ")");
  return static_cast<int>(inverted);
}

TetMesh read_tet_mesh(const std::string& path, std::vector<std::string>* warnings) {
  if (path != "-" && extension_of(path) == ".msh") return read_gmsh_tet_mesh(path, warnings);
  const std::string name = display_name(path);
  TetMesh mesh;
  {
    VtkMessages messages;
    auto grid = read_unstructured_grid(path, messages);
    if (has_lower_dimensional_cells(grid)) return read_mixed_grid(grid, name, warnings);
    mesh.points = to_points(grid->GetPoints());
    const vtkIdType nc = grid->GetNumberOfCells();
    const vtkIdType np = grid->GetNumberOfPoints();
    mesh.tets.resize(nc, 4);
    vtkCellArray* cells = grid->GetCells();
    for (vtkIdType i = 0; i < nc; ++i) {
      vtkIdType npts;
      const vtkIdType* ids;
      cells->GetCellAtId(i, npts, ids);
      copy_cell(grid->GetCellType(i), npts, ids, i, VTK_TETRA, "tetrahedra", np, name, mesh.tets.row(i));
    }
    mesh.point_data = to_arrays(grid->GetPointData());
    mesh.cell_data = to_arrays(grid->GetCellData());
    mesh.field_data = to_arrays(grid->GetFieldData());
  }
  validate_tet_mesh(mesh, name, warnings);
  return mesh;
}

namespace {
// Cells of one kind, a row of point ids each (tets or triangles), as a VTK cell array.
template <class Cells>
Ptr<vtkCellArray> cell_array(const Cells& cells) {
  const Eigen::Index n = cells.rows(), k = cells.cols();
  auto offsets = Ptr<vtkIdTypeArray>::New();
  auto connectivity = Ptr<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n * k);
  for (Eigen::Index c = 0; c <= n; ++c) offsets->SetValue(c, k * c);
  for (Eigen::Index c = 0; c < n; ++c)
    for (Eigen::Index j = 0; j < k; ++j) connectivity->SetValue(k * c + j, cells(c, j));
  auto out = Ptr<vtkCellArray>::New();
  out->SetData(offsets, connectivity);
  return out;
}
}  // namespace

Compression compression_named(const std::string& name) {
  if (name == "zlib") return Compression::ZLib;
  if (name == "lz4") return Compression::LZ4;
  if (name == "none") return Compression::None;
  throw Error("unknown compression '" + name + "' (expected zlib, lz4 or none)");
}

void write_tet_mesh(const TetMesh& mesh, const std::string& path, Compression compression) {
  if (path != "-" && extension_of(path) != ".vtu")
    throw Error(path + ": volume meshes are written as .vtu, not '" + extension_of(path) + "'");
  const std::string name = path == "-" ? std::string("<stdout>") : path;
  VtkMessages messages;
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(to_vtk(mesh.points, name));
  grid->SetCells(VTK_TETRA, cell_array(mesh.tets));
  add_arrays(grid->GetPointData(), mesh.point_data, mesh.points.rows(), "point", name);
  add_arrays(grid->GetCellData(), mesh.cell_data, mesh.tets.rows(), "cell", name);
  add_arrays(grid->GetFieldData(), mesh.field_data, std::string::npos, "field", name);
  write_atomically(path, [&](const std::string& tmp) {
    write_xml(Ptr<vtkXMLUnstructuredGridWriter>::New(), grid, tmp, name, messages, compression);
  });
}

namespace {

// OFF and OBJ through CGAL, in double precision (VTK's OBJ reader stores float: a cut through mesh
// nodes would move by 1e-8 and miss them).
TriangleMesh read_off(const std::string& path, bool obj = false) {
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::ifstream in(path);
  if (!obj) {  // OFF: the counts in the header, checked against the file size before CGAL allocates.
    std::vector<std::string> words;  // the first words, comments left out
    std::string line, word;
    while (words.size() < 3 && std::getline(in, line)) {
      std::istringstream split(line.substr(0, line.find('#')));
      while (words.size() < 3 && split >> word) words.push_back(word);
    }
    if (!words.empty() && words[0].find("OFF") != std::string::npos) words.erase(words.begin());
    long long nv = -1, nf = -1;
    if (words.size() >= 2) {
      std::istringstream(words[0]) >> nv;
      std::istringstream(words[1]) >> nf;
    }
    in.clear();
    in.seekg(0, std::ios::end);
    const long long size = static_cast<long long>(in.tellg());
    if (nv < 0 || nf < 0) throw Error(path + ": not a readable OFF file (no vertex and face counts)");
    if (nv > size / 6 + 1 || nf > size / 8 + 1)
      throw Error(path + ": the OFF header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                  " faces, more than the " + std::to_string(size) + " bytes of the file can hold");
    in.seekg(0);
  }
  // verbose(false): CGAL would otherwise explain its failure on std::cerr.
  if (!(obj ? CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false))
            : CGAL::IO::read_OFF(in, points, polygons, CGAL::parameters::verbose(false))))
    throw Error(path + (obj ? ": not a readable OBJ file" : ": not a readable OFF file"));
  TriangleMesh mesh;
  mesh.points.resize(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    mesh.points.row(i) << points[i].x(), points[i].y(), points[i].z();
  mesh.triangles.resize(polygons.size(), 3);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() != 3)
      throw Error(path + ": face " + std::to_string(f) + " has " + std::to_string(polygons[f].size()) +
                  " vertices, expected triangles only");
    // CGAL has checked the indices: a face naming a missing vertex makes read_OFF fail.
    for (int k = 0; k < 3; ++k) mesh.triangles(f, k) = static_cast<int>(polygons[f][k]);
  }
  return mesh;
}

// Binary STL has no signature, and VTK reads any bytes as one: check that the file is exactly
// the 80-byte header, the triangle count and 50 bytes per triangle, unless it is ASCII ("solid").
void check_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char header[84] = {};
  in.read(header, sizeof header);
  const std::streamsize got = in.gcount();
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  if (got == 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(header + 80);
    const std::uint64_t n = b[0] | b[1] << 8 | b[2] << 16 | static_cast<std::uint64_t>(b[3]) << 24;
    if (size == 84 + 50 * n) return;  // binary (even if its header happens to start with "solid")
  }
  std::size_t i = 0;
  while (i < static_cast<std::size_t>(got) && std::isspace(static_cast<unsigned char>(header[i]))) ++i;
  if (std::string(header + i, std::min<std::size_t>(5, got - i)) != "solid")
    throw Error(path + ": not an STL file (neither ASCII 'solid ...' nor binary with a matching triangle count)");
  // ASCII. VTK takes a file with a byte above 127 near its start for binary whatever its first
  // word, and then allocates the triangle count of bytes 80-83: refuse any byte ASCII lacks.
  in.clear();
  in.seekg(0);
  char chunk[65536];
  std::uint64_t at = 0;
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    for (std::streamsize k = 0; k < in.gcount(); ++k)
      if (static_cast<unsigned char>(chunk[k]) > 127)
        throw Error(path + ": byte " + std::to_string(at + static_cast<std::uint64_t>(k)) +
                    " is not ASCII in an ASCII STL file ('solid ...'), and the size does not fit a binary one");
    at += static_cast<std::uint64_t>(in.gcount());
  }
}

TriangleMesh from_polydata(vtkPolyData* poly, const std::string& name) {
  TriangleMesh mesh;
  mesh.points = to_points(poly->GetPoints());
  const vtkIdType np = poly->GetNumberOfPoints();
  // The polygons read straight from their cell array: vtkPolyData's cell map (GetCellType) is
  // built from all four arrays and was a null pointer on a damaged file (found by fuzzing).
  vtkCellArray* polys = poly->GetPolys();
  const vtkIdType nc = polys ? polys->GetNumberOfCells() : 0;
  mesh.triangles.resize(std::max<vtkIdType>(nc, 1), 3);  // row 0 for the error below
  // Cells are numbered vertices first, then lines, polygons, strips: the first that is no polygon.
  const vtkIdType verts = poly->GetNumberOfVerts(), lines = poly->GetNumberOfLines();
  if (verts > 0 || lines > 0 || poly->GetNumberOfStrips() > 0)
    copy_cell(verts > 0 ? VTK_VERTEX : lines > 0 ? VTK_LINE : VTK_TRIANGLE_STRIP, 0, nullptr, verts + lines > 0 ? 0 : nc,
              VTK_TRIANGLE, "triangles", np, name, mesh.triangles.row(0));
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    polys->GetCellAtId(i, npts, ids);
    copy_cell(npts == 3 ? VTK_TRIANGLE : VTK_POLYGON, npts, ids, i, VTK_TRIANGLE, "triangles", np, name,
              mesh.triangles.row(i));
  }
  mesh.triangles.conservativeResize(nc, 3);
  mesh.point_data = to_arrays(poly->GetPointData());
  mesh.cell_data = to_arrays(poly->GetCellData());
  return mesh;
}

TriangleMesh from_grid(vtkUnstructuredGrid* grid, const std::string& name) {
  TriangleMesh mesh;
  mesh.points = to_points(grid->GetPoints());
  const vtkIdType nc = grid->GetNumberOfCells();
  const vtkIdType np = grid->GetNumberOfPoints();
  mesh.triangles.resize(nc, 3);
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCells()->GetCellAtId(i, npts, ids);
    copy_cell(grid->GetCellType(i), npts, ids, i, VTK_TRIANGLE, "triangles", np, name, mesh.triangles.row(i));
  }
  mesh.point_data = to_arrays(grid->GetPointData());
  mesh.cell_data = to_arrays(grid->GetCellData());
  return mesh;
}

// Keeps the rows of every cell array whose triangle survives.
void keep_cells(DataArrays& arrays, const std::vector<int>& kept) {
  for (auto& [name, a] : arrays) {
    std::vector<double> values;
    values.reserve(kept.size() * a.components);
    for (int f : kept)
      for (int c = 0; c < a.components; ++c) values.push_back(a(f, c));
    a.values = std::move(values);
  }
}

// A surface as a VTK XML unstructured grid of triangles: for readers that take no .vtp (meshio).
void write_triangle_grid(const TriangleMesh& mesh, const std::string& path, Compression compression) {
  VtkMessages messages;
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(to_vtk(mesh.points, path));
  grid->SetCells(VTK_TRIANGLE, cell_array(mesh.triangles));
  add_arrays(grid->GetPointData(), mesh.point_data, mesh.points.rows(), "point", path);
  add_arrays(grid->GetCellData(), mesh.cell_data, mesh.triangles.rows(), "cell", path);
  write_atomically(path, [&](const std::string& tmp) {
    write_xml(Ptr<vtkXMLUnstructuredGridWriter>::New(), grid, tmp, path, messages, compression);
  });
}

}  // namespace

void validate_triangle_mesh(TriangleMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows();
  if (np == 0 || mesh.triangles.rows() == 0)
    throw Error(name + ": empty surface (" + std::to_string(np) + " points, " +
                std::to_string(mesh.triangles.rows()) + " triangles)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<int> kept;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) < 0 || mesh.triangles(f, k) >= np)
        throw Error(name + ": triangle " + std::to_string(f) + " uses point " +
                    std::to_string(mesh.triangles(f, k)) + ", out of range [0, " + std::to_string(np) + ")");
    const Eigen::Vector3d a = mesh.points.row(mesh.triangles(f, 0)), b = mesh.points.row(mesh.triangles(f, 1)),
                          c = mesh.points.row(mesh.triangles(f, 2));
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() > 1e-12 * longest) kept.push_back(static_cast<int>(f));
  }
  if (kept.empty()) throw Error(name + ": every triangle has zero area");
  if (kept.size() != static_cast<std::size_t>(mesh.triangles.rows())) {
    if (warnings)
      warnings->push_back(name + ": " + std::to_string(mesh.triangles.rows() - kept.size()) +
                          " zero-area triangles dropped");
    Triangles t(kept.size(), 3);
    for (std::size_t i = 0; i < kept.size(); ++i) t.row(i) = mesh.triangles.row(kept[i]);
    mesh.triangles = t;
    keep_cells(mesh.cell_data, kept);
  }

  // Orientation: two triangles sharing an edge agree when they run along it in opposite
  // directions. Breadth-first from the lowest-numbered triangle of each piece, flipping as needed.
  const int nf = static_cast<int>(mesh.triangles.rows());
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;  // undirected edge -> faces
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  for (const auto& [edge, faces] : edge_faces)
    if (faces.size() > 2)
      throw Error(name + ": edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                  ") is shared by " + std::to_string(faces.size()) + " triangles; a cut must be a manifold surface");
  auto runs_forward = [&](int f, int a, int b) {  // does triangle f traverse a -> b?
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) == a && mesh.triangles(f, (k + 1) % 3) == b) return true;
    return false;
  };
  std::vector<int> flip(nf, -1);  // -1 unvisited, 0 keep, 1 flip
  int flipped = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (flip[seed] != -1) continue;
    flip[seed] = 0;
    std::queue<int> todo;
    todo.push(seed);
    while (!todo.empty()) {
      const int f = todo.front();
      todo.pop();
      for (int k = 0; k < 3; ++k) {
        int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
        if (flip[f]) std::swap(a, b);  // f's direction along the edge after its own flip
        for (int g : edge_faces[{std::min(a, b), std::max(a, b)}]) {
          if (g == f) continue;
          const int needed = runs_forward(g, a, b) ? 1 : 0;  // g must run b -> a
          if (flip[g] == -1) {
            flip[g] = needed;
            flipped += needed;
            todo.push(g);
          } else if (flip[g] != needed) {
            throw Error(name + ": the surface cannot be oriented consistently (a Moebius strip?) at edge (" +
                        std::to_string(a) + ", " + std::to_string(b) + ")");
          }
        }
      }
    }
  }
  for (int f = 0; f < nf; ++f)
    if (flip[f] == 1) std::swap(mesh.triangles(f, 1), mesh.triangles(f, 2));
  if (flipped && warnings)
    warnings->push_back(name + ": " + std::to_string(flipped) +
                        " triangles flipped to agree with their neighbours' orientation");
}

TriangleMesh read_triangle_mesh(const std::string& path, std::vector<std::string>* warnings) {
  if (path != "-" && extension_of(path) == ".msh") return read_gmsh_triangle_mesh(path, warnings);
  const std::string name = display_name(path);
  const char* what = "triangle surface";
  TriangleMesh mesh;
  {
    VtkMessages messages;
    const std::string ext = path == "-" ? std::string(".vtp") : extension_of(path);  // stdin carries VTK XML
    if (path != "-") require_readable(path);
    if (ext == ".vtp") {
      auto reader = Ptr<vtkXMLPolyDataReader>::New();
      if (path == "-") {
        reader->ReadFromInputStringOn();
        const std::string text = read_stdin();
        check_vtk_xml_text(name, text);
        reader->SetInputString(text);
      } else {
        if (!reader->CanReadFile(path.c_str())) throw Error(path + ": not a VTK XML polydata (.vtp) file");
        check_vtk_xml_sizes(path);
        reader->SetFileName(path.c_str());
      }
      update_or_throw(reader.Get(), messages, name, what);
      mesh = from_polydata(reader->GetOutput(), name);
    } else if (ext == ".vtk") {
      check_legacy_sections(path);
      auto reader = Ptr<vtkDataSetReader>::New();
      reader->SetFileName(path.c_str());
      configure_legacy(reader.Get());
      update_or_throw(reader.Get(), messages, path, what);
      if (auto poly = vtkPolyData::SafeDownCast(reader->GetOutput()))
        mesh = from_polydata(poly, path);
      else if (auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput()))
        mesh = from_grid(grid, path);
      else
        throw Error(path + ": not a legacy VTK POLYDATA or UNSTRUCTURED_GRID file");
    } else if (ext == ".vtu") {  // an unstructured grid of triangles (meshio reads and writes these)
      mesh = from_grid(read_unstructured_grid(path, messages), path);
    } else if (ext == ".stl") {
      check_stl(path);
      auto reader = Ptr<vtkSTLReader>::New();
      reader->SetFileName(path.c_str());
      reader->MergingOn();  // STL repeats each vertex in every facet; merge exact duplicates
      update_or_throw(reader.Get(), messages, path, what);
      mesh = from_polydata(reader->GetOutput(), path);
    } else if (ext == ".obj") {
      mesh = read_off(path, true);
    } else if (ext == ".off") {
      mesh = read_off(path);
    } else {
      throw Error(path + ": unknown extension '" + ext + "' for a " + what +
                  " (expected .vtp, .vtu, .vtk, .stl, .obj, .off or .msh)");
    }
  }
  validate_triangle_mesh(mesh, name, warnings);
  return mesh;
}

void write_triangle_mesh(const TriangleMesh& mesh, const std::string& path, Compression compression) {
  if (path != "-" && extension_of(path) == ".vtu") return write_triangle_grid(mesh, path, compression);
  if (path != "-" && extension_of(path) != ".vtp")
    throw Error(path + ": surfaces are written as .vtp or .vtu, not '" + extension_of(path) + "'");
  const std::string name = path == "-" ? std::string("<stdout>") : path;
  VtkMessages messages;
  auto poly = Ptr<vtkPolyData>::New();
  poly->SetPoints(to_vtk(mesh.points, name));
  poly->SetPolys(cell_array(mesh.triangles));
  add_arrays(poly->GetPointData(), mesh.point_data, mesh.points.rows(), "point", name);
  add_arrays(poly->GetCellData(), mesh.cell_data, mesh.triangles.rows(), "cell", name);
  write_atomically(path, [&](const std::string& tmp) {
    write_xml(Ptr<vtkXMLPolyDataWriter>::New(), poly, tmp, name, messages, compression);
  });
}

}  // namespace xfem
