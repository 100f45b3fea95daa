#pragma once
// Shapes, cases and tolerance-aware assertions shared by the tests.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "case/case_file.h"
#include "geometry/hull.h"
#include "geometry/posed_hull.h"
#include "harness/case_run.h"

namespace mfz::test {

/// The eight corners of the box [-hx, hx] x [-hy, hy] x [-hz, hz].
std::vector<Vec3> box_points(double hx, double hy, double hz);
/// `count` points on the unit sphere, the same for the same seed.
std::vector<Vec3> sphere_points(int count, unsigned seed);
/// A regular tetrahedron's four corners around the origin.
std::vector<Vec3> tetrahedron_points();
/// A pyramid: a regular `sides`-gon of circumradius `radius` in z = 0, its
/// apex at (0, 0, apex_z).
std::vector<Vec3> pyramid_points(int sides, double radius, double apex_z);
/// A unit quaternion for `angle` radians about `axis`.
Quat about(const Vec3& axis, double angle);

/// A case file's two hulls built and posed as a generator sees them (the
/// orientations normalised); `built` is false where a hull does not build.
struct PosedCase {
  explicit PosedCase(const CaseFile& file);
  PosedCase(const PosedCase&) = delete;  // the posed hulls refer to the members
  bool built = false;
  std::optional<Hull> hull_a, hull_b;
  mfz_hull view_a{}, view_b{};
  Pose pose_a, pose_b;
  PosedHull a() const { return PosedHull(view_a, pose_a); }
  PosedHull b() const { return PosedHull(view_b, pose_b); }
  /// Moves both poses so that A's position is the origin: the frame the
  /// generator works in (F21), where the fuzzer met its pairs.
  void centre_on_a();
};

/// Two clouds overlapping for SAT's tests: A from `points_a` about the
/// origin, B `count_b` points on a sphere of radius 0.5-1.5 (its points
/// from `seed_b`), B's centre `apart` along `towards`, from touching to
/// nearly concentric, both turned at random; drawn from `random`.
struct OverlappingClouds {
  OverlappingClouds(const std::vector<Vec3>& points_a, int count_b, unsigned seed_b, std::mt19937& random);
  OverlappingClouds(const OverlappingClouds&) = delete;  // the views refer to the hulls
  double radius_b;
  Hull hull_a, hull_b;
  mfz_hull view_a, view_b;
  double apart;
  Pose pose_a;
  Vec3 towards;
  Pose pose_b;
};

CaseFile make_case(std::vector<Vec3> a, const Pose& pose_a, std::vector<Vec3> b, const Pose& pose_b);
/// Runs `c` through the built-in generator; fails the test on an input error.
CaseRun run_builtin(const CaseFile& c);
/// The path of a file in the source tree's corpus/.
std::string corpus_path(const std::string& name);
/// A path for a scratch file of this test process (in the system's temporary folder).
std::string scratch_path(const std::string& name);

}  // namespace mfz::test

/// Each coordinate within `tol`.
#define EXPECT_VEC_NEAR(actual, expected, tol)                                   \
  do {                                                                           \
    const ::mfz::Vec3 mfz_a_ = (actual), mfz_e_ = (expected);                    \
    EXPECT_LE((mfz_a_ - mfz_e_).cwiseAbs().maxCoeff(), (tol))                    \
        << "actual " << mfz_a_.transpose() << ", expected " << mfz_e_.transpose(); \
  } while (0)
