#include "oracles/libccd_oracle.h"

#include <ccd/ccd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/tolerances.h"

namespace mfz {
namespace {

// How many support points one libccd call may ask for. GJK and MPR's
// penetration stop after max_iterations, but EPA and MPR's portal search
// loop until their tolerance is met, and that need never come: two boxes
// nearly concentric, one corner moved by 1e-5, kept EPA adding points for
// ever, and every command hung in the oracle (h14, manifuzz fuzz on the
// reducing variant). Once the budget is spent, every support point is the
// origin: A's and B's agree, so the Minkowski difference's support point is
// the origin, which expands nothing, and EPA and the portal search return
// at once. Their answer is then no answer (`exhausted`).
struct SupportBudget {
  long left = 0;
  bool exhausted = false;
  // A fresh budget for one call: enough for max_iterations, and for each
  // vertex of A - B (an exact EPA adds each at most once), up to a cap that
  // keeps a spent budget to a fraction of a second.
  void reset(size_t points_a, size_t points_b) {
    const long vertices = static_cast<long>(std::min<size_t>(points_a * points_b, tol::kCcdMaxPolytopeVertices));
    left = 2 * (static_cast<long>(tol::kCcdMaxIterations) + vertices) + 64;
    exhausted = false;
  }
};

// A posed hull in the rescaled frame: (world - origin) / L.
struct PointSet {
  std::vector<Vec3> points;
  Vec3 centre = Vec3::Zero();
  SupportBudget* budget = nullptr;
};

void support(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto& set = *static_cast<const PointSet*>(object);
  if (--set.budget->left < 0) {
    set.budget->exhausted = true;
    ccdVec3Set(out, 0, 0, 0);
    return;
  }
  const Vec3 d(ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir));
  const Vec3* best = &set.points[0];
  double best_d = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : set.points)
    if (const double v = d.dot(p); v > best_d) best_d = v, best = &p;
  ccdVec3Set(out, best->x(), best->y(), best->z());
}

void centre(const void* object, ccd_vec3_t* out) {
  const auto& set = *static_cast<const PointSet*>(object);
  ccdVec3Set(out, set.centre.x(), set.centre.y(), set.centre.z());
}

PointSet rescaled(const std::vector<Vec3>& world, const Vec3& origin, double scale, const Vec3& shift) {
  PointSet set;
  set.points.reserve(world.size());  // grown point by point, 8 points took four allocations
  for (const Vec3& p : world) {
    set.points.push_back((p + shift - origin) / scale);
    set.centre += set.points.back();
  }
  set.centre /= static_cast<double>(world.size());
  return set;
}

ccd_t settings() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = support;
  ccd.support2 = support;
  ccd.center1 = centre;
  ccd.center2 = centre;
  ccd.max_iterations = tol::kCcdMaxIterations;
  ccd.epa_tolerance = tol::kCcdEpaTolerance;
  ccd.mpr_tolerance = tol::kCcdMprTolerance;
  ccd.dist_tolerance = tol::kCcdDistTolerance;
  return ccd;
}

// Translating by A's first vertex is a rigid motion: it keeps libccd's
// arithmetic near the origin however far the case is placed.
struct Rescaled {
  PointSet a, b;
  SupportBudget budget;
  Rescaled(const Scene& s, const Vec3& shift_b)
      : a(rescaled(s.world_a, s.world_a[0], s.scale, Vec3::Zero())),
        b(rescaled(s.world_b, s.world_a[0], s.scale, shift_b)) {
    a.budget = b.budget = &budget;
  }
  /// A fresh budget before each libccd call; true when the call spent it.
  void start_call() { budget.reset(a.points.size(), b.points.size()); }
  bool spent() const { return budget.exhausted; }
};

// libccd's direction as a unit vector, or nothing where it gave none: at
// two tetrahedra touching by 1.5e-42 its EPA answered depth 0 along (inf,
// inf, inf), and the overlap along that, -inf, was held against the
// built-in as an upper bound (depth-within-epa-bounds, manifuzz fuzz).
std::optional<Vec3> to_unit(const ccd_vec3_t& v) {
  const Vec3 d(ccdVec3X(&v), ccdVec3Y(&v), ccdVec3Z(&v));
  const double n = d.norm();
  if (!(n > 0) || !std::isfinite(n)) return std::nullopt;
  return Vec3(d / n);
}

}  // namespace

LibccdAnswer ask_libccd(const Scene& s, bool with_mpr) {
  Rescaled frame(s, Vec3::Zero());
  const ccd_t ccd = settings();
  LibccdAnswer answer;
  frame.start_call();
  // GJK stops after max_iterations, within the budget.
  answer.gjk_intersecting = ccdGJKIntersect(&frame.a, &frame.b, &ccd) != 0;
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  // An answer without a direction, or after the support budget ran out, is
  // a failure of the method, not an answer.
  frame.start_call();
  if (ccdGJKPenetration(&frame.a, &frame.b, &ccd, &depth, &dir, &pos) == 0 && !frame.spent())
    if (const std::optional<Vec3> unit = to_unit(dir)) {
      answer.epa_ok = true;
      answer.epa_depth = depth * s.scale;
      answer.epa_direction = *unit;
    }
  frame.start_call();
  if (with_mpr && ccdMPRPenetration(&frame.a, &frame.b, &ccd, &depth, &dir, &pos) == 0 && !frame.spent())
    if (const std::optional<Vec3> unit = to_unit(dir)) {
      answer.mpr_ok = true;
      answer.mpr_depth = depth * s.scale;
      answer.mpr_direction = *unit;
    }
  return answer;
}

bool libccd_intersecting(const Scene& s, const Vec3& translation) {
  Rescaled frame(s, translation);
  const ccd_t ccd = settings();
  frame.start_call();
  return ccdGJKIntersect(&frame.a, &frame.b, &ccd) != 0;
}

}  // namespace mfz
