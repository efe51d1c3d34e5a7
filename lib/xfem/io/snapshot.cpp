// SPDX-License-Identifier: MIT
#include "xfem/io/snapshot.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkClipDataSet.h>
#include <vtkClipPolyData.h>
#include <vtkCoordinate.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>

#include <mutex>
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
#include <map>
#include <utility>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/io/region_boundary.h"

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

// Viridis (matplotlib's perceptually uniform map, CC0), its entries 0, 32, ..., 224 and 255 of
// 256; linear interpolation between them stays within 0.01 of the full table.
constexpr double kViridis[9][3] = {
    {0.267004, 0.004874, 0.329415}, {0.278826, 0.175490, 0.483397}, {0.229739, 0.322361, 0.545706},
    {0.172719, 0.448791, 0.557885}, {0.127568, 0.566949, 0.550556}, {0.157851, 0.683765, 0.501686},
    {0.369214, 0.788888, 0.382914}, {0.678489, 0.863742, 0.189503}, {0.993248, 0.906157, 0.143936}};

Ptr<vtkLookupTable> viridis(double top) {
  auto lut = Ptr<vtkLookupTable>::New();
  const int n = 256;
  lut->SetNumberOfTableValues(n);
  lut->SetTableRange(0.0, top);
  for (int i = 0; i < n; ++i) {
    const double t = 255.0 * i / (n - 1);
    const double anchor[9] = {0, 32, 64, 96, 128, 160, 192, 224, 255};
    int k = 0;
    while (k < 7 && t > anchor[k + 1]) ++k;
    const double w = (t - anchor[k]) / (anchor[k + 1] - anchor[k]);
    lut->SetTableValue(i, (1 - w) * kViridis[k][0] + w * kViridis[k + 1][0],
                       (1 - w) * kViridis[k][1] + w * kViridis[k + 1][1],
                       (1 - w) * kViridis[k][2] + w * kViridis[k + 1][2], 1.0);
  }
  lut->SetAboveRangeColor(kViridis[8][0], kViridis[8][1], kViridis[8][2], 1.0);
  lut->UseAboveRangeColorOn();
  return lut;
}

// The wound's own colour: a red no viridis entry comes near.
constexpr double kWoundColour[3] = {0.85, 0.2, 0.25};

// Outline colours of the regions other than the largest, in ascending id order (cycled): far from
// viridis and from the wound's red.
constexpr double kRegionColours[4][3] = {{1.0, 0.5, 0.0}, {0.9, 0.1, 0.75}, {0.1, 0.8, 1.0}, {0.55, 0.35, 0.1}};
const char* const kRegionColourNames[4] = {"orange", "magenta", "cyan", "brown"};

// The name of region r for the legend: its name in the mesh, or "region r".
std::string region_name(const TetMesh& mesh, int r) {
  const auto it = mesh.region_names.find(r);
  return it != mesh.region_names.end() ? it->second : "region " + std::to_string(r);
}

