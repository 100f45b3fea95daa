// A posed hull's projection onto an axis: hulls of more than
// kWideProjectionVertices vertices are projected out of line, four vertices
// at a time where the processor has AVX2, smaller ones inline. Both must give
// the bits of one sum, (ax x + ay y) + az z, for every vertex: SAT's answers
// are compared to the bit before and after a change, and replays must give
// the same bits on any machine; so must many axes projected at once. The
// face normals, turned all at once for the passes that read every face, must
// be the bits each turned alone is.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/hull.h"
#include "geometry/posed_hull.h"
#include "test_support.h"

namespace mfz {
namespace {

Interval reference_projection(const PosedHull& hull, const Vec3& axis) {
  Interval range;
  for (int i = 0; i < hull.vertex_count(); ++i) {
    const Vec3 p = hull.world_vertex(i);
    const double d = (axis.x() * p.x() + axis.y() * p.y()) + axis.z() * p.z();
    range.min = std::min(range.min, d);
    range.max = std::max(range.max, d);
  }
  return range;
}

TEST(PosedHull, AProjectionIsOneSumPerVertexInlineOrInWideLanes) {
  std::mt19937_64 random(20261126);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const int points : {8, kWideProjectionVertices + 1, 40, kCachedVertices}) {
    const Hull hull = *build_hull(test::sphere_points(points, static_cast<unsigned>(points))).hull;
    const mfz_hull view = hull.view();
    for (int trial = 0; trial < 200; ++trial) {
      // Far from the origin and turned, so that each sum rounds, and any
      // other order of its terms would round otherwise.
      const Pose pose{Vec3(u(random), u(random), u(random)) * 1e7,
                      Quat(u(random), u(random), u(random), u(random)).normalized()};
      const PosedHull posed(view, pose);
      const Vec3 axis = Vec3(u(random), u(random), u(random)) * 3;
      const Interval got = posed.project(axis), want = reference_projection(posed, axis);
      ASSERT_EQ(got.min, want.min) << points << " points, trial " << trial;
      ASSERT_EQ(got.max, want.max) << points << " points, trial " << trial;
    }
  }
}

// Many axes at once, as SAT on small hulls projects the edge pairs the
// Gauss-map test keeps and the brute-force SAT its rows: each axis's bounds
// the bits of that axis projected alone, for every count of axes (the
// lanes' remainder) and of vertices (the fours' remainder).
TEST(PosedHull, ProjectingOntoManyAxesAtOnceGivesEachAxisAloneToTheBit) {
  std::mt19937_64 random(20261128);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const int points : {5, 8, 23, 64}) {
    const Hull hull = *build_hull(test::sphere_points(points, static_cast<unsigned>(points) + 2)).hull;
    const mfz_hull view = hull.view();
    for (const int count : {1, 3, 4, 7, 17, 90}) {
      const Pose pose{Vec3(u(random), u(random), u(random)) * 1e7,
                      Quat(u(random), u(random), u(random), u(random)).normalized()};
      const PosedHull posed(view, pose);
      std::vector<double> ax(count), ay(count), az(count), lowest(count), highest(count);
      for (int j = 0; j < count; ++j) ax[j] = 3 * u(random), ay[j] = 3 * u(random), az[j] = 3 * u(random);
      posed.project_onto_axes(ax.data(), ay.data(), az.data(), count, lowest.data(), highest.data());
      for (int j = 0; j < count; ++j) {
        const Interval want = reference_projection(posed, Vec3(ax[j], ay[j], az[j]));
        ASSERT_EQ(lowest[j], want.min) << points << " points, " << count << " axes, axis " << j;
        ASSERT_EQ(highest[j], want.max) << points << " points, " << count << " axes, axis " << j;
      }
    }
  }
}

// Every face's world normal, turned alone before the hull turns them all
// and read from the turned ones after, is the same bits: SAT's faces, its
// inner balls, the edge arcs and the faces below the reference plane read
// them turned at once, and the few scattered reads (a significant face, a
// flat edge) turn them alone where no pass has.
TEST(PosedHull, FaceNormalsTurnedAtOnceAreTheNormalsTurnedOneByOne) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const int points : {8, 40, kCachedVertices}) {
    const Hull hull = *build_hull(test::sphere_points(points, static_cast<unsigned>(points) + 1)).hull;
    const mfz_hull view = hull.view();
    for (int trial = 0; trial < 50; ++trial) {
      const Pose pose{Vec3(u(random), u(random), u(random)) * 1e7,
                      Quat(u(random), u(random), u(random), u(random)).normalized()};
      const PosedHull posed(view, pose);
      const Mat3 rotation = pose.orientation.toRotationMatrix();
      std::vector<Vec3> alone;
      for (int f = 0; f < posed.face_count(); ++f) {
        alone.push_back(posed.world_face_normal(f));
        ASSERT_EQ(alone.back(), Vec3(rotation * to_vec(view.face_normals[f]))) << points << " points, face " << f;
      }
      posed.turn_face_normals();
      for (int f = 0; f < posed.face_count(); ++f)
        ASSERT_EQ(posed.world_face_normal(f), alone[f]) << points << " points, trial " << trial << ", face " << f;
    }
  }
}

}  // namespace
}  // namespace mfz
