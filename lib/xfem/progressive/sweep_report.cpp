// SPDX-License-Identifier: MIT
#include "xfem/progressive/sweep_report.h"

#include "xfem/core/cli.h"

namespace xfem {

using cli::three_digits;

std::string describe_uncut_body(const UncutBody& body) {
  return "uncut body: " + std::to_string(body.free_dofs.size()) + " free DOFs, assembled in " +
         three_digits(body.assemble_seconds) + " s, factorized once (CHOLMOD, " + body.factor->ordering + ", " +
         std::to_string(static_cast<long>(body.factor->factor_nonzeros)) + " non-zeros in L) in " +
         three_digits(body.factor->analyze_seconds + body.factor->factor_seconds) + " s";
}

Json factorization_json(const UncutBody& body, double seconds) {
  return {{"free_dofs", static_cast<long>(body.free_dofs.size())},
          {"ordering", body.factor->ordering},
          {"factor_nonzeros", static_cast<long>(body.factor->factor_nonzeros)},
          {"assemble_seconds", body.assemble_seconds},
          {"analyze_seconds", body.factor->analyze_seconds},
          {"factor_seconds", body.factor->factor_seconds},
          {"solve_seconds", body.solve_seconds},
          {"seconds", seconds}};
}

namespace {
long cut_triangles(const CutSolution& step) {
  return step.em.cut ? static_cast<long>(step.em.cut->mesh().triangles.rows()) : 0;
}
}  // namespace

std::string describe_step(const CutSolution& step, int k, int steps, double t, bool incremental, const StepTimes& times,
                          bool picture) {
  return "step " + std::to_string(k) + "/" + std::to_string(steps) + ", t = " + three_digits(t) + " s: " +
         std::to_string(cut_triangles(step)) + " cut triangles, " +
         std::to_string(step.counts.partial + step.counts.complete) + " cut tets, " +
         std::to_string(step.enriched_dofs) + " enriched DOFs; solved in " + three_digits(times.solved) +
         " s (classify " + three_digits(step.classify_seconds) + ", assemble " + three_digits(step.assemble_seconds) +
         (incremental ? ", incremental Schur " : step.schur_used ? ", Schur " : ", refactorization ") +
         three_digits(step.solve_seconds) + "), frame written in " + three_digits(times.written) + " s" +
         (picture ? ", picture in " + three_digits(times.pictured) + " s" : "");
}

Json step_json(const CutSolution& step, int k, double t, bool incremental, const StepTimes& times) {
  return {{"step", k},
          {"time", t},
          {"cut_triangles", cut_triangles(step)},
          {"partial", step.counts.partial},
          {"complete", step.counts.complete},
          {"sign", step.counts.sign},
          {"branch", step.counts.branch},
          {"n", step.em.n},
          {"dofs", 3 * step.em.n},
          {"enriched_dofs", step.enriched_dofs},
          {"unsupported_dofs", step.unsupported_dofs},
          {"enriched_tets", step.enriched_tets},
          {"classify_seconds", step.classify_seconds},
          {"assemble_seconds", step.assemble_seconds},
          {"solver", incremental ? "incremental" : step.schur_used ? "schur" : "refactor"},
          {"recomputed_tets", step.recomputed_tets},
          {"keys_seconds", step.keys_seconds},
          {"elements_seconds", step.elements_seconds},
          {"kept_dofs", step.incremental.kept},
          {"added_dofs", step.incremental.added},
          {"refactored_rows", step.incremental.refactored},
          {"region_added", step.incremental.region_added},
          {"schur_seconds", step.schur.schur_seconds},
          {"dense_seconds", step.schur.dense_seconds},
          {"solve_seconds", step.solve_seconds},
          {"seconds", times.solved},
          {"frame_seconds", times.written},
          {"frame_build_seconds", times.built},
          {"schur_columns_seconds", step.incremental.columns_seconds},
          {"schur_factor_seconds", step.incremental.factor_seconds},
          {"picture_seconds", times.pictured}};
}

}  // namespace xfem
