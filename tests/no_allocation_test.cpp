// The built-in generator allocates nothing per call: this executable counts
// every global operator new and asserts that none happens during calls on
// face, edge, vertex, tied and many-vertex cases.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "generator/builtin_generator.h"
#include "families.h"
#include "case/scene.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// Counting replacements of the global allocation functions (malloc-backed,
// so that new and delete stay matched).
void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mfz {
namespace {

std::vector<Vec3> prism(int sides) {
  std::vector<Vec3> points;
  for (int k = 0; k < sides; ++k) {
    const double t = 2 * M_PI * k / sides;
    points.emplace_back(std::cos(t), std::sin(t), -0.5);
    points.emplace_back(std::cos(t), std::sin(t), 0.5);
  }
  return points;
}

TEST(BuiltinGenerator, AllocatesNothingPerCall) {
  const Quat turn(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  std::vector<Scene> scenes;
  for (const auto& [a, b, pose_b] : std::vector<std::tuple<std::vector<Vec3>, std::vector<Vec3>, Pose>>{
           {props::box_corners(2, 2, 0.5), props::box_corners(0.5, 0.5, 0.5), {Vec3(0, 0, 0.9), Quat::Identity()}},
           {props::box_corners(1, 1, 1), props::box_corners(1, 1, 1), {Vec3(0.3, 0.2, 1.9), turn}},
           {prism(64), prism(64), {Vec3(0, 0, 0.95), Quat(Eigen::AngleAxisd(0.01, Vec3::UnitZ()))}},
           {prism(15), props::box_corners(0.3, 0.3, 0.3), {Vec3(0, 0, 0.75), Quat::Identity()}}}) {
    CaseFile c;
    c.points_a = a;
    c.points_b = b;
    c.pose_b = pose_b;
    scenes.push_back(std::move(*make_scene(c).scene));
  }
  mfz_manifold out;
  for (const Scene& s : scenes) {
    const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
    const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
    const long before = allocations.load();
    for (int k = 0; k < 10; ++k) mfz_builtin_generate(&a, &pa, &b, &pb, &out);
    EXPECT_EQ(allocations.load() - before, 0) << "contacts " << out.contact_count;
    EXPECT_EQ(out.colliding, 1);
  }
}

TEST(AllocationCounter, SeesAnAllocation) {
  const long before = allocations.load();
  auto* p = new std::vector<int>(100);
  EXPECT_GT(allocations.load() - before, 0);
  delete p;
}

}  // namespace
}  // namespace mfz
