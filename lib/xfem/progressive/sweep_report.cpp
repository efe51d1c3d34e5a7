// SPDX-License-Identifier: MIT
#include "xfem/progressive/sweep_report.h"

#include <algorithm>

#include "xfem/core/cli.h"
#include "xfem/core/median.h"

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

StepSplit step_split(const CutSolution& step, const StepTimes& times) {
  StepSplit s;
  s.classify = step.classify_seconds;
  s.enrich = step.enrich_seconds;
  s.integrate = step.elements_seconds;
  s.gather = std::max(0.0, step.assemble_seconds - step.elements_seconds);
  const IncrementalSchurStats& i = step.incremental;
  s.schur_update = i.region_seconds + i.columns_seconds + i.factor_seconds + step.schur.schur_seconds;
  s.back_substitution = step.back_substitution_seconds;
  s.solve = std::max(0.0, step.solve_seconds - s.schur_update);
  s.frame = std::max(0.0, times.written - times.back_substitution);
  return s;
}

Json split_json(const StepSplit& s) {
  return {{"classify", s.classify},         {"enrich", s.enrich},
          {"integrate", s.integrate},       {"gather", s.gather},
          {"schur_update", s.schur_update}, {"solve", s.solve},
          {"back_substitution", s.back_substitution}, {"frame", s.frame}};
}

StepSplit median_split(const std::vector<StepSplit>& splits) {
  StepSplit m;
  for (auto part : {&StepSplit::classify, &StepSplit::enrich, &StepSplit::integrate, &StepSplit::gather,
                    &StepSplit::schur_update, &StepSplit::solve, &StepSplit::back_substitution, &StepSplit::frame}) {
    std::vector<double> v;
    for (const auto& s : splits) v.push_back(s.*part);
    m.*part = median(v);
  }
  return m;
}

namespace {
std::string milliseconds(double s) { return three_digits(1e3 * s) + " ms"; }
}  // namespace

std::string describe_median_split(const StepSplit& m, long steps, double median_wall) {
  return "median over the " + std::to_string(steps) + " steps that cut: step " + milliseconds(median_wall) +
         " (wall); classify " + milliseconds(m.classify) + ", enrich " + milliseconds(m.enrich) + ", integrate " +
         milliseconds(m.integrate) + ", gather " + milliseconds(m.gather) + ", Schur update " +
         milliseconds(m.schur_update) + ", solve " + milliseconds(m.solve) + "; back-substitution " +
         milliseconds(m.back_substitution) + " and frame " + milliseconds(m.frame) + " in the frame's thread";
}

std::string describe_step(const CutSolution& step, int k, int steps, double t, bool incremental, const StepTimes& times,
                          bool picture) {
  return "step " + std::to_string(k) + "/" + std::to_string(steps) + ", t = " + three_digits(t) + " s: " +
         std::to_string(cut_triangles(step)) + " cut triangles, " +
         std::to_string(step.counts.partial + step.counts.complete) + " cut tets, " +
         std::to_string(step.enriched_dofs) + " enriched DOFs; solved in " + three_digits(times.solved) +
         " s (classify " + three_digits(step.classify_seconds) + ", enrich " + three_digits(step.enrich_seconds) +
         ", assemble " + three_digits(step.assemble_seconds) +
         (incremental ? ", incremental Schur " : step.schur_used ? ", Schur " : ", refactorization ") +
         three_digits(step.solve_seconds) + "), back-substitution " + three_digits(step.back_substitution_seconds) +
         " s, frame written in " + three_digits(times.written) + " s" +
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
          {"enrich_seconds", step.enrich_seconds},
          {"back_substitution_seconds", step.back_substitution_seconds},
          {"split", split_json(step_split(step, times))},
          {"assemble_seconds", step.assemble_seconds},
          {"solver", incremental ? "incremental" : step.schur_used ? "schur" : "refactor"},
          {"recomputed_tets", step.recomputed_tets},
          {"reused_columns", step.reused_columns},
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
