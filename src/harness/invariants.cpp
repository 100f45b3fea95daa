#include "harness/invariants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/closest_point.h"
#include "geometry/hull_distance.h"
#include "geometry/posed_hull.h"
#include "oracles/contact_region.h"
#include "oracles/exact_depth.h"
#include "geometry/tolerances.h"

namespace mfz {

const char* status_name(CheckStatus status) {
  switch (status) {
    case CheckStatus::pass: return "pass";
    case CheckStatus::fail: return "FAIL";
    case CheckStatus::skipped: return "skipped";
    case CheckStatus::oracle_disagreement: return "oracle disagreement";
  }
  return "?";
}

int contact_named_in(const std::string& detail) {
  const size_t at = detail.rfind("(contact ");
  if (at == std::string::npos) return -1;
  int contact = -1;
  char close = 0;
  if (std::sscanf(detail.c_str() + at, "(contact %d%c", &contact, &close) != 2 || close != ')') return -1;
  return contact;
}

const InvariantCheck* Verdict::first_violation() const {
  for (const InvariantCheck& c : checks)
    if (c.status == CheckStatus::fail) return &c;
  return nullptr;
}

bool Verdict::has_oracle_disagreement() const {
  return std::any_of(checks.begin(), checks.end(),
                     [](const InvariantCheck& c) { return c.status == CheckStatus::oracle_disagreement; });
}

namespace {

// What every check reads: the case, the oracles and the manifold in Eigen form.
struct Context {
  const Scene& scene;
  const OracleAnswers& oracles;
  const mfz_manifold& m;
  const Profile& profile;
  double L;
  Vec3 n;
  double depth;  // -penetration
  bool colliding;
  /// Whether a passing check describes itself. Only a failure's detail is
  /// read by the property suite and the relations, and formatting each
  /// pass's numbers was a twentieth of a property case.
  bool pass_details = true;

