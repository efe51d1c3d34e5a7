// SPDX-License-Identifier: MIT
#include "xfem/post/point_probe.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"

namespace xfem {
namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
    cells.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

int checked_side(double s, const std::string& where) {
  if (s != -1.0 && s != 0.0 && s != 1.0)
    throw Error(where + ": side must be -1, 0 or 1, got " + std::to_string(s));
  return static_cast<int>(s);
}

std::vector<ProbePoint> read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open for reading");
  std::vector<ProbePoint> points;
  std::string line;
  long number = 0;
  std::size_t columns = 0;  // 3 or 4 once the header is read
  while (std::getline(in, line)) {
    ++number;
    const std::string where = path + ": line " + std::to_string(number);
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const auto cells = split_csv(line);
    if (columns == 0) {
      const bool xyz = cells.size() >= 3 && cells[0] == "x" && cells[1] == "y" && cells[2] == "z";
      if (!xyz || cells.size() > 4 || (cells.size() == 4 && cells[3] != "side"))
        throw Error(where + ": the header must be x,y,z or x,y,z,side, got '" + line + "'");
      columns = cells.size();
      continue;
    }
    if (cells.size() != columns)
      throw Error(where + ": " + std::to_string(cells.size()) + " values, expected " + std::to_string(columns));
    double v[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < columns; ++c) {
      std::size_t used = 0;
      try {
        v[c] = std::stod(cells[c], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != cells[c].size() || !std::isfinite(v[c]))
        throw Error(where + ": '" + cells[c] + "' is not a finite number");
    }
    points.push_back({Eigen::Vector3d(v[0], v[1], v[2]), checked_side(v[3], where)});
  }
  if (columns == 0) throw Error(path + ": no header line x,y,z[,side]");
  return points;
}

std::vector<ProbePoint> read_vtp(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  if (!reader->CanReadFile(path.c_str())) throw Error(path + ": not a VTK XML polydata (.vtp) file");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  if (!poly || !poly->GetPoints()) throw Error(path + ": no points");
  vtkDataArray* side = poly->GetPointData()->GetArray("side");
  if (side && side->GetNumberOfComponents() != 1)
    throw Error(path + ": point array 'side' must have 1 component, has " +
                std::to_string(side->GetNumberOfComponents()));
  std::vector<ProbePoint> points(static_cast<std::size_t>(poly->GetNumberOfPoints()));
  for (vtkIdType k = 0; k < poly->GetNumberOfPoints(); ++k) {
    double p[3];
    poly->GetPoint(k, p);
    const std::string where = path + ": point " + std::to_string(k + 1);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Error(where + ": non-finite coordinate");
    points[k] = {Eigen::Vector3d(p[0], p[1], p[2]), side ? checked_side(side->GetTuple1(k), where) : 0};
  }
  return points;
}

}  // namespace

std::vector<ProbePoint> read_probe_points(const std::string& path) {
  require_readable(path);
  auto points = extension_of(path) == ".vtp" ? read_vtp(path) : read_csv(path);
  if (points.empty()) throw Error(path + ": no point to probe");
  return points;
}

std::vector<Eigen::Vector3d> probe(const FieldAt& field, const std::vector<ProbePoint>& points,
                                   const std::string& points_name) {
  std::vector<Eigen::Vector3d> values;
  values.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    bool snapped = false;
    const auto u = field(points[k].x, points[k].side, snapped);
    if (!u) {
      char where[160];
      std::snprintf(where, sizeof where, "point %zu (%.9g, %.9g, %.9g) lies outside the mesh", k + 1, points[k].x[0],
                    points[k].x[1], points[k].x[2]);
      throw Error(points_name + ": " + where);
    }
    values.push_back(*u);
  }
  return values;
}

void write_probe_csv(const std::vector<ProbePoint>& points, const std::vector<Eigen::Vector3d>& values,
                     const std::string& path) {
  write_atomically(path, [&](const std::string& tmp) {
    FILE* f = tmp == "-" ? stdout : std::fopen(tmp.c_str(), "w");
    if (!f) throw Error(path + ": cannot open for writing");
    std::fprintf(f, "x,y,z,side,ux,uy,uz\n");
    for (std::size_t k = 0; k < points.size(); ++k)
      std::fprintf(f, "%.17g,%.17g,%.17g,%d,%.17g,%.17g,%.17g\n", points[k].x[0], points[k].x[1], points[k].x[2],
                   points[k].side, values[k][0], values[k][1], values[k][2]);
    const bool ok = std::fflush(f) == 0 && !std::ferror(f);
    if (f != stdout) std::fclose(f);
    if (!ok) throw Error(path + ": write failed");
  });
}

}  // namespace xfem
