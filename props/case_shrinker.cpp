#include "case_shrinker.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mfz::props {
namespace {

using Clock = std::chrono::steady_clock;

class Budget {
 public:
  explicit Budget(double seconds)
      : end_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))) {}
  bool left() const { return Clock::now() < end_; }

 private:
  Clock::time_point end_;
};

// `value` with `digits` significant decimal digits.
double rounded(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return std::strtod(text, nullptr);
}

// One pass of dropping points, last first (later points are the
// families' decorations: duplicates, grid points, pushed-out corners).
bool drop_points(CaseFile& c, std::vector<Vec3> CaseFile::*hull, const StillFails& still_fails, const Budget& budget,
                 int& steps) {
  bool dropped = false;
  for (size_t i = (c.*hull).size(); i-- > 0 && budget.left();) {
    if ((c.*hull).size() <= 4) break;
    CaseFile candidate = c;
    (candidate.*hull).erase((candidate.*hull).begin() + static_cast<long>(i));
    if (still_fails(candidate)) c = std::move(candidate), dropped = true, ++steps;
  }
  return dropped;
}

// Rounds one number to zero, or to the fewest digits (1 to 6), that keep
// the failure.
bool round_number(CaseFile& c, double& number, const StillFails& still_fails, int& steps) {
  const double original = number;
  for (int digits = 0; digits <= 6; ++digits) {
    const double shorter = digits == 0 ? 0.0 : rounded(original, digits);
    if (shorter == original) break;
    number = shorter;
    if (still_fails(c)) return ++steps, true;
  }
  number = original;
  return false;
}

void round_points(CaseFile& c, std::vector<Vec3> CaseFile::*hull, const StillFails& still_fails,
                  const Budget& budget, int& steps) {
  for (size_t i = 0; i < (c.*hull).size() && budget.left(); ++i)
    for (int axis = 0; axis < 3; ++axis) round_number(c, (c.*hull)[i](axis), still_fails, steps);
}

// A pose's position and quaternion: make_scene normalises the quaternion,
// so its components round like any number.
void round_pose(CaseFile& c, Pose CaseFile::*pose, const StillFails& still_fails, const Budget& budget, int& steps) {
  for (int axis = 0; axis < 3 && budget.left(); ++axis) round_number(c, (c.*pose).position(axis), still_fails, steps);
  for (int k = 0; k < 4 && budget.left(); ++k) round_number(c, (c.*pose).orientation.coeffs()(k), still_fails, steps);
}

// Moves the case so that A sits at the origin, then turns it so that A has
// the identity rotation: a rigid motion of both poses, which a person reads
// more easily. Kept only if the failure survives the motion's rounding.
void toward_origin_and_identity(CaseFile& c, const StillFails& still_fails, int& steps) {
  if (c.pose_a.position != Vec3::Zero()) {
    CaseFile moved = c;
    moved.pose_b.position = c.pose_b.position - c.pose_a.position;
    moved.pose_a.position = Vec3::Zero();
    if (still_fails(moved)) c = std::move(moved), ++steps;
  }
  const Quat qa = c.pose_a.orientation.normalized();
  if (qa.coeffs() != Quat::Identity().coeffs() && c.pose_a.position == Vec3::Zero()) {
    CaseFile turned = c;
    const Quat back = qa.conjugate();
    turned.pose_a.orientation = Quat::Identity();
    turned.pose_b = Pose{back * c.pose_b.position, (back * c.pose_b.orientation.normalized()).normalized()};
    if (still_fails(turned)) c = std::move(turned), ++steps;
  }
}

}  // namespace

int shrink_case_file(CaseFile& failing, const StillFails& still_fails, double seconds) {
  const Budget budget(seconds);
  int steps = 0;
  toward_origin_and_identity(failing, still_fails, steps);
  bool changed = true;
  while (changed && budget.left()) {
    changed = drop_points(failing, &CaseFile::points_a, still_fails, budget, steps);
    changed |= drop_points(failing, &CaseFile::points_b, still_fails, budget, steps);
  }
  round_points(failing, &CaseFile::points_a, still_fails, budget, steps);
  round_points(failing, &CaseFile::points_b, still_fails, budget, steps);
  round_pose(failing, &CaseFile::pose_a, still_fails, budget, steps);
  round_pose(failing, &CaseFile::pose_b, still_fails, budget, steps);
  return steps;
}

}  // namespace mfz::props