  double relative(double length) const { return length / L; }
  Vec3 on_a(int i) const { return to_vec(m.contacts[i].point_on_a); }
  Vec3 on_b(int i) const { return to_vec(m.contacts[i].point_on_b); }
  /// The profile's margin as a length (0 without one).
  double margin() const { return profile.margin * L; }
  /// Separated in truth, but within the profile's margin: a margin engine
  /// reports such a case as colliding with a positive penetration.
  bool within_margin() const { return separated_within_margin(scene, oracles, profile); }
  /// n is a face axis (of A, or of B reversed), which face-bias lets exceed
  /// the exact depth by up to its fraction.
  bool biased_face_axis() const;
  /// How much deeper than the exact depth face-bias lets a face axis be.
  double face_bias_allowance() const {
    return biased_face_axis() ? profile.face_bias * std::max(0.0, oracles.exact.signed_depth) : 0;
  }
  /// Contact i's signed distance from its point on A to A's surface; and
  /// from its point on B to B's. Both on-surface and within-both-hulls ask,
  /// so each is measured once.
  double own_distance_a(int i) const { return own_distances(i)[0]; }
  double own_distance_b(int i) const { return own_distances(i)[1]; }
  const double* own_distances(int i) const {
    if (!own_known[i]) {
      own[i][0] = signed_distance(scene.hull_a, scene.pose_a, on_a(i));
      own[i][1] = signed_distance(scene.hull_b, scene.pose_b, on_b(i));
      own_known[i] = true;
    }
    return own[i];
  }
  mutable double own[MFZ_MAX_CONTACTS][2] = {};
  mutable bool own_known[MFZ_MAX_CONTACTS] = {};
};

// The profile's share of a check's tolerance, for the report.
InvariantCheck with_share(InvariantCheck check, double share) {
  check.profile_share = share;
  return check;
}

// The checks leave the name to the table below (kInvariants).
InvariantCheck measured(double error, double tolerance, std::string detail = {}) {
  const bool ok = error <= tolerance;  // a NaN error fails
  return {{}, ok ? CheckStatus::pass : CheckStatus::fail, error, tolerance, std::move(detail)};
}

// The same, with the detail written only when someone will read it.
template <class Detail>
InvariantCheck measured(const Context& c, double error, double tolerance, Detail&& detail) {
  InvariantCheck check = measured(error, tolerance);
  if (check.status == CheckStatus::fail || c.pass_details) check.detail = detail();
  return check;
}

InvariantCheck skipped(std::string why) { return {{}, CheckStatus::skipped, 0, 0, std::move(why)}; }

// printf-style, for the one-line details: a stream per check cost more than
// the checks' arithmetic.
template <class... Numbers>
std::string text(const char* format, Numbers... numbers) {
  char line[256];
  std::snprintf(line, sizeof line, format, numbers...);
  return line;
}

// contact_named_in reads this form back.
std::string describe(const char* what, int contact) {
  return contact >= 0 ? text("%s (contact %d)", what, contact) : std::string(what);
}

// finite also covers fields out of range: a colliding flag other than 0 or 1,
// a contact count outside 0..64. Both mean garbage came back.
InvariantCheck check_finite(const Context& c) {
  const mfz_manifold& m = c.m;
  if (m.colliding != 0 && m.colliding != 1) return measured(1, 0, "colliding is " + std::to_string(m.colliding));
  if (m.contact_count < 0 || m.contact_count > MFZ_MAX_CONTACTS)
    return measured(1, 0, "contact_count is " + std::to_string(m.contact_count));
  if (c.profile.max_contacts > 0 && m.contact_count > c.profile.max_contacts)
    return measured(1, 0, text("contact_count is %d, past the profile's max-contacts=%d", m.contact_count,
                               c.profile.max_contacts));
  if (m.colliding == 1 && (!to_vec(m.normal).allFinite() || !std::isfinite(m.penetration)))
    return measured(1, 0, "normal or penetration is not finite");
  for (int i = 0; i < m.contact_count; ++i)
    if (!c.on_a(i).allFinite() || !c.on_b(i).allFinite() || !std::isfinite(m.contacts[i].penetration))
      return measured(1, 0, describe("a contact field is not finite", i));
  return measured(0, 0);
}

InvariantCheck check_unit_normal(const Context& c) {
  if (!c.colliding) return skipped("not colliding");
  const double precision = tol::kWorldUlps * c.scene.precision_epsilon;
  return with_share(measured(std::abs(c.n.norm() - 1), tol::kUnitNormal + precision), precision);
}

// Touching cases may report p or p_i a rounding error above zero. Elsewhere
// p_i < 0 is strict: a contact with p_i = 0 fails however small its error.
InvariantCheck check_negative_penetration(const Context& c) {
  if (!c.colliding) return skipped("not colliding");
  // margin: a case separated by up to the margin may report its gap as a
  // positive penetration. Its contacts may lie up to the margin apart in
  // any case, overlapping or not: a margin engine keeps the incident face's
  // points within the margin above the reference face (Bullet's clip keeps
  // those up to its breaking threshold: bullet, edge_crosses_edge.case).
  const double margin = c.within_margin() ? c.margin() : 0;
  const double contact_margin = c.margin();
  const double base = c.scene.length_tolerance(tol::kDepth);
  const double tol = base + margin, contact_tol = base + contact_margin;
  const double ceiling = c.oracles.touching || margin > 0 ? tol : 0;
  double worst = std::max(0.0, c.m.penetration - ceiling);
  bool broken = worst > 0;
  int at = -1;
  // The tolerance reported is the one the worst error broke: a contact
  // above its margin, or one deeper than the manifold's depth.
  double worst_tol = contact_tol;
  const char* rule = "p <= 0 and p - tol <= p_i < 0";
  for (int i = 0; i < c.m.contact_count; ++i) {
    const double p = c.m.contacts[i].penetration;
    const bool not_negative = c.oracles.touching || contact_margin > 0 ? p > contact_tol : p >= 0;
    const double too_deep = (c.m.penetration - tol) - p;
    if (not_negative || too_deep > 0) {
      broken = true;
      const double err = std::max(too_deep, p);
      if (err >= worst) {
        worst = err, at = i;
        const bool deeper = too_deep >= p;
        worst_tol = deeper ? tol : contact_tol;
        rule = deeper ? "p - tol <= p_i: a contact deeper than the manifold's depth" : "p_i < 0 (or within the margin)";
      }
    }
  }
  InvariantCheck check{{}, broken ? CheckStatus::fail : CheckStatus::pass, c.relative(worst),
                       c.relative(worst_tol), broken || c.pass_details ? describe(rule, at) : std::string()};
  return with_share(check, c.relative(contact_margin + c.scene.precision_rounding()));
}

// The point checks: each contact's error (a length), the worst against
// `tol`, naming the contact that gave it.
template <class ErrorOf>
InvariantCheck worst_contact(const Context& c, double tol, const char* what, ErrorOf&& error_of) {
  if (c.m.contact_count == 0) return skipped("no contacts");
  double worst = 0;
  int at = -1;
  for (int i = 0; i < c.m.contact_count; ++i)
    if (const double err = error_of(i); err > worst || std::isnan(err)) worst = err, at = i;
  return measured(c, c.relative(worst), c.relative(tol), [&] { return describe(what, at); });
}

InvariantCheck check_pair_consistency(const Context& c) {
  return worst_contact(c, c.scene.length_tolerance(tol::kPoint), "|b - (a + p_i n)|", [&](int i) {
    return (c.on_b(i) - (c.on_a(i) + c.m.contacts[i].penetration * c.n)).norm();
  });
}

InvariantCheck check_on_surface(const Context& c) {
  const Scene& s = c.scene;
  return worst_contact(c, s.point_tolerance(), "distance to own surface", [&](int i) {
    return std::max(std::abs(c.own_distance_a(i)), std::abs(c.own_distance_b(i)));
  });
}

// The error is how far a point sticks out beyond what is allowed, so that one
// tolerance serves both the own-hull and the other-hull bound.
InvariantCheck check_within_both_hulls(const Context& c) {
  const Scene& s = c.scene;
  return worst_contact(c, s.point_tolerance(), "outside allowed by", [&](int i) {
    const double slack = std::abs(c.m.contacts[i].penetration);
    // Within the slack a point's distance is clamped to 0 below, so it need
    // only be measured where it exceeds the slack.
    return std::max({c.own_distance_a(i), c.own_distance_b(i),
                     signed_distance_past(s.hull_b, s.pose_b, c.on_a(i), slack) - slack,
                     signed_distance_past(s.hull_a, s.pose_a, c.on_b(i), slack) - slack, 0.0});
  });
}

InvariantCheck check_has_contacts(const Context& c) {
  const double tol = c.scene.length_tolerance(tol::kDepth);
  if (!c.colliding || !(c.depth > tol)) return skipped("not colliding deeper than tol");
  return measured(c.m.contact_count >= 1 ? 0 : c.relative(c.depth), c.relative(tol),
                  c.m.contact_count >= 1 ? "" : "colliding, no contacts");
}

InvariantCheck check_agrees_with_gjk(const Context& c) {
  const OracleAnswers& o = c.oracles;
  if (o.touching) return skipped("touching: either answer passes");
  if (o.ccd.gjk_intersecting != o.exact.colliding)
    return {{}, CheckStatus::oracle_disagreement, 0, 0,
            std::string("GJK says ") + (o.ccd.gjk_intersecting ? "intersecting" : "separate") +
                ", the exact oracle says " + (o.exact.colliding ? "intersecting" : "separate")};
  if (c.colliding && c.within_margin())
    return with_share(measured(0, c.relative(c.margin()), "separated within the profile's margin"), c.relative(c.margin()));
  const bool agree = c.colliding == o.ccd.gjk_intersecting;
  return measured(agree ? 0 : c.relative(std::abs(o.exact.signed_depth)),
                  c.relative(c.scene.length_tolerance(tol::kTouching)),
                  agree ? "" : (c.colliding ? "colliding, but GJK and the exact oracle say separate"
                                            : "not colliding, but GJK and the exact oracle say intersecting"));
}

// Where the least axis is an edge pair, its cross product is known only to
// the frame's rounding over the shorter edge and the sine of their angle,
// and the overlap along it, a corner of the support function, grows by that
// turn times the hulls' reach: the oracle's depth and the generator's are
// each that much above the true one at most. Two needles 2,300 long and
// 1e-4 across lay 4.1e-8 rad apart; turned and moved 1,600 out (the
// rounding there 5.2e-11), the built-in took a face axis 3.85e-5 deep where
// the oracle's edge pair gave 3.46e-5, 1.7e-9 L apart, in a frame where
// that pair is known to 5.5e-7 rad and its overlap to 2.5e-3 (h31,
// rigid-motion, manifold_fuzzer on 5- to 12-point hulls, open as O32; ODE's
// SAT failed the case itself by 1.7e-9 L).
InvariantCheck check_depth_exact(const Context& c) {
  if (!c.colliding) return skipped("not colliding");
  const double tol =
      c.scene.length_tolerance(tol::kDepth) + c.oracles.least_edge_pair.depth_room(c.scene.rounding());
  const double excess = c.depth - c.oracles.exact.signed_depth, bias = c.face_bias_allowance();
  // face-bias: a face axis may be deeper than the exact depth by its fraction.
  const double err = excess > 0 ? std::max(0.0, excess - bias) : -excess;
  return with_share(measured(c, c.relative(err), c.relative(tol),
                             [&] { return text("depth %g, exact %g", c.depth, c.oracles.exact.signed_depth); }),
                    c.relative(bias + c.scene.precision_rounding()));
}

InvariantCheck check_depth_within_epa_bounds(const Context& c) {
  const OracleAnswers& o = c.oracles;
  if (!c.colliding || !o.ccd.epa_ok) return skipped("not colliding, or EPA did not run");
  const double tol_epa = c.scene.length_tolerance(tol::kEpa);
  if (o.ccd.epa_depth > o.exact.signed_depth + tol_epa)
    return {{}, CheckStatus::oracle_disagreement, c.relative(o.ccd.epa_depth - o.exact.signed_depth),
            c.relative(tol_epa), "EPA's depth exceeds the exact depth"};
  const double upper = directed_overlap(c.scene.world_a, c.scene.world_b, o.ccd.epa_direction);
  const double bias = c.face_bias_allowance();
  const double err = std::max({0.0, o.ccd.epa_depth - c.depth, c.depth - upper - bias});
  // EPA's depth is held to the exact depth within tol_epa, and the
  // generator's to it within depth-exact's tolerance, so the two are within
  // both of each other. Held to tol_epa alone, a depth 0.215 under the exact
  // one 1.2e15 from the origin, within the 14.8 depth-exact allows there,
  // was 1.12e-6 L under an EPA 1.114e-6 L over the exact depth, against a
  // tolerance of 1.11e-6 L (h26, manifuzz fuzz --strict on the built-in).
  const double tol = tol_epa + c.scene.length_tolerance(tol::kDepth);
  return with_share(measured(c, c.relative(err), c.relative(tol),
                             [&] { return text("EPA %g <= depth %g <= %g", o.ccd.epa_depth, c.depth, upper + bias); }),
                    c.relative(bias + c.scene.precision_rounding()));
}

InvariantCheck check_normal_agrees_with_epa(const Context& c) {
  const OracleAnswers& o = c.oracles;
  const double tol_epa = c.scene.length_tolerance(tol::kEpa);
  if (!c.colliding || !o.ccd.epa_ok || std::abs(o.ccd.epa_depth - o.exact.signed_depth) > tol_epa)
    return skipped("EPA's depth is not the exact depth");
  // At zero depth every direction realises the depth, so EPA's is arbitrary.
  if (o.touching) return skipped("touching: EPA's direction is arbitrary");
  const double angle = std::acos(std::clamp(c.n.normalized().dot(o.ccd.epa_direction), -1.0, 1.0));
  if (angle <= tol::kEpaAngle) return with_share(measured(angle, tol::kEpaAngle, "angle to EPA (rad)"), 0);
  // EPA's direction is only an oracle where it realises the exact depth
  // itself: at small depths its depth can be right and its direction not.
  const double along_epa = directed_overlap(c.scene.world_a, c.scene.world_b, o.ccd.epa_direction);
  if (std::abs(along_epa - o.exact.signed_depth) > tol_epa) {
    return {{}, CheckStatus::oracle_disagreement, c.relative(std::abs(along_epa - o.exact.signed_depth)),
            c.relative(tol_epa),
            text("EPA's direction does not realise the exact depth: overlap along it %g, exact depth %g", along_epa,
                 o.exact.signed_depth)};
  }
  // A tie: both axes are minimal, EPA's and n, each realising the depth.
  // face-bias: n may be a face axis up to its fraction deeper than EPA's.
  const double along_n = directed_overlap(c.scene.world_a, c.scene.world_b, c.n.normalized());
  const double bias = c.face_bias_allowance();
  if (bias > 0)
    return with_share(measured(c.relative(std::max({0.0, along_n - o.exact.signed_depth - bias, std::abs(along_n - c.depth)})),
                               c.relative(tol_epa),
                               text("a face axis %g deep, exact %g, within the profile's face-bias", along_n,
                                    o.exact.signed_depth)),
                      c.relative(bias + c.scene.precision_rounding()));
  const double err = std::max(std::abs(along_epa - c.depth), std::abs(along_n - c.depth));
  return measured(c, c.relative(err), c.relative(tol_epa), [&] {
    return text("angle to EPA %g rad; overlap along EPA's direction %g, along n %g, depth %g", angle, along_epa,
                along_n, c.depth);
  });
}

InvariantCheck check_normal_realises_depth(const Context& c) {
  if (!c.colliding) return skipped("not colliding");
  const double along_n = directed_overlap(c.scene.world_a, c.scene.world_b, c.n.normalized());
  return measured(c, c.relative(std::abs(along_n - c.depth)), c.relative(c.scene.length_tolerance(tol::kDepth)),
                  [&] { return text("overlap along n %g, depth %g", along_n, c.depth); });
}

// Moving B by t keeps the hulls overlapping exactly when t lies in A - B, so
// the exact test is a point-in-polytope test against the planes of A - B
// (every candidate axis, both ways for edge pairs); GJK is asked too.
InvariantCheck check_separates(const Context& c) {
  const OracleAnswers& o = c.oracles;
  if (!c.colliding) return skipped("not colliding");
  if (c.within_margin()) return skipped("separated within the profile's margin");
  const double tol = c.scene.length_tolerance(tol::kSeparates);
  const Vec3 n = c.n.normalized();
  const Vec3 beyond = (c.depth + tol) * n;
  // Only a positive depth is an error: the pass stops at the first axis
  // that leaves none.
  double err = std::max(0.0, depth_after_moving_b(o.sat_axes, beyond, 0.0));
  const char* what = "still overlapping after moving B by depth + tol";
  bool exact_separates = err == 0;
  bool gjk_disagrees = exact_separates && libccd_intersecting(c.scene, beyond);
  // face-bias: a face axis deeper than the exact depth leaves the hulls
  // apart before its own depth, but never before the exact depth.
  const double bias = c.face_bias_allowance();
  if (exact_separates && c.depth - bias > 2 * tol) {
    const Vec3 short_of = (c.depth - bias - tol) * n;
    // Short of the least overlap, B certainly still overlaps: no axis read.
    err = surely_overlapping_after_moving_b(o.sat_axes, short_of)
              ? 0.0
              : std::max(0.0, -depth_after_moving_b(o.sat_axes, short_of));
    what = "already separate after moving B by depth - tol";
    gjk_disagrees = err == 0 && !libccd_intersecting(c.scene, short_of);
  }
  if (err == 0 && gjk_disagrees)
    return {{}, CheckStatus::oracle_disagreement, 0, c.relative(tol),
            "the exact test and GJK disagree at depth +- tol"};
  return with_share(measured(c.relative(err), 0.0, err > 0 ? what : ""), c.relative(bias));
}

// True when unit `n` is the outward normal of a face of A or the inward
// normal of a face of B, to `sine` (the generator's coplanarity by default).
bool along_a_face_normal(const Scene& s, const Vec3& n, double sine = tol::kCoplanarSine) {
  const auto along = [&](const Vec3& normal, const Vec3& d) { return normal.dot(d) > 0 && normal.cross(d).norm() <= sine; };
  for (int f = 0; f < s.hull_a.face_count(); ++f)
    if (along(s.pose_a.rotate(s.hull_a.face_normal(f)), n)) return true;
  for (int f = 0; f < s.hull_b.face_count(); ++f)
    if (along(s.pose_b.rotate(s.hull_b.face_normal(f)), -n)) return true;
  return false;
}

// Whether `p` lies on an edge of `hull` (posed at `world`) whose direction
// is across n (within `sine`); each such edge's direction into `directions`.
void edges_across_n_through(const Hull& hull, const std::vector<Vec3>& world, const Vec3& p, const Vec3& n,
                            double near, double sine, std::vector<Vec3>& directions) {
  for (const HullEdge& e : hull.edges()) {
    const Vec3 &e0 = world[e.v0], &e1 = world[e.v1];
    const Vec3 d = (e1 - e0).normalized();
    if (std::abs(d.dot(n)) <= sine && (p - closest_on_segment(p, e0, e1)).norm() <= near) directions.push_back(d);
  }
}

// Under a precision profile, a single contact on an edge of each hull whose
// cross product is n: the closest points of an edge pair whose axis is n to
// the profile's precision, and so, where n realises the depth, tied with the
// face axis along it at that precision. The contract lets a generator answer
// that tie with the pair's one point ("one may give 4 contacts, the other
// 1"), and the check tells such an answer by its normal being no face's;
// rounded to the profile's precision the pair's normal may be the face's.
// The float variant took the edge pair in its rounded frame, where B's edge
// lying on A's face tilted by 1e-8, and its normal rounded to float was A's
// face's (-1/3, 2/3, -2/3) to the bit, its one point where the edge crosses
// the face's rim, in a region 0.065 wide (h24, manifuzz check on the float
// variant, --seed 5931). In double the normal tells: an edge pair whose axis
// is the face's to the bit is the face's contact, and one point at a corner
// of a box turned 45 degrees on another, where two rims cross, is still
// asked to span the octagon. Read from the hulls alone, so that a
// relation's transformed run, which has no ranked axes of its own, is read
// alike. A deepest vertex alone lies on no edge of the other hull, and is
// still asked to span the region.
bool single_contact_of_edge_pair_along(const Context& c, const Vec3& n) {
  if (c.m.contact_count != 1 || !(c.scene.precision_epsilon > 0)) return false;
  const double near = c.scene.point_tolerance();
  const double sine = tol::kCoplanarSine + tol::kWorldUlps * c.scene.precision_epsilon;
  std::vector<Vec3> along_a, along_b;
  edges_across_n_through(c.scene.hull_a, c.scene.world_a, c.on_a(0), n, near, sine, along_a);
  if (along_a.empty()) return false;
  edges_across_n_through(c.scene.hull_b, c.scene.world_b, c.on_b(0), n, near, sine, along_b);
  for (const Vec3& da : along_a)
    for (const Vec3& db : along_b)
      if (const Vec3 axis = da.cross(db); axis.norm() > sine && axis.normalized().cross(n).norm() <= sine) return true;
  return false;
}

// An engine's face axis is the face's normal to its own precision: within
// 1e-6 rad (tolerances.h, kRelationNormal) and 64 of its ulps.
bool Context::biased_face_axis() const {
  return profile.face_bias > 0 &&
         along_a_face_normal(scene, n.normalized(), tol::kRelationNormal + tol::kWorldUlps * scene.precision_epsilon);
}

// How far a region's centroid lies outside the contacts' hull, and what is
// allowed: kRegionPoint L, plus kRegionDrift times how far the centroid moves
// between `region` and the region with B backed off along n by `nearer`,
// closer to touching.
struct CentroidMiss {
  double off = INFINITY, allowed = 0, width = 0, drift = INFINITY;
  const char* region = "first-touching region";
  bool passes() const { return off <= allowed; }
};

CentroidMiss centroid_miss(const Context& c, const ContactRegion& region, double nearer,
                           const std::vector<Eigen::Vector2d>& contacts) {
  const Vec3 n = c.n.normalized();
  const double slack = c.scene.length_tolerance(tol::kRegionSlack);
  CentroidMiss miss;
  if (region.empty) return miss;
  miss.width = region.width;
  miss.off = distance_to_convex_hull_2d(region.centroid, contacts);
  // A centroid inside the contacts' hull passes whatever the drift, and an
  // error of zero reads the same against any tolerance: the closer region
  // is worked out only when the check will be read for its numbers (it was
  // half of the check, which was 7% of a fuzz execution).
  if (miss.off == 0 && !c.pass_details) {
    miss.drift = 0;
    miss.allowed = c.scene.length_tolerance(tol::kRegionPoint);
    return miss;
  }
  const ContactRegion closer = contact_region(c.scene, n, nearer * n, slack);
  miss.drift = closer.empty ? INFINITY : (region.centroid - closer.centroid).norm();
  miss.allowed = c.scene.length_tolerance(tol::kRegionPoint) + tol::kRegionDrift * miss.drift;
  return miss;
}

// Completeness: where the region is well defined, the contacts projected
// onto the contact plane enclose its centroid. The region is the part of the
// hulls' intersection that touched first (oracles/contact_region.h). It is
// well defined where a face axis is among the minimal candidates: two
// crossing edges first touch at one point, which on-surface and the depth
// checks already pin (f20, f21: an edge nearly along a face beyond a ridge).
// The tolerance grows with how far the centroid drifts on the way to
// touching (tolerances.h). A manifold at its declared max-contacts may
// instead enclose the whole intersection's centroid, the contract's region:
// a reducer keeps k corners of the overlap and need not keep both ends of
// the first-touching strip along a tilted contact's deepest edge (h13).
InvariantCheck check_spans_contact_region(const Context& c) {
  const double depth = c.oracles.exact.signed_depth;
  if (!c.colliding || !(depth > c.scene.length_tolerance(tol::kDepth)) || c.m.contact_count == 0)
    return skipped("not colliding deeper than tol, or no contacts");
  if (!c.oracles.face_contact) return skipped("the hulls first touch at crossing edges: a point");
  // In a tie of a face axis with an edge pair 1e-9 rad away a generator may
  // take the edge pair and answer with one point (docs/contract.md: "one may
  // give 4 contacts, the other 1"): completeness is asked of a face normal's
  // manifold only (seed 10).
  if (!along_a_face_normal(c.scene, c.n.normalized())) return skipped("the normal is no face's: an edge contact");
  if (single_contact_of_edge_pair_along(c, c.n.normalized()))
    return skipped("one point of an edge pair tied with the face axis along n: an edge contact");
  // Which of two equally aligned incident faces a generator clips is a tie;
  // clipping one covers only its part of the region (seed 17).
  if (c.oracles.ties.incident_face) return skipped("the incident faces tie: the region is a choice");
  const Vec3 n = c.n.normalized();
  const double halfway = (1 + tol::kRegionFirstTouch) / 2;
  // A hull no thicker along n than the half slab lies whole in both
  // regions: each is that hull's outline, not what touched first, and the
  // centroid does not drift between them, so the tolerance does not grow.
  // A tetrahedral sliver 5 thick, 2005 deep inside a hull, had its outline
  // asked of the contacts under its reference face, which covers half of it
  // (0.125 off, tolerance 0.024; h15, manifuzz fuzz).
  // A hull's overlap with itself along n is its thickness.
  const double thinner = std::min(directed_overlap(c.scene.world_a, c.scene.world_a, n),
                                  directed_overlap(c.scene.world_b, c.scene.world_b, n));
  if ((1 - halfway) * depth >= thinner)
    return skipped("a hull is thinner along n than the first-touching slab: the region is its outline");
  // The slab is a fraction of the depth, or of the thinner hull's thickness
  // where that is less: a hull sunk deeper than its own thickness is
  // resolved by a fraction of itself, not of the depth. A sliver 1.2e-3
  // thick, 0.1 deep, four of its five vertices within 4e-4 of its bottom,
  // lay in the slab of 1e-3 and in the half slab with one outline, did not
  // drift (1.5e-7), and had that outline's centroid asked of the contacts
  // on its lowest face (7e-4 off, tolerance 2e-6; h20, manifuzz fuzz).
  // The intersection is no thicker along n than that either: a sunk hull's
  // contact is shallow when the hull is thin beside its region's width.
  const double thickness = std::min(depth, thinner), slab = (1 - tol::kRegionFirstTouch) * thickness;
  // The slab must be thicker than the frame's rounding that the region is
  // computed with, or its drift is noise (1e6 L out, seed 16).
  const double slack = c.scene.length_tolerance(tol::kRegionSlack);
  if (!(slab > 4 * slack)) return skipped("the first-touching slab is below the frame's resolution");
  // A contact (an intersection) thicker than a quarter of the widest its
  // region can be is no shallow one, whatever the region: the region is worked out only where
  // the bound lets it be thin (random overlapping hulls first touch at a
  // corner, 1% of the depth across, and working out that region only to
  // skip the check was 7% of a fuzz execution).
  const char* not_shallow = "not a shallow contact: the hulls' intersection is not thin along n";
  const Vec3 first_touch = (depth - slab) * n;
  if (!(thickness <= tol::kThinRegion * region_width_bound(c.scene, n, first_touch, slack)))
    return skipped(not_shallow);
  const ContactRegion region = contact_region(c.scene, n, first_touch, slack);
  if (region.empty || !(thickness <= tol::kThinRegion * region.width)) return skipped(not_shallow);
  // The region lying against two faces of one hull that both face the other
  // (a face folded under the contact) is the contract's folded-face tie: the
  // clipping method contacts one of them (near-coplanar, seeds 101, 102,
  // 104; a small cube across a fold, seed 4).
  if (region.facing_faces_a > 1 || region.facing_faces_b > 1)
    return skipped("the region lies across a folded face: a tie");
  Vec3 u, v;
  plane_basis(n, u, v);
  std::vector<Eigen::Vector2d> contacts;
  for (int i = 0; i < c.m.contact_count; ++i) contacts.emplace_back(u.dot(c.on_a(i)), v.dot(c.on_a(i)));
  CentroidMiss miss = centroid_miss(c, region, depth - slab / 2, contacts);
  const bool reduced = c.profile.max_contacts > 0 && c.m.contact_count >= c.profile.max_contacts;
  if (!miss.passes() && reduced) {
    const CentroidMiss whole =
        centroid_miss(c, contact_region(c.scene, n, Vec3::Zero(), slack), 0.5 * depth, contacts);
    if (whole.passes()) miss = whole, miss.region = "whole intersection";
  }
  return measured(c, c.relative(miss.off), c.relative(miss.allowed), [&] {
    return text("%s's centroid %g outside the contacts' hull; region width %g, drift %g", miss.region, miss.off,
                miss.width, miss.drift);
  });
}

struct InvariantRow {
  const char* name;
  InvariantCheck (*check)(const Context&);
  /// Needs no oracle of its own beyond the exact depth: a relation's
  /// transformed run is held to it too.
  bool transformed_runs;
};

// The invariants in the contract's order: one table gives the names, the
// order and the dispatch.
constexpr InvariantRow kInvariants[] = {
    {"finite", check_finite, true},
    {"unit-normal", check_unit_normal, true},
    {"negative-penetration", check_negative_penetration, true},
    {"pair-consistency", check_pair_consistency, true},
    {"on-surface", check_on_surface, true},
    {"within-both-hulls", check_within_both_hulls, true},
    {"has-contacts", check_has_contacts, true},
    {"agrees-with-gjk", check_agrees_with_gjk, false},
    {"depth-exact", check_depth_exact, true},
    {"depth-within-epa-bounds", check_depth_within_epa_bounds, false},
    {"normal-agrees-with-epa", check_normal_agrees_with_epa, false},
    {"normal-realises-depth", check_normal_realises_depth, true},
    {"separates", check_separates, false},
    {"spans-contact-region", check_spans_contact_region, true},
};

// Runs the rows that `wanted` selects; after a failed `finite` the rest are
// skipped, since they would read garbage.
Verdict run_rows(const Context& c, int32_t status) {
  Verdict v;
  v.generator_status = status;
  if (status != 0) return v;
  v.checks.reserve(std::size(kInvariants));
  bool garbage = false;
  for (const InvariantRow& row : kInvariants) {
    InvariantCheck check = garbage ? skipped("output not finite") : row.check(c);
    check.name = row.name;
    // Every length tolerance holds the precision's rounding once.
    if (check.profile_share < 0)
      check.profile_share = check.tolerance > 0 && check.status != CheckStatus::skipped
                                ? std::min(check.tolerance, c.relative(c.scene.precision_rounding()))
                                : 0;
    garbage = garbage || (check.status == CheckStatus::fail && check.name == "finite");
    v.checks.push_back(std::move(check));
  }
  return v;
}

}  // namespace

bool separated_within_margin(const Scene& scene, const OracleAnswers& oracles, const Profile& profile) {
  return profile.margin > 0 && !oracles.exact.colliding &&
         -oracles.exact.signed_depth <= profile.margin * scene.scale + scene.length_tolerance(tol::kTouching);
}

const std::vector<std::string>& invariant_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const InvariantRow& row : kInvariants) v.push_back(row.name);
    return v;
  }();
  return names;
}

