// SPDX-License-Identifier: MIT
#include "xfem/snapshot.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "xfem/atomic_file.h"
#include "xfem/error.h"

namespace xfem {
namespace {

template <class T>
using Ptr = vtkSmartPointer<T>;

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// Value and unit prefix for a stress in Pa, e.g. 12345 -> "12.3 kPa".
std::string pascals(double v) {
  if (v >= 1e6) return format("%.3g MPa", v / 1e6);
  if (v >= 1e3) return format("%.3g kPa", v / 1e3);
  return format("%.3g Pa", v);
}

Ptr<vtkTextActor> text(const std::string& s, double x, double y, int size, int justification) {
  auto t = Ptr<vtkTextActor>::New();
  t->SetInput(s.c_str());
  t->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  t->SetPosition(x, y);
  t->GetTextProperty()->SetFontSize(size);
  t->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  t->GetTextProperty()->SetJustification(justification);
  return t;
}

}  // namespace

void write_snapshot(const TetMesh& deformed, const std::string& png, const SnapshotOptions& o) {
  if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY"))
    throw Error(png + ": rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
  const Eigen::Index np = deformed.points.rows(), nt = deformed.tets.rows();
  const auto& u = require_array(deformed.point_data, "displacement", "point", 3, np, "deformed mesh", "deformed_body");
  const auto& vm = require_array(deformed.cell_data, "von_mises", "cell", 1, nt, "deformed mesh", "deformed_body");

  // 1. The deformed split mesh; its outer surface includes both faces of the opened cut.
  auto points = Ptr<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  for (Eigen::Index k = 0; k < np; ++k)
    points->SetPoint(k, deformed.points(k, 0) + o.scale * u(k, 0), deformed.points(k, 1) + o.scale * u(k, 1),
                     deformed.points(k, 2) + o.scale * u(k, 2));
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(nt);
  for (Eigen::Index t = 0; t < nt; ++t) {
    const vtkIdType ids[4] = {deformed.tets(t, 0), deformed.tets(t, 1), deformed.tets(t, 2), deformed.tets(t, 3)};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  auto stress = Ptr<vtkDoubleArray>::New();
  stress->SetName("von_mises");
  stress->SetNumberOfTuples(nt);
  for (Eigen::Index t = 0; t < nt; ++t) stress->SetValue(t, vm(t));
  grid->GetCellData()->SetScalars(stress);
  auto surface = Ptr<vtkDataSetSurfaceFilter>::New();
  surface->SetInputData(grid);
  surface->Update();

  // 2. Colours: 0 .. 95th percentile of the cells' von Mises stress.
  std::vector<double> sorted(vm.values);
  std::sort(sorted.begin(), sorted.end());
  double top = sorted.empty() ? 1.0 : sorted[static_cast<std::size_t>(0.95 * (sorted.size() - 1))];
  if (!(top > 0)) top = sorted.empty() || !(sorted.back() > 0) ? 1.0 : sorted.back();
  auto lut = Ptr<vtkLookupTable>::New();
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(0.0, top);
  lut->SetNumberOfTableValues(256);
  lut->Build();

  auto mapper = Ptr<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(surface->GetOutputPort());
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUseCellData();
  mapper->SetScalarRange(0.0, top);
  auto actor = Ptr<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetEdgeVisibility(o.edges);
  actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
  actor->GetProperty()->SetLineWidth(0.5);
  // Enough ambient light that the faces turned away from the headlight keep their colour.
  actor->GetProperty()->SetAmbient(0.35);
  actor->GetProperty()->SetDiffuse(0.7);

  auto renderer = Ptr<vtkRenderer>::New();
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(actor);
  // The body in the left 80 %, the colour bar on the right.
  renderer->SetViewport(0.0, 0.0, 0.82, 1.0);

  // 3. The fixed camera: parallel projection looking along (1, 1, -1) (from (-1, -1, 1), isometric, towards
  // the centre of the deformed bounding box), z up, scaled so that the box's 8 corners fit with a
  // 5 % margin. Parallel, so that the picture does not depend on a distance.
  double b[6];
  surface->GetOutput()->GetBounds(b);
  const Eigen::Vector3d centre((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
  const Eigen::Vector3d view = Eigen::Vector3d(1, 1, -1).normalized();
  const Eigen::Vector3d up = (Eigen::Vector3d::UnitZ() - view.z() * view).normalized(), right = view.cross(up);
  double half_height = 0, half_width = 0, depth = 0;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)]);
    half_height = std::max(half_height, std::abs(up.dot(corner - centre)));
    half_width = std::max(half_width, std::abs(right.dot(corner - centre)));
    depth = std::max(depth, (corner - centre).norm());
  }
  const double aspect = 0.82 * o.width / o.height;
  auto camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre - 4 * (depth > 0 ? depth : 1.0) * view;
  camera->SetPosition(eye.data());
  camera->SetViewUp(up.data());
  camera->SetParallelScale(1.05 * std::max(half_height, half_width / aspect));
  renderer->ResetCameraClippingRange();

  // 4. Colour bar (a strip of quads in normalized viewport coordinates) and captions.
  auto overlay = Ptr<vtkRenderer>::New();
  overlay->SetViewport(0.82, 0.0, 1.0, 1.0);
  overlay->SetBackground(1, 1, 1);
  auto bar = Ptr<vtkPolyData>::New();
  auto bar_points = Ptr<vtkPoints>::New();
  auto bar_cells = Ptr<vtkCellArray>::New();
  auto bar_colours = Ptr<vtkUnsignedCharArray>::New();
  bar_colours->SetNumberOfComponents(3);
  const int steps = 64;
  const double x0 = 0.15, x1 = 0.4, y0 = 0.1, y1 = 0.8;
  for (int i = 0; i < steps; ++i) {
    const double ya = y0 + (y1 - y0) * i / steps, yb = y0 + (y1 - y0) * (i + 1) / steps;
    const vtkIdType base = bar_points->GetNumberOfPoints();
    bar_points->InsertNextPoint(x0, ya, 0);
    bar_points->InsertNextPoint(x1, ya, 0);
    bar_points->InsertNextPoint(x1, yb, 0);
    bar_points->InsertNextPoint(x0, yb, 0);
    const vtkIdType quad[4] = {base, base + 1, base + 2, base + 3};
    bar_cells->InsertNextCell(4, quad);
    double rgb[3];
    lut->GetColor(top * (i + 0.5) / steps, rgb);
    bar_colours->InsertNextTuple3(255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
  }
  bar->SetPoints(bar_points);
  bar->SetPolys(bar_cells);
  bar->GetCellData()->SetScalars(bar_colours);
  auto coordinate = Ptr<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToNormalizedViewport();
  auto bar_mapper = Ptr<vtkPolyDataMapper2D>::New();
  bar_mapper->SetInputData(bar);
  bar_mapper->SetTransformCoordinate(coordinate);
  bar_mapper->SetColorModeToDirectScalars();
  bar_mapper->SetScalarModeToUseCellData();
  auto bar_actor = Ptr<vtkActor2D>::New();
  bar_actor->SetMapper(bar_mapper);
  overlay->AddActor2D(bar_actor);
  const int font = std::max(12, o.height / 50);
  overlay->AddActor2D(text(pascals(0.0), x1 + 0.05, y0 - 0.01, font, VTK_TEXT_LEFT));
  overlay->AddActor2D(text(pascals(top / 2), x1 + 0.05, (y0 + y1) / 2 - 0.01, font, VTK_TEXT_LEFT));
  overlay->AddActor2D(text(">= " + pascals(top), x1 + 0.05, y1 - 0.01, font, VTK_TEXT_LEFT));
  overlay->AddActor2D(text("von Mises", x0, y1 + 0.06, font, VTK_TEXT_LEFT));
  std::string caption = o.title.empty() ? std::string() : o.title + "\n";
  caption += "displacements x " + format("%g", o.scale) + ", max |u| = " +
             format("%.3g m", [&] {
               double m = 0;
               for (Eigen::Index k = 0; k < np; ++k) m = std::max(m, std::sqrt(u(k, 0) * u(k, 0) + u(k, 1) * u(k, 1) + u(k, 2) * u(k, 2)));
               return m;
             }());
  renderer->AddActor2D(text(caption, 0.02, 0.02, font, VTK_TEXT_LEFT));

  auto window = Ptr<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetSize(o.width, o.height);
  window->AddRenderer(renderer);
  window->AddRenderer(overlay);
  window->Render();
  auto image = Ptr<vtkWindowToImageFilter>::New();
  image->SetInput(window);
  image->SetInputBufferTypeToRGB();
  image->ReadFrontBufferOff();
  image->Update();
  write_atomically(png, [&](const std::string& tmp) {
    auto writer = Ptr<vtkPNGWriter>::New();
    writer->SetFileName(tmp.c_str());
    writer->SetInputConnection(image->GetOutputPort());
    writer->Write();
    if (writer->GetErrorCode() != 0) throw Error(png + ": cannot write the PNG");
  });
}

}  // namespace xfem
