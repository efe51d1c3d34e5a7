// SPDX-License-Identifier: MIT
// Internal to lib/xfem/io: what the VTK readers and writers of vtk_io.h share (VTK's messages
// turned into xfem::Error, VTK's arrays and points as ours and back, the cells' checks, the grid
// reader and the XML writer). Users of the library include xfem/io/vtk_io.h.
#pragma once
#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/core/mesh.h"
#include "xfem/io/vtk_io.h"

class vtkDataSet;
class vtkFieldData;
class vtkPoints;
class vtkXMLWriter;

namespace xfem::vtk_io_detail {

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

  /// VTK's message `text` as one line for a user: VTK formats "ERROR: In <source file>, line
  /// <n>\n<Class> (0x<address>): <message>\n\n". Keeps the first line of <message>, without the
  /// object addresses it names (they change from run to run: error texts must be deterministic,
  /// and mean nothing to a user), with the bytes of a corrupt input it quotes escaped ("\xNN")
  /// and at most 200 characters.
  static std::string clean(const char* text);
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

/// The named numeric arrays of `in` (null: none), as ours.
DataArrays to_arrays(vtkFieldData* in);
/// The points of `in` (null: none), as ours.
Points to_points(vtkPoints* in);
/// "vtkTriangle (VTK type 5)": a cell type as messages name it.
std::string cell_type_name(int type);
/// Name used in messages for "-" (standard input/output).
std::string display_name(const std::string& path);
/// All of standard input.
std::string read_stdin();

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

/// The region names of a tet mesh's field data `in` (the parallel arrays region_ids and
/// region_names, tet_mesh_regions.cpp); region_ids, already read into `field_data` as a numeric
/// array, is removed from it. Empty when there are none. Throws xfem::Error "<name>: ..." for one
/// array without the other, wrong types or lengths, an id out of range or named twice.
std::map<int, std::string> take_region_names(vtkFieldData* in, DataArrays& field_data, const std::string& name);
/// Adds `names` (if any) to `out` as region_ids (Int32) and region_names (strings). Throws when
/// `field_data` (the mesh's other field arrays) also has a region_ids.
void add_region_names(vtkFieldData* out, const std::map<int, std::string>& names, const DataArrays& field_data,
                      const std::string& name);

/// Refuses a legacy `.vtk` file whose sections VTK would misread (vtk_legacy_check.cpp).
void check_legacy_sections(const std::string& path);

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

/// Reads a `.vtu` or legacy `.vtk` unstructured grid (from standard input for "-": VTK XML),
/// checked before VTK parses it; VTK's first error becomes an xfem::Error.
Ptr<vtkUnstructuredGrid> read_unstructured_grid(const std::string& path, const VtkMessages& messages);

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

/// `in` as VTK points in double precision; a non-finite coordinate is an error.
Ptr<vtkPoints> to_vtk(const Points& in, const std::string& name);
/// Adds the point and cell arrays (and the field arrays unless `field_data` is null) to `data`,
/// whose points and cells are set, checked, and writes it with `writer` to `path` atomically
/// (stdout for "-"; `name` names it in messages). VTK's first error is thrown as an xfem::Error.
void write_vtk_xml(vtkXMLWriter* writer, vtkDataSet* data, const DataArrays& point_data, const DataArrays& cell_data,
                   const DataArrays* field_data, const std::string& path, const std::string& name,
                   Compression compression);

}  // namespace xfem::vtk_io_detail
