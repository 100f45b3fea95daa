#include <gtest/gtest.h>

#include "case/scene.h"
#include "geometry/hull_cache.h"
#include "test_support.h"

namespace mfz {
namespace {

TEST(HullCache, BuildsAPointSetOnceAndGivesTheSameHullAgain) {
  HullCache cache(4);
  const std::vector<Vec3> box = test::box_points(1, 2, 3);
  const int faces = cache.build(box).hull->face_count();
  EXPECT_EQ(cache.build(box).hull->face_count(), faces);
  EXPECT_EQ(cache.misses(), 1);
  EXPECT_EQ(cache.hits(), 1);
}

TEST(HullCache, TellsPointSetsApartBitForBit) {
  HullCache cache(4);
  std::vector<Vec3> box = test::box_points(1, 1, 1);
  cache.build(box);
  box[0].x() = std::nextafter(box[0].x(), 0.0);
  cache.build(box);
  EXPECT_EQ(cache.misses(), 2);
  std::vector<Vec3> too_few(box.begin(), box.begin() + 3);
  EXPECT_FALSE(cache.build(too_few).hull);
  EXPECT_FALSE(cache.build(too_few).hull);  // an error is remembered too
  EXPECT_EQ(cache.misses(), 3);
}

// case_file_fuzzer under UBSan: two empty point sets were compared with
// memcmp on null pointers.
TEST(HullCache, AnEmptyPointSetIsAnErrorAndComparesSafely) {
  HullCache cache(4);
  EXPECT_FALSE(cache.build({}).hull);
  EXPECT_FALSE(cache.build({}).hull);
  EXPECT_EQ(cache.hits(), 1);
}

TEST(HullCache, HoldsNoMoreThanItsCapacity) {
  HullCache cache(3);
  for (int k = 1; k <= 10; ++k) cache.build(test::box_points(k, 1, 1));
  EXPECT_EQ(cache.size(), 3u);
  cache.build(test::box_points(10, 1, 1));  // the most recent stays
  EXPECT_EQ(cache.hits(), 1);
}

// A fuzzer's mutation that moves only a pose must not rebuild a hull.
TEST(HullCache, AScenePosedAnotherWayBuildsNoHull) {
  CaseFile c = test::make_case(test::box_points(1, 1, 1), {}, test::box_points(0.5, 0.5, 0.5),
                               {Vec3(0, 0, 1.4), Quat::Identity()});
  ASSERT_TRUE(make_scene(c).scene);
  const long long built = thread_hull_cache().misses();
  c.pose_b.position.z() = 1.3;
  c.pose_a.orientation = test::about(Vec3::UnitZ(), 0.1);
  ASSERT_TRUE(make_scene(c).scene);
  EXPECT_EQ(thread_hull_cache().misses(), built);
}

}  // namespace
}  // namespace mfz