// The regions other than the largest, drawn over the opaque body in a layer of their own (so an
// inclusion inside the body shows through it): each region's boundary faces see-through in its
// colour and its outline (silhouette and open borders, seen from `eye`) as opaque lines. Clipped
// by `plane` when `plane` is given (a section). Returns the regions drawn, ascending, and sets
// `majority` to the largest region (not drawn).
std::vector<int> add_region_outlines(vtkRenderer* layer, const TetMesh& mesh, const Points& x,
                                     const Eigen::Vector3d& eye, vtkPlane* plane, int& majority) {
  const RegionBoundary boundary = region_boundary(mesh);
  majority = boundary.majority;
  std::vector<int> drawn(boundary.region.begin(), boundary.region.end());
  std::sort(drawn.begin(), drawn.end());
  drawn.erase(std::unique(drawn.begin(), drawn.end()), drawn.end());
  auto points = Ptr<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(x.rows());
  for (Eigen::Index k = 0; k < x.rows(); ++k) points->SetPoint(k, x(k, 0), x(k, 1), x(k, 2));
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const double* colour = kRegionColours[i % 4];
    Triangles tris(std::count(boundary.region.begin(), boundary.region.end(), drawn[i]), 3);
    auto polys = Ptr<vtkCellArray>::New();
    for (Eigen::Index f = 0, n = 0; f < boundary.triangles.rows(); ++f) {
      if (boundary.region[f] != drawn[i]) continue;
      tris.row(n++) = boundary.triangles.row(f);
      const vtkIdType ids[3] = {boundary.triangles(f, 0), boundary.triangles(f, 1), boundary.triangles(f, 2)};
      polys->InsertNextCell(3, ids);
    }
    auto lines = Ptr<vtkCellArray>::New();
    for (const auto& e : outline_edges(x, tris, eye)) {
      const vtkIdType ids[2] = {e[0], e[1]};
      lines->InsertNextCell(2, ids);
    }
    for (const bool fill : {true, false}) {
      auto poly = Ptr<vtkPolyData>::New();
      poly->SetPoints(points);
      if (fill) poly->SetPolys(polys);
      else poly->SetLines(lines);
      auto mapper = Ptr<vtkPolyDataMapper>::New();
      auto clip = Ptr<vtkClipPolyData>::New();
      if (plane) {
        clip->SetInputData(poly);
        clip->SetClipFunction(plane);
        clip->InsideOutOn();
        mapper->SetInputConnection(clip->GetOutputPort());
      } else {
        mapper->SetInputData(poly);
      }
      mapper->ScalarVisibilityOff();
      auto actor = Ptr<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
      if (fill) {
        actor->GetProperty()->SetOpacity(0.35);
        actor->GetProperty()->SetAmbient(0.5);
        actor->GetProperty()->SetDiffuse(0.6);
      } else {
        actor->GetProperty()->SetLineWidth(2.5);
        actor->GetProperty()->LightingOff();
      }
      layer->AddActor(actor);
    }
  }
  return drawn;
}

}  // namespace

