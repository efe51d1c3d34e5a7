// SPDX-License-Identifier: MIT
// Region names of a tet mesh in VTK field data: the parallel arrays region_ids (Int32) and
// region_names (vtkStringArray), docs/FORMATS.md "Regions".
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkStringArray.h>

#include <cmath>

#include "xfem/core/regions.h"
#include "xfem/io/vtk_io_detail.h"

namespace xfem::vtk_io_detail {
namespace {
const char* const ids_name = "region_ids";
const char* const names_name = "region_names";
}  // namespace

std::map<int, std::string> take_region_names(vtkFieldData* in, DataArrays& field_data, const std::string& name) {
  std::map<int, std::string> out;
  vtkAbstractArray* names = in ? in->GetAbstractArray(names_name) : nullptr;
  const auto ids = field_data.find(ids_name);
  if (!names && ids == field_data.end()) return out;
  if (!names || ids == field_data.end())
    throw Error(name + ": field array '" + (names ? ids_name : names_name) + "' missing: region names need both '" +
                ids_name + "' and '" + names_name + "'");
  auto* strings = vtkStringArray::SafeDownCast(names);
  if (!strings) throw Error(name + ": field array 'region_names' must be a string array");
  const DataArray& id = ids->second;
  if (id.type == DataArray::Type::Float64 || id.components != 1)
    throw Error(name + ": field array 'region_ids' must be a one-component integer array");
  if (strings->GetNumberOfComponents() != 1 ||
      static_cast<std::size_t>(strings->GetNumberOfValues()) != id.values.size())
    throw Error(name + ": field arrays 'region_ids' (" + std::to_string(id.values.size()) + " values) and " +
                "'region_names' (" + std::to_string(strings->GetNumberOfValues()) + ") differ in length");
  for (std::size_t i = 0; i < id.values.size(); ++i) {
    const double v = id.values[i];
    if (!(v >= 0 && v <= static_cast<double>(max_region_id) && v == std::floor(v)))
      throw Error(name + ": field array 'region_ids' holds " + short_number(v) + ", not a region id in [0, " +
                  std::to_string(max_region_id) + "]");
    if (!out.emplace(static_cast<int>(v), strings->GetValue(static_cast<vtkIdType>(i))).second)
      throw Error(name + ": field array 'region_ids' names region " + short_number(v) + " twice");
  }
  field_data.erase(ids);
  return out;
}

void add_region_names(vtkFieldData* out, const std::map<int, std::string>& names, const DataArrays& field_data,
                      const std::string& name) {
  if (names.empty()) return;
  if (field_data.count(ids_name))
    throw Error(name + ": cannot write: field array 'region_ids' is both an array and the region names' ids");
  auto ids = Ptr<vtkIntArray>::New();
  auto strings = Ptr<vtkStringArray>::New();
  ids->SetName(ids_name);
  strings->SetName(names_name);
  for (const auto& [id, region] : names) {
    ids->InsertNextValue(id);
    strings->InsertNextValue(region);
  }
  out->AddArray(ids);
  out->AddArray(strings);
}

}  // namespace xfem::vtk_io_detail
