// manifuzz explain [--generator G] FILE: one case as a worked example.
#include <cmath>
#include <iostream>
#include <sstream>

#include "case_property.h"
#include "harness/case_run.h"
#include "oracles/minkowski_difference.h"
#include "cli/arguments.h"
#include "case_pictures.h"
#include "cli/program_files.h"
#include "generator/clipping_generator.h"
#include "harness/report.h"

namespace mfz::cli {
namespace {

void describe_hull(std::ostream& out, char name, const Hull& hull, const Pose& pose) {
  out << "  hull " << name << ": " << hull.vertex_count() << " vertices, " << hull.face_count() << " faces, "
      << hull.edge_count() << " edges, diameter " << hull.diameter() << "\n"
      << "          at " << vec_text(pose.position) << ", orientation (w x y z) " << pose.orientation.w() << " "
      << pose.orientation.x() << " " << pose.orientation.y() << " " << pose.orientation.z() << "\n";
}

std::string feature_text(const RankedAxis& axis) {
  std::ostringstream s;
  if (axis.kind == AxisKind::face_a) s << "normal of A's face " << axis.feature_a;
  if (axis.kind == AxisKind::face_b) s << "normal of B's face " << axis.feature_b;
  if (axis.kind == AxisKind::edge_edge) s << "A's edge " << axis.feature_a << " x B's edge " << axis.feature_b;
  return s.str();
}

void describe_sat(std::ostream& out, const CaseRun& run) {
  out << "\n1. Separating axes (brute force: every face normal and edge pair). The three best:\n";
  const auto& axes = run.oracles.sat_axes;
  for (size_t k = 0; k < axes.size() && k < 3; ++k)
    out << "     overlap " << axes[k].overlap << " along " << vec_text(axes[k].normal) << "  (" << feature_text(axes[k])
        << ")\n";
  if (!axes.empty() && axes[0].overlap < 0)
    out << "   An axis with negative overlap separates the hulls: no collision.\n";
  if (run.oracles.axis_tie)
    out << "   Two different axes tie for the least overlap: a correct generator may pick either.\n";
}

void describe_polygon(std::ostream& out, const std::vector<Vec3>& polygon) {
  for (const Vec3& p : polygon) out << "        " << vec_text(p) << "\n";
  if (polygon.empty()) out << "        (empty)\n";
}

void describe_clipping(std::ostream& out, const CaseRun& run) {
  ClipTrace trace;
  mfz_manifold manifold;
  const mfz_hull a = run.scene.hull_a.view(), b = run.scene.hull_b.view();
  generate_clipping_manifold(a, run.scene.abi_pose_a(), b, run.scene.abi_pose_b(), manifold, &trace);
  const SatResult& sat = trace.sat;
  out << "\n2. The built-in generator's SAT picks " << axis_kind_name(sat.kind) << " (A feature " << sat.feature_a
      << ", B feature " << sat.feature_b << "):\n     n = " << vec_text(sat.normal) << " (from A to B), "
      << (sat.separated ? "separating overlap " : "depth ") << sat.depth << "\n";
  if (trace.edge_contact && sat.kind == AxisKind::edge_edge) {
    out << "   An edge-edge axis: the contact is the closest pair of points of the edge of A furthest along n\n"
        << "   and the edge of B furthest along -n (FINDINGS.md F3); no faces are clipped.\n";
    return;
  }
  // A face axis whose clipping left nothing below the reference face: the
  // supporting edges gave the contact (F16). Said as an edge-edge axis, it
  // read as though SAT had picked one (stop 68, F62's case under rigid-motion).
  if (trace.edge_contact)
    out << "   Clipping left no point below the reference face (the edges cross just beyond it, FINDINGS.md F16):\n"
        << "   the contact is the closest pair of points of the edges supporting A along n and B along -n.\n";
  if (sat.separated || trace.face_a < 0) {
    out << "   No penetration, so no contacts.\n";
    return;
  }
  const Vec3 na = run.scene.pose_a.rotate(run.scene.hull_a.face_normal(trace.face_a));
  const Vec3 nb = run.scene.pose_b.rotate(run.scene.hull_b.face_normal(trace.face_b));
  out << "\n3. Significant faces: on a face axis the SAT face; otherwise, of the faces holding the most of the\n"
      << "   vertices furthest along n, the one most parallel to it.\n"
      << "     A: vertex " << trace.support_a << ", face " << trace.face_a << " with normal " << vec_text(na)
      << ", |n . normal| = " << std::abs(sat.normal.dot(na)) << "\n"
      << "     B (along -n): vertex " << trace.support_b << ", face " << trace.face_b << " with normal " << vec_text(nb)
      << ", |n . normal| = " << std::abs(sat.normal.dot(nb)) << "\n"
      << "   The reference face (the SAT face, or the more parallel one): " << (trace.flipped ? "B's" : "A's") << " face "
      << (trace.flipped ? trace.face_b : trace.face_a) << "; the incident face is " << (trace.flipped ? "A's" : "B's")
      << " face " << (trace.flipped ? trace.face_a : trace.face_b) << (trace.flipped ? " (flipped)" : "") << ".\n";
  out << "\n4. Sutherland-Hodgman clipping of each equally aligned incident face against the sides of the\n"
      << "   prism over the reference face (the largest coplanar patch around it), then removal of the\n"
      << "   points above the reference plane:\n";
  for (size_t k = 0; k < trace.steps.size(); ++k) {
    out << "     step " << k << ": " << trace.steps[k].what << " (" << trace.steps[k].polygon.size() << " points)\n";
    describe_polygon(out, trace.steps[k].polygon);
  }
}

void describe_oracles(std::ostream& out, const CaseRun& run) {
  const OracleAnswers& o = run.oracles;
  out << "\n6. Oracles:\n"
      << "     exact (least overlap over every axis; the hulls' distance when apart): "
      << (o.exact.colliding ? "depth " : "gap ") << std::abs(o.exact.signed_depth) << ", direction "
      << vec_text(o.exact.normal) << (o.touching ? "  (touching: within tolerance of zero)" : "") << "\n";
  std::string error;
  if (const auto difference = MinkowskiDifference::build(run.scene.world_a, run.scene.world_b, error)) {
    const ExactDepth qhull = difference->at_origin();
    out << "     Qhull's A - B (hull of the vertex differences): ";
    if (qhull.colliding)
      out << "depth " << qhull.signed_depth << "\n";
    else
      out << "origin outside\n";
  } else {
    out << "     Qhull's A - B: " << error << "\n";
  }
  out
      << "     libccd GJK: " << (o.ccd.gjk_intersecting ? "intersecting" : "separate") << "\n";
  if (o.ccd.epa_ok) out << "     libccd EPA: depth " << o.ccd.epa_depth << " along " << vec_text(o.ccd.epa_direction) << "\n";
  const LibccdAnswer with_mpr = ask_libccd(run.scene, /*with_mpr=*/true);
  if (with_mpr.mpr_ok)
    out << "     libccd MPR: depth " << with_mpr.mpr_depth << " along " << vec_text(with_mpr.mpr_direction) << "\n";
}

bool named_relation(const CaseFile& c) {
  for (const std::string& line : c.extensions)
    if (line.rfind("relation ", 0) == 0) return true;
  return false;
}

}  // namespace

// The manifold and verdict come from the one pipeline (a plugin in its
// worker, a relation finding's relation replayed); the narration of the
// built-in's steps re-runs the built-in in process with a trace.
int explain_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words, {"--generator", "--call-timeout", "--profile", "--render"}, {"--strict"}, error);
  if (!args || args->positional.size() != 1) {
    std::cerr << "manifuzz explain: " << (args ? "expected exactly one case file" : error)
              << " (usage: manifuzz explain [--generator G] [--strict] [--profile P] [--render DIR] FILE)\n";
    return kExitInputError;
  }
  const std::string spec = resolve_generator(args->get("--generator", "builtin"));
  std::unique_ptr<GeneratorSession> session = nullptr;
  if (const auto timeout = call_timeout(*args, error)) session = open_session(spec, *timeout, error);
  if (!session) {
    std::cerr << "manifuzz explain: " << error << "\n";
    return kExitInputError;
  }
  const std::string& file = args->positional[0];
  const CaseParse parsed = read_case_file(file);
  props::Selection selection;
  if (args->has("--strict")) selection.level = props::Level::strict;
  if (!apply_profile(*args, *session, selection, error)) {
    std::cerr << "manifuzz explain: " << error << "\n";
    return kExitInputError;
  }
  selection.keep_transformed_run = args->options.count("--render") > 0;
  std::optional<props::CaseOutcome> outcome;
  if (parsed.value) outcome = props::check_case(*parsed.value, *session, selection);
  if (!parsed.value || outcome->invalid) {
    std::cerr << "manifuzz explain: " << (parsed.value ? file + ": " + outcome->invalid_reason : parsed.error) << "\n";
    return kExitInputError;
  }
  // --render DIR: the pictures beside the text, DIR/STEM.svg and .html.
  if (args->options.count("--render")) {
    const std::string dir = args->get("--render", "");
    const std::vector<CasePicture> runs = props::pictures_of_outcome(*parsed.value, *outcome, session->name());
    if (!props::write_case_pictures(dir, props::file_stem(file), runs, "manifuzz explain: " + file, error)) {
      std::cerr << "manifuzz explain: " << error << "\n";
      return kExitInputError;
    }
  }
  SceneBuild built = make_scene(*parsed.value);
  const OracleAnswers oracles = consult_oracles(*built.scene);
  const props::Finding* finding = outcome->finding ? &*outcome->finding : nullptr;
  std::ostream& out = std::cout;
  out << "Case " << file << "\n";
  for (const std::string& line : parsed.value->extensions) out << "  " << printable(line, 4096) << "\n";
  if (!outcome->manifold) {
    out << "\nThe generator " << session->name() << " gave no answer: " << finding->name << " (" << finding->detail
        << ").\n";
    return kExitViolation;
  }
  const CaseRun run{std::move(*built.scene), *outcome->manifold, oracles, *outcome->verdict};
  describe_hull(out, 'A', run.scene.hull_a, run.scene.pose_a);
  describe_hull(out, 'B', run.scene.hull_b, run.scene.pose_b);
  out << "  L (scale of the case, the larger diameter) = " << run.scene.scale
      << "; tolerances below are in units of L\n";
  describe_sat(out, run);
  if (spec == "builtin") describe_clipping(out, run);
  else out << "\n2-4. " << session->name() << " is a plugin: its steps are not visible, only its answer.\n";
  out << "\n5. The manifold (" << session->name() << "):\n" << manifold_text(run.manifold, "     ");
  describe_oracles(out, run);
  out << "\n7. Invariants:\n" << verdict_text(run.verdict, "     ");
  if (run.verdict.refused()) out << "\nVerdict: the generator refused this case.\n";
  else if (finding)
    out << "\nVerdict: " << finding->name << " fails: " << finding->detail << ".\n";
  else out << "\nVerdict: every invariant holds" << (named_relation(*parsed.value) ? ", and so does the case's relation" : "")
           << ".\n";
  return finding ? kExitViolation : kExitClean;
}

}  // namespace mfz::cli
