// SPDX-License-Identifier: MIT
#include "xfem/post/solution_provenance_check.h"

#include <cctype>

#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/enrich/classification_several_cuts.h"

namespace xfem {
namespace {

// The fingerprint name of cut k, as xfem-assemble records it (solution_provenance.h).
std::string cut_name(std::size_t k) { return k == 0 ? "cut" : "cut_" + std::to_string(k); }

// The cut index of a fingerprint name ("cut" 0, "cut_3" 3), or -1 for another name.
long cut_index(const std::string& name) {
  if (name == "cut") return 0;
  if (name.compare(0, 4, "cut_") != 0 || name.size() == 4 || name.size() > 8) return -1;
  for (std::size_t i = 4; i < name.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return -1;
  return std::stol(name.substr(4));
}

std::string describe_cut(std::size_t k) { return k == 0 ? "a cut" : "cut " + std::to_string(k); }

}  // namespace

void check_solution_provenance(const SolutionFiles& files, const TetMesh& mesh,
                               const std::vector<const TriangleMesh*>& cuts) {
  const Provenance recorded = read_mtx_provenance(files.solution);
  if (recorded.empty()) return;  // another solver's u.mtx, or one written before fingerprints
  const std::string& u = files.solution;
  check_provenance(recorded, u, "enriched", fingerprint(mesh), files.mesh);
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const std::string& path = k < files.cuts.size() ? files.cuts[k] : files.cuts.at(0);
    // A solution that records its mesh but no cut k was solved without it (xfem-assemble records every
    // cut): wrong for a mesh classified with that cut. A mesh classified without one (no record)
    // has no enriched DOFs, and a cut given with it changes nothing (bench.py's reference case).
    Fingerprint classified_with = 0;
    if (!recorded.count(cut_name(k)) && recorded.count("enriched") &&
        stored_fingerprint(mesh.field_data, "cut_fingerprint" + cut_suffix(static_cast<int>(k)), &classified_with))
      throw Error(u + ": does not belong to " + path + " (solved without " + describe_cut(k) + ", but " + files.mesh +
                  " was classified with " + path + ")");
    check_provenance(recorded, u, cut_name(k), fingerprint(*cuts[k]), path);
  }
  if (!files.standard_dofs_only)
    for (const auto& [name, f] : recorded) {
      const long k = cut_index(name);
      if (k >= static_cast<long>(cuts.size()))
        throw Error(u + ": solved with " + describe_cut(static_cast<std::size_t>(k)) + " (" + name + " " +
                    to_string(f) + "), but " + files.mesh + " is given without it");
    }
  if (!files.problem.empty())
    check_provenance(recorded, u, "problem", fingerprint_json_file(files.problem), files.problem);
}

void check_solution_provenance(const SolutionFiles& files, const EnrichedMesh& em) {
  std::vector<const TriangleMesh*> cuts;  // several cuts: from em.cuts (xfem-front's em.cut is the selected front's)
  if (em.cuts.empty() && em.cut) cuts.push_back(&em.cut->mesh());
  for (const CutLayer& layer : em.cuts) cuts.push_back(&layer.cut->mesh());
  if (em.cut && em.cuts.empty() && !files.cuts.empty())
    check_cut_matches(em.mesh, files.mesh, em.cut->mesh(), files.cuts[0]);
  check_solution_provenance(files, em.mesh, cuts);
}

}  // namespace xfem
