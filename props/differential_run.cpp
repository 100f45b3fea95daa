#include "differential_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <ostream>

#include "case_property.h"
#include "case_shrinker.h"
#include "families.h"
#include "finding_file.h"
#include "geometry/tolerances.h"
#include "harness/interruption.h"
#include "oracles/brute_force_sat.h"
#include "oracles/contact_region.h"
#include "oracles/oracle_answers.h"

namespace mfz::props {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Budget for minimising the first case of each kind.
constexpr double kShrinkSeconds = 30;

const char* const kFirst = "first";
const char* const kSecond = "second";

Vec3 vec(const mfz_vec3& v) { return {v.x, v.y, v.z}; }

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

/// Whose answer the oracles confirm, from whether each is right.
std::string sides_with(bool first_right, bool second_right) {
  if (first_right && second_right) return "both";
  if (first_right) return kFirst;
  return second_right ? kSecond : "neither";
}

/// How far one side's depth may stray from the exact depth under its
/// profile: the contract's depth tolerance with its precision's rounding
/// (`scene` set to that precision), its face bias and its margin.
double depth_allowance(const Scene& scene, const Profile& p, double exact_depth) {
  return scene.length_tolerance(tol::kDepth) + p.face_bias * std::max(0.0, exact_depth) + p.margin * scene.scale;
}

/// How far apart two unit normals may be under one side's profile: the
/// relations' tolerance and 64 ulps of its precision over the shortest edge.
double normal_allowance(const Profile& p) { return tol::kRelationNormal + tol::kWorldUlps * p.precision_epsilon; }

/// The contacts' midpoints, projected onto the plane perpendicular to n.
std::vector<Eigen::Vector2d> projected_contacts(const mfz_manifold& m, const Vec3& n) {
  Vec3 u, v;
  plane_basis(n, u, v);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < m.contact_count; ++i) {
    const Vec3 mid = 0.5 * (vec(m.contacts[i].point_on_a) + vec(m.contacts[i].point_on_b));
    points.emplace_back(mid.dot(u), mid.dot(v));
  }
  return points;
}

/// The greatest distance of a point of `points` outside the hull of `hull`.
double farthest_outside(const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector2d>& hull) {
  double worst = 0;
  for (const auto& p : points) worst = std::max(worst, distance_to_convex_hull_2d(p, hull));
  return worst;
}

/// Whether a side's own verdict (under its own profile) passes the named
/// checks: the oracles confirm its answer there.
bool passes(const Verdict& v, std::initializer_list<const char*> names) {
  for (const InvariantCheck& c : v.checks)
    for (const char* name : names)
      if (c.name == name && c.status == CheckStatus::fail) return false;
  return true;
}

/// Whether a side reduces: a profile's max-contacts reached.
bool reduced(const mfz_manifold& m, const Profile& p) {
  return p.max_contacts > 0 && m.contact_count >= p.max_contacts;
}

/// One side's answer, judged under its own profile.
struct Answer {
  mfz_manifold m;
  const Profile* profile;
  Verdict verdict;         ///< the invariants: whose answer the oracles confirm
  double depth_allowance;  ///< depth_allowance at this side's precision
};

// ---- the four comparisons, in order; each returns a disagreement or nothing ----

std::optional<Disagreement> compare_colliding(const Scene& scene, const OracleAnswers& o, const Answer& a1,
                                              const Answer& a2) {
  const mfz_manifold &m1 = a1.m, &m2 = a2.m;
  if (m1.colliding == m2.colliding || o.touching) return std::nullopt;
  // Within either margin the hulls may be reported colliding before they touch.
  const double gap = -o.exact.signed_depth;
  if (!o.exact.colliding && gap <= std::max(a1.profile->margin, a2.profile->margin) * scene.scale) return std::nullopt;
  const bool truth = o.exact.colliding;
  return Disagreement{"colliding",
                      format("first says %g, second %g; the exact oracle %g,", m1.colliding, m2.colliding, truth) +
                          format(" depth %.3g L", o.exact.signed_depth / scene.scale),
                      sides_with((m1.colliding == 1) == truth, (m2.colliding == 1) == truth)};
}