Verdict check_manifold(const Scene& scene, const OracleAnswers& oracles, int32_t status, const mfz_manifold& m,
                       const Profile& profile, PassDetails pass_details) {
  const Context c{scene, oracles, m, profile, scene.scale, to_vec(m.normal), -m.penetration, m.colliding == 1,
                  pass_details == PassDetails::written};
  return run_rows(c, status);
}

std::optional<InvariantCheck> check_transformed_manifold(const Scene& scene, const OracleAnswers& original,
                                                         double depth_factor, const mfz_manifold& m,
                                                         const Profile& profile) {
  OracleAnswers known;
  known.exact = original.exact;
  known.exact.signed_depth *= depth_factor;
  known.touching = original.touching;
  known.face_contact = original.face_contact;
  known.ties = original.ties;
  known.least_edge_pair = original.least_edge_pair;
  const Context c{scene, known, m, profile, scene.scale, to_vec(m.normal), -m.penetration, m.colliding == 1,
                  /*pass_details=*/false};
  // "finite" comes first: past a failure nothing else runs, so no check
  // meets a NaN it was not written for.
  for (const InvariantRow& row : kInvariants) {
    if (!row.transformed_runs) continue;
    InvariantCheck check = row.check(c);
    if (check.status != CheckStatus::fail) continue;
    check.name = row.name;
    return check;
  }
  return std::nullopt;
}

}  // namespace mfz