CutView cut_view(const TriangleMesh& wound) {
  CutView v;
  const Eigen::Index nf = wound.triangles.rows();
  if (nf == 0) return v;
  const auto& side = require_array(wound.cell_data, "side", "cell", 1, nf, "wound", "deformed_body");
  // 1. Normal and centre from the upper sheet (side +1), whose faces point to the lower side.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  double area = 0;
  std::vector<int> sides(wound.points.rows(), 0);  // bit 1: used by +1, bit 2: used by -1
  std::map<std::pair<int, int>, int> edges;         // of the upper sheet: how many faces use each
  for (Eigen::Index f = 0; f < nf; ++f) {
    const bool upper = side(f) > 0;
    for (int c = 0; c < 3; ++c) sides[wound.triangles(f, c)] |= upper ? 1 : 2;
    if (!upper) continue;
    const Eigen::Vector3d a = wound.points.row(wound.triangles(f, 0)), b = wound.points.row(wound.triangles(f, 1)),
                          c = wound.points.row(wound.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    sum += n;
    area += n.norm();
    centre += n.norm() * (a + b + c) / 3;
    for (int e = 0; e < 3; ++e) {
      const int p = wound.triangles(f, e), q = wound.triangles(f, (e + 1) % 3);
      ++edges[{std::min(p, q), std::max(p, q)}];
    }
  }
  if (!(area > 0) || !(sum.norm() > 0)) return v;
  v.has_cut = true;
  v.centre = centre / area;
  v.normal = -sum.normalized();
  // 2. The sheet's border: front edges join points both sheets use; the other border edges lie
  // where the cut meets the body's surface (the mouth).
  Eigen::Vector3d mouth = Eigen::Vector3d::Zero(), front = Eigen::Vector3d::Zero();
  double mouth_length = 0, front_length = 0;
  for (const auto& [e, count] : edges) {
    if (count != 1) continue;
    const Eigen::Vector3d p = wound.points.row(e.first), q = wound.points.row(e.second);
    const double l = (q - p).norm();
    if (sides[e.first] == 3 && sides[e.second] == 3) {
      front += l * (p + q) / 2;
      front_length += l;
    } else {
      mouth += l * (p + q) / 2;
      mouth_length += l;
    }
  }
  // 3. The opening faces from the front towards the mouth, in the cut's plane.
  Eigen::Vector3d o = Eigen::Vector3d::Zero();
  if (mouth_length > 0 && front_length > 0) o = mouth / mouth_length - front / front_length;
  else if (mouth_length > 0) o = mouth / mouth_length - v.centre;  // cut through: no front
  o -= o.dot(v.normal) * v.normal;
  v.interior = mouth_length < 0.05 * (mouth_length + front_length);
  if (v.interior || !(o.norm() > 1e-9 * std::sqrt(area))) {
    // No mouth to look into: an in-plane direction towards the default isometric eye.
    o = Eigen::Vector3d(-1, -1, 1).normalized();
    o -= o.dot(v.normal) * v.normal;
    if (o.norm() < 1e-3) o = v.normal.unitOrthogonal();
  }
  v.opening = o.normalized();
  v.eye = v.interior ? (v.normal + v.opening).normalized()
                     : (v.opening + 0.8 * v.normal + 0.35 * v.normal.cross(v.opening)).normalized();
  return v;
}

double colour_top(const TetMesh& deformed) {
  const auto& vm = require_array(deformed.cell_data, "von_mises", "cell", 1, deformed.tets.rows(), "deformed mesh",
                                 "deformed_body");
  std::vector<double> sorted(vm.values);
  std::sort(sorted.begin(), sorted.end());
  double top = sorted.empty() ? 1.0 : sorted[static_cast<std::size_t>(0.95 * (sorted.size() - 1))];
  if (!(top > 0)) top = sorted.empty() || !(sorted.back() > 0) ? 1.0 : sorted.back();
  return top;
}

void write_snapshot(const TetMesh& deformed, const TriangleMesh& wound, const std::string& png,
                    const SnapshotOptions& o) {
  if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY"))
    throw Error(png + ": rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
  const Eigen::Index np = deformed.points.rows(), nt = deformed.tets.rows();
  const auto& u = require_array(deformed.point_data, "displacement", "point", 3, np, "deformed mesh", "deformed_body");
  const auto& vm = require_array(deformed.cell_data, "von_mises", "cell", 1, nt, "deformed mesh", "deformed_body");
  const CutView view = o.view ? *o.view : cut_view(wound);

  // 1. The deformed split mesh; its outer surface includes both faces of the opened cut. An
  // interior cut is shown by clipping away the half of the body between it and the eye.
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
  const bool section = view.has_cut && view.interior;
  auto plane = Ptr<vtkPlane>::New();
  plane->SetOrigin(view.centre.data());
  plane->SetNormal(view.opening.data());  // clip functions keep the side the normal points to
  auto surface = Ptr<vtkDataSetSurfaceFilter>::New();
  auto clip = Ptr<vtkClipDataSet>::New();
  if (section) {
    clip->SetInputData(grid);
    clip->SetClipFunction(plane);
    clip->InsideOutOn();  // keep (x - c) . opening < 0: the half away from the eye
    surface->SetInputConnection(clip->GetOutputPort());
  } else {
    surface->SetInputData(grid);
  }
  surface->Update();
  const vtkIdType faces = surface->GetOutput()->GetNumberOfCells();

  // 2. Colours: viridis from 0 to the 95th percentile of the cells' von Mises stress.
  const double top = o.colour_max > 0 ? o.colour_max : colour_top(deformed);
  auto lut = viridis(top);
  auto mapper = Ptr<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(surface->GetOutputPort());
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUseCellData();
  mapper->SetScalarRange(0.0, top);
  mapper->SetResolveCoincidentTopologyToPolygonOffset();  // the wound lies on the cut's faces
  auto actor = Ptr<vtkActor>::New();
  actor->SetMapper(mapper);
  const bool edges = o.edges == SnapshotOptions::Edges::On || (o.edges == SnapshotOptions::Edges::Auto && faces < 20000);
  actor->GetProperty()->SetEdgeVisibility(edges);
  actor->GetProperty()->SetEdgeColor(0.75, 0.75, 0.75);
  actor->GetProperty()->SetLineWidth(0.5);
  // Enough ambient light that the faces turned away from the headlight keep their colour.
  actor->GetProperty()->SetAmbient(0.35);
  actor->GetProperty()->SetDiffuse(0.7);

  auto renderer = Ptr<vtkRenderer>::New();
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(actor);
  // The body in the left 80 % above the caption, the colour bar on the right.
  renderer->SetViewport(0.0, 0.1, 0.82, 1.0);
  auto caption_strip = Ptr<vtkRenderer>::New();
  caption_strip->SetViewport(0.0, 0.0, 0.82, 0.1);
  caption_strip->SetBackground(1, 1, 1);

  // The wound in its own colour, at its deformed position (clipped like the body).
  if (view.has_cut) {
    auto wpoints = Ptr<vtkPoints>::New();
    wpoints->SetDataTypeToDouble();
    const auto& wu = require_array(wound.point_data, "displacement", "point", 3, wound.points.rows(), "wound",
                                   "deformed_body");
    for (Eigen::Index k = 0; k < wound.points.rows(); ++k)
      wpoints->InsertNextPoint(wound.points(k, 0) + o.scale * wu(k, 0), wound.points(k, 1) + o.scale * wu(k, 1),
                               wound.points(k, 2) + o.scale * wu(k, 2));
    auto wpolys = Ptr<vtkCellArray>::New();
    for (Eigen::Index f = 0; f < wound.triangles.rows(); ++f) {
      const vtkIdType ids[3] = {wound.triangles(f, 0), wound.triangles(f, 1), wound.triangles(f, 2)};
      wpolys->InsertNextCell(3, ids);
    }
    auto wpoly = Ptr<vtkPolyData>::New();
    wpoly->SetPoints(wpoints);
    wpoly->SetPolys(wpolys);
    auto wclip = Ptr<vtkClipPolyData>::New();
    auto wmapper = Ptr<vtkPolyDataMapper>::New();
    if (section) {
      wclip->SetInputData(wpoly);
      wclip->SetClipFunction(plane);
      wclip->InsideOutOn();
      wmapper->SetInputConnection(wclip->GetOutputPort());
    } else {
      wmapper->SetInputData(wpoly);
    }
    wmapper->ScalarVisibilityOff();
    wmapper->SetResolveCoincidentTopologyToPolygonOffset();
    auto wactor = Ptr<vtkActor>::New();
    wactor->SetMapper(wmapper);
    wactor->GetProperty()->SetColor(kWoundColour[0], kWoundColour[1], kWoundColour[2]);
    wactor->GetProperty()->SetAmbient(0.35);
    wactor->GetProperty()->SetDiffuse(0.7);
    renderer->AddActor(wactor);
  }

  // 3. The camera of cut_view: parallel projection from `eye` towards the centre of what is drawn,
  // the world's z up on the screen (y when looking along z), scaled so that the drawn box's 8
  // corners fit with a 5 % margin. Parallel, so that the picture does not depend on a distance.
  double b[6];
  surface->GetOutput()->GetBounds(b);
  if (o.frame) std::copy(o.frame->begin(), o.frame->end(), b);
  const Eigen::Vector3d centre((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
  const Eigen::Vector3d look = -view.eye;
  const Eigen::Vector3d world_up = std::abs(look.z()) < 0.95 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d up = (world_up - look.dot(world_up) * look).normalized(), right = look.cross(up);
  double half_height = 0, half_width = 0, depth = 0;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)]);
    half_height = std::max(half_height, std::abs(up.dot(corner - centre)));
    half_width = std::max(half_width, std::abs(right.dot(corner - centre)));
    depth = std::max(depth, (corner - centre).norm());
  }
  const double aspect = 0.82 * o.width / (0.9 * o.height);
  auto camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre + 4 * (depth > 0 ? depth : 1.0) * view.eye;
  camera->SetPosition(eye.data());
  camera->SetViewUp(up.data());
  camera->SetParallelScale(1.05 * std::max(half_height, half_width / aspect));
  renderer->ResetCameraClippingRange();

  // 3b. Several regions (an inclusion inside an organ): the regions other than the largest are
  // outlined in a layer over the body, with the same camera, and named in a legend. One region:
  // nothing is added, the picture is the same as without regions.
  auto region_layer = Ptr<vtkRenderer>::New();
  std::vector<int> outlined;
  int majority = 0;
  if (region_ids(deformed).size() > 1) {
    Points x(np, 3);
    for (Eigen::Index k = 0; k < np; ++k)
      for (int c = 0; c < 3; ++c) x(k, c) = deformed.points(k, c) + o.scale * u(k, c);
    outlined = add_region_outlines(region_layer, deformed, x, view.eye, section ? plane.Get() : nullptr, majority);
  }
  if (!outlined.empty()) {
    region_layer->SetLayer(1);
    region_layer->SetViewport(0.0, 0.1, 0.82, 1.0);
    region_layer->SetActiveCamera(camera);
    const int legend_font = std::max(12, o.height / 45);
    auto body_label = text(region_name(deformed, majority) + ": stress colours", 0.02, 0.95, legend_font, VTK_TEXT_LEFT);
    renderer->AddActor2D(body_label);
    for (std::size_t i = 0; i < outlined.size(); ++i) {
      const double* colour = kRegionColours[i % 4];
      auto label = text(region_name(deformed, outlined[i]) + ": " + kRegionColourNames[i % 4] + " outline, seen through",
                        0.02, 0.95 - 0.045 * (i + 1), legend_font, VTK_TEXT_LEFT);
      label->GetTextProperty()->SetColor(0.8 * colour[0], 0.8 * colour[1], 0.8 * colour[2]);
      label->GetTextProperty()->BoldOn();
      renderer->AddActor2D(label);
    }
  }

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
  const std::string model = o.stress_model.empty() ? std::string() : " (Cauchy, " + o.stress_model + ")";
  overlay->AddActor2D(text("von Mises\nstress" + (model.empty() ? std::string() : "\n(Cauchy,\n" + o.stress_model + ")"),
                           x0, y1 + 0.04, font, VTK_TEXT_LEFT));
  std::string caption = o.title.empty() ? std::string() : o.title + "\n";
  caption += "colour: von Mises stress" + model + (model.empty() ? ", " : ",\n") + "0 to " + pascals(top) + (o.colour_max > 0 ? std::string(" (fixed for the series; above: yellow)")
                                                                   : std::string(" (95th percentile of the cells; above: yellow)"));
  if (view.has_cut) caption += ", wound faces red";
  if (section) caption += "\nsection through the cut's centre, the half towards the viewer removed";
  caption += "\ndisplacements x " + format("%g", o.scale) + ", max |u| = " +
             format("%.3g m", [&] {
               double m = 0;
               for (Eigen::Index k = 0; k < np; ++k) m = std::max(m, std::sqrt(u(k, 0) * u(k, 0) + u(k, 1) * u(k, 1) + u(k, 2) * u(k, 2)));
               return m;
             }());
  caption_strip->AddActor2D(text(caption, 0.02, 0.08, font, VTK_TEXT_LEFT));

  // One picture at a time: xfem-sweep renders frames from two threads when its worker falls behind,
  // and two X connections opened at once without XInitThreads fail ("bad X server connection").
  // Declared before the window, so the window is released under the lock too.
  static std::mutex rendering;
  const std::lock_guard<std::mutex> lock(rendering);
  auto window = Ptr<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetSize(o.width, o.height);
  // Smoothed edges by FXAA (one pass over the image) instead of VTK's default 8x multisampling:
  // under xvfb-run the rendering is Mesa's software rasterizer, where multisampling cost ~0.35 s
  // of the organ's ~1.1 s picture (docs/PERFORMANCE.md); the two pictures look the same.
  window->SetMultiSamples(0);
  renderer->UseFXAAOn();
  window->AddRenderer(renderer);
  window->AddRenderer(overlay);
  window->AddRenderer(caption_strip);
  if (!outlined.empty()) {
    window->SetNumberOfLayers(2);
    window->AddRenderer(region_layer);
  }
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