std::optional<Disagreement> compare_depth(const Scene& scene, const OracleAnswers& o, const Answer& a1,
                                          const Answer& a2) {
  const double exact = o.exact.signed_depth;
  const double allowed = a1.depth_allowance + a2.depth_allowance;
  const double d1 = -a1.m.penetration, d2 = -a2.m.penetration;
  if (std::abs(d1 - d2) <= allowed) return std::nullopt;
  return Disagreement{"depth",
                      format("first %.6g, second %.6g, exact %.6g", d1, d2, exact) +
                          format(" (differ by %.3g L, both profiles allow %.3g L)", std::abs(d1 - d2) / scene.scale,
                                 allowed / scene.scale),
                      sides_with(passes(a1.verdict, {"depth-exact"}), passes(a2.verdict, {"depth-exact"}))};
}

std::optional<Disagreement> compare_normal(const Scene& scene, const OracleAnswers& o, const Answer& a1,
                                           const Answer& a2) {
  const Vec3 n1 = vec(a1.m.normal).normalized(), n2 = vec(a2.m.normal).normalized();
  const double angle = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
  if (angle <= normal_allowance(*a1.profile) + normal_allowance(*a2.profile)) return std::nullopt;
  // Where the geometry does not decide the direction (two axes of least
  // overlap, or the reverse of the best), either normal is right; the depth
  // comparison has already held.
  if (o.ties.direction) return std::nullopt;
  const double exact = o.exact.signed_depth;
  const auto right = [](const Verdict& v) { return passes(v, {"normal-realises-depth", "normal-agrees-with-epa"}); };
  return Disagreement{
      "normal",
      format("%.3g rad apart", angle) +
          format("; overlap along the first %.6g, the second %.6g", directed_overlap(scene.world_a, scene.world_b, n1),
                 directed_overlap(scene.world_a, scene.world_b, n2)) +
          format(", exact %.6g", exact),
      sides_with(right(a1.verdict), right(a2.verdict))};
}

// The contacts' hulls on the contact plane: each must hold the other's
// points (a side that reduced to its max-contacts need only lie inside the
// other's). The region itself (the hulls' intersection, from the oracles)
// says whose hull is right: the one that encloses its centroid.
std::optional<Disagreement> compare_region(const Scene& scene, const OracleAnswers& o, const Answer& a1,
                                           const Answer& a2) {
  const mfz_manifold &m1 = a1.m, &m2 = a2.m;
  if (m1.contact_count < 1 || m2.contact_count < 1 || !o.face_contact) return std::nullopt;
  const Vec3 n = vec(m1.normal).normalized();
  const auto p1 = projected_contacts(m1, n), p2 = projected_contacts(m2, n);
  // `scene` holds the coarser of the two precisions.
  const double slack = tol::kRegionPoint * scene.scale +
                       std::max(a1.profile->margin, a2.profile->margin) * scene.scale + scene.precision_rounding();
  const double first_outside = reduced(m2, *a2.profile) ? 0 : farthest_outside(p1, p2);
  const double second_outside = reduced(m1, *a1.profile) ? 0 : farthest_outside(p2, p1);
  if (std::max(first_outside, second_outside) <= slack) return std::nullopt;
  const ContactRegion region = contact_region(scene, n, Vec3::Zero(), tol::kRegionSlack * scene.scale);
  const auto right = [](const Verdict& v) {
    return passes(v, {"spans-contact-region", "within-both-hulls", "on-surface"});
  };
  const double area = scene.scale * scene.scale;
  return Disagreement{
      "contact-region",
      format("%g and %g contacts, areas %.3g L^2", m1.contact_count, m2.contact_count, convex_hull_area_2d(p1) / area) +
          format(" and %.3g L^2; the first's reach %.3g L outside the second's hull, the second's %.3g L "
                 "outside the first's",
                 convex_hull_area_2d(p2) / area, first_outside / scene.scale, second_outside / scene.scale) +
          format("; the region's area %.3g L^2", region.empty ? 0.0 : convex_hull_area_2d(region.corners) / area),
      sides_with(right(a1.verdict), right(a2.verdict))};
}

/// One generator's answer, or why there is none.
std::optional<Disagreement> call(DiffSide& side, const char* which, const Scene& scene, mfz_manifold& m) {
  const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
  const mfz_pose pa = scene.abi_pose_a(), pb = scene.abi_pose_b();
  int32_t status = 0;
  std::string failure;
  const CallOutcome outcome = side.session->generate(a, pa, b, pb, m, status, failure);
  if (outcome == CallOutcome::done && status == 0) return std::nullopt;
  if (outcome == CallOutcome::interrupted) return Disagreement{kInterrupted, "", ""};
  const std::string kind = outcome == CallOutcome::crashed ? "crash"
                           : outcome == CallOutcome::hung  ? "hang"
                                                           : "refused";
  const bool first = std::string(which) == kFirst;
  return Disagreement{
      kind,
      std::string("the ") + which + " generator: " + (kind == "refused" ? "status " + std::to_string(status) : failure),
      first ? kSecond : kFirst};
}

}  // namespace

