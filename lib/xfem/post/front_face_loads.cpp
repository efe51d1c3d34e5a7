// SPDX-License-Identifier: MIT
#include "xfem/post/front_face_loads.h"

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/solve/contact_pressure_file.h"
#include "xfem/system/cut_loads.h"

namespace xfem {

FaceContactPressure front_face_loads(const Problem& problem, const std::string& problem_path, const EnrichedMesh& em,
                                     int cut, const std::string& contact_path, FrontSifOptions& options) {
  for (const CutLoad& load : problem.cut_loads)
    if (load.cut == cut) options.face_pressure += load.pressure, options.face_traction += load.traction;
  const std::string which = "cut " + std::to_string(cut);
  if (contact_path.empty()) {
    if (problem.contact.applies_to(cut))
      cli::warn(problem_path + ": contact is on for " + which + ": K leaves out the contact pressure on its faces "
                "(right where they are open, not where they touch): give --contact-pressure");
    return {};
  }
  if (!problem.contact.applies_to(cut))
    throw Error(problem_path + ": contact is off for " + which + ", yet --contact-pressure is given");
  return face_contact_pressure(read_contact_pressure(contact_path, em.mesh.points.rows(), cut_count(em)), cut,
                               contact_path);
}

}  // namespace xfem
