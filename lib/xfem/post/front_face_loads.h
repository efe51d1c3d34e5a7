// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/fracture/stress_intensity.h"
#include "xfem/system/problem.h"

namespace xfem {

/// The loads on the faces of cut `cut` that xfem-front's interaction integral takes into its
/// crack-face term (docs/METHOD.md "K with loaded faces"): problem.json's cut_loads on that cut
/// added to options.face_pressure and face_traction, and the contact pressure of `contact_path`
/// (xfem-solve's or xfem-newton's --contact-pressure file; empty: none), returned (empty
/// `pressure` when none). The caller points options.contact_pressure at the result, which must
/// outlive the evaluation. Throws xfem::Error naming the file when contact is off for the cut yet a
/// file is given, or the file does not fit the mesh; warns when contact is on and no file is given.
FaceContactPressure front_face_loads(const Problem& problem, const std::string& problem_path, const EnrichedMesh& em,
                                     int cut, const std::string& contact_path, FrontSifOptions& options);

}  // namespace xfem
