// SPDX-License-Identifier: MIT
#include "xfem/io/paraview_script.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"

namespace xfem {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string vector(const Eigen::Vector3d& v) { return "[" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + "]"; }

// `file` relative to the directory of `script`, as a Python string literal.
std::string relative(const std::string& file, const std::string& script) {
  namespace fs = std::filesystem;
  const fs::path base = fs::absolute(script).parent_path();
  std::string r = fs::absolute(file).lexically_normal().lexically_relative(base.lexically_normal()).generic_string();
  std::string quoted = "'";
  for (char c : r) quoted += c == '\'' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  return quoted + "'";
}

}  // namespace

void write_paraview_script(const std::string& path, const std::string& deformed, const std::string& wound,
                           const CutView& view, double top, double scale) {
  const bool section = view.has_cut && view.interior;
  std::string s;
  s += "# Opens " + std::filesystem::path(deformed).filename().string() +
       " as xfem-visualize drew it: warped, coloured by von Mises stress over the picture's range.\n";
  s += "# Run: paraview --script=" + std::filesystem::path(path).filename().string() + "   (or pvpython for a batch run)\n";
  s += "import os\nfrom paraview.simple import *\n\n";
  s += "here = os.path.dirname(os.path.abspath(__file__)) if '__file__' in globals() else os.getcwd()\n";
  s += "scale = " + number(scale) + "  # displacement magnification\n";
  s += "top = " + number(top) + "  # Pa: colour range 0..top (95th percentile of the cells)\n";
  s += "view = GetActiveViewOrCreate('RenderView')\n";
  s += "body = XMLUnstructuredGridReader(registrationName='deformed', FileName=[os.path.join(here, " +
       relative(deformed, path) + ")])\n";
  s += "shown = WarpByVector(registrationName='warped', Input=body)\n";
  s += "shown.Vectors = ['POINTS', 'displacement']\nshown.ScaleFactor = scale\n";
  if (section) {
    s += "# The cut lies inside the body: a section through its centre, the half towards the eye removed.\n";
    s += "shown = Clip(registrationName='section', Input=shown)\nshown.ClipType = 'Plane'\n";
    s += "shown.ClipType.Origin = " + vector(view.centre) + "\nshown.ClipType.Normal = " + vector(view.opening) + "\n";
    s += "shown.Invert = 1\n";
  }
  s += "display = Show(shown, view)\n";
  s += "ColorBy(display, ('CELLS', 'von_mises'))\n";
  s += "lut = GetColorTransferFunction('von_mises')\nlut.ApplyPreset('Viridis (matplotlib)', True)\n";
  s += "lut.AutomaticRescaleRangeMode = 'Never'\nlut.RescaleTransferFunction(0.0, top)\n";
  s += "display.SetScalarBarVisibility(view, True)\n";
  if (!wound.empty()) {
    s += "wound = XMLPolyDataReader(registrationName='wound', FileName=[os.path.join(here, " + relative(wound, path) + ")])\n";
    s += "wound_shown = WarpByVector(registrationName='wound warped', Input=wound)\n";
    s += "wound_shown.Vectors = ['POINTS', 'displacement']\nwound_shown.ScaleFactor = scale\n";
    if (section) {
      s += "wound_shown = Clip(registrationName='wound section', Input=wound_shown)\nwound_shown.ClipType = 'Plane'\n";
      s += "wound_shown.ClipType.Origin = " + vector(view.centre) + "\nwound_shown.ClipType.Normal = " +
           vector(view.opening) + "\nwound_shown.Invert = 1\n";
    }
    s += "wound_display = Show(wound_shown, view)\nColorBy(wound_display, None)\n";
    s += "wound_display.AmbientColor = wound_display.DiffuseColor = [0.85, 0.2, 0.25]\n";
  }
  s += "# The picture's camera: parallel projection from this direction, z up.\n";
  s += "eye = " + vector(view.eye) + "\n";
  s += "b = shown.GetDataInformation().GetBounds()\n";
  s += "centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]\n";
  s += "size = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])\n";
  s += "view.CameraParallelProjection = 1\nview.CameraFocalPoint = centre\n";
  s += "view.CameraPosition = [centre[i] + 4 * size * eye[i] for i in range(3)]\n";
  s += "view.CameraViewUp = [0, 0, 1] if abs(eye[2]) < 0.95 else [0, 1, 0]\n";
  s += "view.ResetCamera(False)\nRender()\n";
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << s;
    out.close();
    if (!out) throw Error(path + ": cannot write");
  });
}

}  // namespace xfem
