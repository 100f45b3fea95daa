#include "case_property.h"

#include <cmath>
#include <cstdio>

#include "geometry/tolerances.h"
#include "relations.h"

namespace mfz::props {

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

namespace {

// The case's `profile` line, read whole (it replaces the selection's); the
// selection's own when the line is absent or --profile gave one.
std::optional<Profile> profile_of(const CaseFile& c, const Selection& selection, std::string& error) {
  if (selection.profile_from_command_line) return selection.profile;
  for (const std::string& line : c.extensions)
    if (line.rfind("profile ", 0) == 0) {
      auto p = parse_profile(line.substr(8), error);
      if (!p) error = "profile line: " + error.substr(error.find(' ') + 1);
      return p;
    }
  return selection.profile;
}

Level level_of(const CaseFile& c, Level asked) {
  for (const std::string& line : c.extensions)
    if (line == "level strict") return Level::strict;
  return asked;
}

}  // namespace

std::vector<std::string> replay_lines(const Finding& f, const Selection& selection) {
  std::vector<std::string> lines;
  if (!f.relation_line.empty()) lines.push_back(f.relation_line);
  if (selection.level == Level::strict) lines.push_back("level strict");
  if (!selection.profile.empty()) lines.push_back("profile " + selection.profile.text());
  return lines;
}

CaseOutcome check_case(const CaseFile& c, GeneratorSession& generator, const Selection& selection) {
  CaseOutcome outcome;
  std::string relation_error;
  const std::optional<RelationCall> named = relation_in(c, relation_error);
  std::string profile_error;
  const std::optional<Profile> profile = profile_of(c, selection, profile_error);
  if (!profile && relation_error.empty()) relation_error = profile_error;
  SceneBuild built = make_scene(c);
  if (profile) outcome.profile = *profile;
  if (!built.scene || !relation_error.empty()) {
    outcome.invalid = true;
    outcome.invalid_reason = built.scene ? relation_error : built.error;
    return outcome;
  }
  Scene& scene = *built.scene;
  scene.precision_epsilon = profile->precision_epsilon;
  if (scene.precision_rounding() > tol::kProfileFarthestFrame * scene.scale) {
    outcome.invalid = true;
    char why[200];
    std::snprintf(why, sizeof why,
                  "the case lies %.3g L from the origin, where the profile's precision resolves only %.3g L (past %g L)",
                  scene.world_extent / scene.scale, scene.precision_rounding() / scene.scale,
                  tol::kProfileFarthestFrame);
    outcome.invalid_reason = why;
    return outcome;
  }
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
  // Made in place: a copy of the verdict was ten allocations a case.
  const Verdict& verdict = outcome.verdict.emplace(check_manifold(
      scene, oracles, status, manifold, *profile, selection.pass_details ? PassDetails::written : PassDetails::left_out));
  outcome.manifold = manifold;
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
  TransformedRun kept;
  const RelationInput input{c, scene, manifold, oracles, level_of(c, selection.level), *profile,
                            selection.keep_transformed_run ? &kept : nullptr};
  for (const std::string& name : relation_names()) {
    if (named ? name != named->name : !selection.wants(name)) continue;
    if (auto finding = check_relation(name, input, generator, named ? &named->numbers : nullptr)) {
      if (finding->name == kInterrupted) outcome.interrupted = true;
      else outcome.finding = finding;
      if (selection.keep_transformed_run && !kept.relation.empty()) outcome.transformed = std::move(kept);
      return outcome;
    }
  }
  return outcome;
}

}  // namespace mfz::props