const std::vector<std::string>& disagreement_kinds() {
  static const std::vector<std::string> kinds = {"colliding", "depth", "normal", "contact-region"};
  return kinds;
}

std::optional<Disagreement> compare_generators(const CaseFile& c, DiffSide& first, DiffSide& second, bool& invalid,
                                               RunStatistics* statistics) {
  invalid = false;
  SceneBuild built = make_scene(c);
  if (!built.scene) {
    invalid = true;
    return std::nullopt;
  }
  Scene& scene = *built.scene;
  // Past what the coarser precision resolves, neither answer is promised.
  scene.precision_epsilon = std::max(first.profile.precision_epsilon, second.profile.precision_epsilon);
  if (scene.precision_rounding() > tol::kProfileFarthestFrame * scene.scale) {
    invalid = true;
    return std::nullopt;
  }
  Answer a1{{}, &first.profile, {}, 0}, a2{{}, &second.profile, {}, 0};
  if (auto none = call(first, kFirst, scene, a1.m)) return none;
  if (auto none = call(second, kSecond, scene, a2.m)) return none;
  const OracleAnswers oracles = consult_oracles(scene);
  // Each answer judged by the invariants under its own profile (the scene
  // at that profile's precision): whose answer the oracles confirm.
  const double coarser = scene.precision_epsilon;
  for (Answer* a : {&a1, &a2}) {
    scene.precision_epsilon = a->profile->precision_epsilon;
    a->verdict = check_manifold(scene, oracles, 0, a->m, *a->profile);
    a->depth_allowance = depth_allowance(scene, *a->profile, oracles.exact.signed_depth);
  }
  scene.precision_epsilon = coarser;
  if (statistics) {
    statistics->count("contact kind", tags_of(scene, oracles, a1.m).contact_kind);
    statistics->add_verdict(a1.verdict, "first: ");
    statistics->add_verdict(a2.verdict, "second: ");
  }
  if (auto d = compare_colliding(scene, oracles, a1, a2)) return d;
  if (!a1.m.colliding || !a2.m.colliding || !oracles.exact.colliding) return std::nullopt;
  if (auto d = compare_depth(scene, oracles, a1, a2)) return d;
  if (auto d = compare_normal(scene, oracles, a1, a2)) return d;
  return compare_region(scene, oracles, a1, a2);
}

namespace {

// The first case of a kind, minimised while the same kind of disagreement
// holds, written with what reproduces it.
std::string write_example(const DiffOptions& options, const DiffResult& result, CaseFile file, const Disagreement& d,
                          DiffSide& first, DiffSide& second, std::string& error) {
  shrink_case_file(
      file,
      [&](const CaseFile& candidate) {
        bool invalid = false;
        const auto again = compare_generators(candidate, first, second, invalid);
        return !invalid && again && again->kind == d.kind && again->sides_with != "both";
      },
      kShrinkSeconds);
  bool invalid = false;
  const auto final_answer = compare_generators(file, first, second, invalid);
  const Disagreement shown = final_answer && final_answer->kind == d.kind ? *final_answer : d;
  std::string text;
  Selection selection;
  const Finding finding{"diff-" + d.kind, shown.detail + "; the oracles side with " + shown.sides_with, {}};
  return write_finding(options.out_dir, file, finding, selection,
                       {"found by: manifuzz diff --generator " + options.generator + " --against " + options.against +
                            " --seed " + std::to_string(options.seed),
                        "first: " + result.first_name + " (profile " + result.first_profile.text() +
                            "), second: " + result.second_name + " (profile " + result.second_profile.text() + ")"},
                       text, error);
}

}  // namespace

