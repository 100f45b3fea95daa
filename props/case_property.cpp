#include "case_property.h"

#include <cmath>
#include <cstdio>

#include "relations.h"

namespace mfz::props {
namespace {

CaseTags tags_of(const Scene& s, const OracleAnswers& o, const mfz_manifold& m) {
  CaseTags tags;
  tags.touching = o.touching;
  tags.tie = o.ties.any();
  tags.contact_count = m.contact_count;
  tags.depth_over_l = o.exact.signed_depth / s.scale;
  if (!o.exact.colliding) tags.contact_kind = "separated";
  else if (!o.sat_axes.empty() && o.sat_axes[0].kind == AxisKind::edge_edge) tags.contact_kind = "edge-edge";
  else if (m.contact_count >= 3) tags.contact_kind = "face-face";
  else if (m.contact_count == 2) tags.contact_kind = "edge-face";
  else if (m.contact_count == 1) tags.contact_kind = "vertex-face";
  else tags.contact_kind = "no-contacts";
  return tags;
}

Level level_of(const CaseFile& c, Level asked) {
  for (const std::string& line : c.extensions)
    if (line == "level strict") return Level::strict;
  return asked;
}

}  // namespace

std::vector<std::string> replay_lines(const Finding& f, Level level) {
  std::vector<std::string> lines;
  if (!f.relation_line.empty()) lines.push_back(f.relation_line);
  if (level == Level::strict) lines.push_back("level strict");
  return lines;
}

CaseOutcome check_case(const CaseFile& c, GeneratorSession& generator, const Selection& selection) {
  CaseOutcome outcome;
  std::string relation_error;
  const std::optional<RelationCall> named = relation_in(c, relation_error);
  SceneBuild built = make_scene(c);
  if (!built.scene || !relation_error.empty()) {
    outcome.invalid = true;
    outcome.invalid_reason = built.scene ? relation_error : built.error;
    return outcome;
  }
  const Scene& scene = *built.scene;
  outcome.scale = scene.scale;
  const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
  const mfz_pose pa = scene.abi_pose_a(), pb = scene.abi_pose_b();
  mfz_manifold manifold;
  int32_t status = 0;
  std::string failure;
  const CallOutcome call = generator.generate(a, pa, b, pb, manifold, status, failure);
  if (call == CallOutcome::interrupted) {
    outcome.interrupted = true;
    return outcome;
  }
  if (call != CallOutcome::done) {
    outcome.finding = Finding{call == CallOutcome::crashed ? "crash" : "hang", failure, {}};
    return outcome;
  }
  const OracleAnswers oracles = consult_oracles(scene);
  const Verdict verdict = check_manifold(scene, oracles, status, manifold);
  outcome.manifold = manifold;
  outcome.verdict = verdict;
  outcome.tags = tags_of(scene, oracles, manifold);
  if (verdict.refused()) {
    outcome.finding = Finding{"refused", "status " + std::to_string(status), {}};
    return outcome;
  }
  for (const InvariantCheck& check : verdict.checks)
    if (check.status == CheckStatus::fail && selection.wants(check.name)) {
      char margin[96];
      std::snprintf(margin, sizeof margin, " (error %.3g L, tol %.3g L)", check.error, check.tolerance);
      outcome.finding = Finding{check.name, check.detail + margin, {}, check.error, check.tolerance};
      return outcome;
    }
  // Relations only make sense on a manifold that is itself right.
  if (verdict.first_violation()) return outcome;
  const RelationInput input{c, scene, manifold, oracles, level_of(c, selection.level)};
  for (const std::string& name : relation_names()) {
    if (named ? name != named->name : !selection.wants(name)) continue;
    if (auto finding = check_relation(name, input, generator, named ? &named->numbers : nullptr)) {
      if (finding->name == kInterrupted) outcome.interrupted = true;
      else outcome.finding = finding;
      return outcome;
    }
  }
  return outcome;
}

}  // namespace mfz::props
