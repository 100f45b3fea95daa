#pragma once
// Shapes, cases and tolerance-aware assertions shared by the tests.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/case_file.h"
#include "harness/case_run.h"

namespace mfz::test {

/// The eight corners of the box [-hx, hx] x [-hy, hy] x [-hz, hz].
std::vector<Vec3> box_points(double hx, double hy, double hz);
/// `count` points on the unit sphere, the same for the same seed.
std::vector<Vec3> sphere_points(int count, unsigned seed);
/// A regular tetrahedron's four corners around the origin.
std::vector<Vec3> tetrahedron_points();
/// A unit quaternion for `angle` radians about `axis`.
Quat about(const Vec3& axis, double angle);

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