std::optional<DiffResult> run_diff(const DiffOptions& options, std::ostream& log, std::string& error) {
  std::signal(SIGXFSZ, SIG_IGN);
  if (!prepare_out_dir(options.out_dir, error)) return std::nullopt;
  auto one = open_session(options.generator, options.call_timeout, error);
  if (!one) return std::nullopt;
  auto two = open_session(options.against, options.call_timeout, error);
  if (!two) return std::nullopt;
  const auto p1 = profile_in_force(one->declared_profile(), options.profile_override, error);
  if (!p1) return std::nullopt;
  const auto p2 = profile_in_force(two->declared_profile(), options.against_profile_override, error);
  if (!p2) return std::nullopt;
  DiffSide first{one.get(), *p1}, second{two.get(), *p2};
  DiffResult result;
  result.first_name = one->name();
  result.second_name = two->name();
  result.first_profile = *p1;
  result.second_profile = *p2;
  catch_interruptions();
  log << "manifuzz diff: " << result.first_name << " (profile " << p1->text() << ") against " << result.second_name
      << " (profile " << p2->text() << "), seed " << options.seed << "\n";
  const double precision = std::max(p1->precision_epsilon, p2->precision_epsilon);
  const double farthest = precision > 0 ? tol::kProfileFarthestFrame / (tol::kWorldUlps * precision)
                                        : std::numeric_limits<double>::infinity();
  const auto gen = any_case(farthest, options.hull_families);
  rc::Random random(options.seed);
  const auto started = Clock::now();
  double last_progress = 0, last_sample = 0;
  result.statistics.sample(0, 0);
  for (long long index = 0;; ++index) {
    if (options.cases && result.cases >= *options.cases) break;
    if (options.seconds && since(started) >= *options.seconds) break;
    if (interrupted()) break;
    const GeneratedCase generated = gen(random.split(), static_cast<int>(index % 100)).value();
    bool invalid = false;
    const auto d = compare_generators(generated.file, first, second, invalid, &result.statistics);
    if (invalid) {
      ++result.invalid;
      continue;
    }
    if (d && d->kind == kInterrupted) break;
    ++result.cases;
    result.statistics.count("hull family A", generated.hull_a);
    result.statistics.count("placement", generated.placement);
    result.statistics.count("outcome", !d ? "agree" : d->sides_with == "both" ? "tie (both confirmed)" : d->kind);
    if (d && d->sides_with != "both") result.statistics.count("the oracles side with", d->sides_with);
    if (!d) {
      ++result.agreeing;
    } else if (d->sides_with == "both") {
      // Both answers are right: the geometry does not decide between them.
      ++result.ties;
    } else {
      KindTally& tally = result.kinds[d->kind];
      ++tally.cases;
      ++tally.sides_with[d->sides_with];
      if (tally.example_path.empty()) {
        tally.example_detail = d->detail;
        tally.example_path = write_example(options, result, generated.file, *d, first, second, error);
        if (tally.example_path.empty()) return std::nullopt;
        log << "  " << d->kind << " at case " << index << ": " << d->detail << "; the oracles side with "
            << d->sides_with << " (" << tally.example_path << ")\n";
      }
    }
    const double now = since(started);
    if (now - last_sample >= 1) last_sample = now, result.statistics.sample(now, result.cases);
    if (options.progress_every > 0 && now - last_progress >= options.progress_every) {
      last_progress = now;
      log << "  " << result.cases << " cases, " << result.cases - result.agreeing - result.ties << " disagreeing\n";
    }
  }
  result.seconds = since(started);
  result.statistics.sample(result.seconds, result.cases);
  result.interrupted = interrupted();
  release_interruptions();
  return result;
}

void print_diff_summary(const DiffResult& r, std::ostream& out) {
  long long disagreeing = 0;
  for (const auto& row : r.kinds) disagreeing += row.second.cases;
  out << "manifuzz diff: " << r.cases << " cases in " << std::setprecision(3) << r.seconds << " s ("
      << static_cast<long long>(r.cases / std::max(r.seconds, 1e-9)) << " cases/s), " << r.invalid
      << " invalid inputs discarded\n"
      << "  first:  " << r.first_name << " (profile " << r.first_profile.text() << ")\n"
      << "  second: " << r.second_name << " (profile " << r.second_profile.text() << ")\n"
      << "  " << r.agreeing << " agree; " << r.ties << " differ where the oracles confirm both (a tie); " << disagreeing
      << " disagree:\n";
  if (r.kinds.empty()) return;
  out << "  " << std::left << std::setw(16) << "disagreement" << std::right << std::setw(7) << "cases"
      << "   oracles side with:" << std::setw(7) << "first" << std::setw(8) << "second" << std::setw(9) << "neither"
      << "   minimised case\n";
  for (const auto& row : r.kinds) {
    const std::string& kind = row.first;
    const KindTally& t = row.second;
    const auto n = [&](const char* who) {
      const auto found = t.sides_with.find(who);
      return found == t.sides_with.end() ? 0LL : found->second;
    };
    out << "  " << std::left << std::setw(16) << kind << std::right << std::setw(7) << t.cases << std::setw(26)
        << n(kFirst) << std::setw(8) << n(kSecond) << std::setw(9) << n("neither") << "   " << t.example_path << "\n";
  }
}

}  // namespace mfz::props
