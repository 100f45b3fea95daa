// The built-in generator allocates nothing per call: this executable counts
// every global operator new and asserts that none happens during calls on
// face, edge, vertex, tied and many-vertex cases, once a thread's first
// calls have reserved its topology store and SAT's workspace. It also
// measures how deep
// a call's stack goes (a thread of its own on a painted stack).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#include <pthread.h>

#include "generator/builtin_generator.h"
#include "families.h"
#include "case/scene.h"
#include "test_support.h"

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
           {prism(15), props::box_corners(0.3, 0.3, 0.3), {Vec3(0, 0, 0.75), Quat::Identity()}},
           {test::sphere_points(300, 1), test::sphere_points(1024, 2), {Vec3(0.3, 0.2, 1.2), turn}}}) {
    CaseFile c;
    c.points_a = a;
    c.points_b = b;
    c.pose_b = pose_b;
    scenes.push_back(std::move(*make_scene(c).scene));
  }
  mfz_manifold out;
  // A thread's first calls reserve, once per thread, its topology store
  // (hull_topology.h: the ring, its index and the builds' scratch), on the
  // first box the table of hulls' shapes (parallelepiped.h) and, on the
  // first call that reaches SAT's edge phase, SAT's workspace with its two
  // hulls' arcs: seven allocations in all.
  {
    const long before = allocations.load();
    for (const Scene& s : scenes) {
      const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
      const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
      mfz_builtin_generate(&a, &pa, &b, &pb, &out);
    }
    EXPECT_LE(allocations.load() - before, 7) << "the first calls on a thread";
  }
  for (const Scene& s : scenes) {
    const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
    const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
    const long before = allocations.load();
    for (int k = 0; k < 10; ++k) mfz_builtin_generate(&a, &pa, &b, &pb, &out);
    EXPECT_EQ(allocations.load() - before, 0) << "contacts " << out.contact_count;
    EXPECT_EQ(out.colliding, 1);
  }
}

// The stack a call uses, beyond what an idle thread uses (its thread-local
// storage lies in the same block): the deepest byte that `work` touched.
template <class Work>
size_t stack_bytes_used(Work&& work) {
  constexpr size_t kSize = 1 << 20;
  static char block[kSize] __attribute__((aligned(4096)));
  const auto deepest = [&](bool idle) {
    std::memset(block, 0xAA, kSize);
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstack(&attr, block, kSize);
    struct Job {
      Work* work;
      bool idle;
    } job{&work, idle};
    pthread_t thread;
    pthread_create(&thread, &attr, [](void* j) -> void* {
      auto* job = static_cast<Job*>(j);
      if (!job->idle) (*job->work)();
      return nullptr;
    }, &job);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    size_t untouched = 0;
    while (untouched < kSize && static_cast<unsigned char>(block[untouched]) == 0xAA) ++untouched;
    return kSize - untouched;
  };
  return deepest(false) - deepest(true);
}

// The issue of speed asked for tens of kilobytes, not 130: the arcs of
// large hulls (296 KB each, sized for 1,024 points) live in SAT's
// workspace, allocated once per thread, and the clip's polygons (50 KB
// each since F61) in the clip's, also once per thread. Under 64 KiB, a
// fibre's stack in many engines' job systems; with the polygons on the
// stack a call took 95.5 KB.
// Hulls of 128 points and less cache their world vertices on the stack;
// larger ones, up to 1,024, rotate theirs and take no more.
TEST(BuiltinGenerator, ACallUsesUnder64KiBOfStack) {
  std::vector<Scene> scenes;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const int points = seed <= 8 ? 128 : 1024;
    CaseFile c;
    c.points_a = test::sphere_points(points, seed);
    c.points_b = test::sphere_points(points, 100 + seed);
    c.pose_b = {Vec3(0.3, 0.2, 1.2), Quat(Eigen::AngleAxisd(0.1 * seed, Vec3(1, 2, 3).normalized()))};
    scenes.push_back(std::move(*make_scene(c).scene));
  }
  CaseFile caps;
  caps.points_a = prism(64);
  caps.points_b = prism(64);
  caps.pose_b = {Vec3(0.1, 0, 0.99), Quat(Eigen::AngleAxisd(0.01, Vec3::UnitX()))};
  scenes.push_back(std::move(*make_scene(caps).scene));
  // Caps fanned into triangles, as the triangulated-faces relation hands
  // them in: SAT's tie of parallel faces (F14) and F27 gather each cap's
  // patch (F61: the patch's room for 1,024 faces and corners).
  for (const int sides : {64, 300}) {
    CaseFile fanned;
    fanned.points_a = prism(sides);
    fanned.points_b = prism(sides);
    fanned.pose_b = caps.pose_b;
    Scene s = std::move(*make_scene(fanned).scene);
    s.hull_a = fan_triangulated(s.hull_a);
    s.hull_b = fan_triangulated(s.hull_b);
    scenes.push_back(std::move(s));
  }
  // Two tetrahedra 1e4 long just touching, turned (F62's case under
  // rigid-motion): clipping, the supporting edges and the deepest point
  // give nothing, and F39's pass measures every edge pair, 64 at a time
  // (a 6 KB frame since stop 68).
  CaseFile touching;
  touching.points_a = {{0, 0, 0}, {-5000, 5000, 0}, {-5000, 5000, 5000}, {5000, 5000.00001, 5000.00001}};
  touching.points_b = {{0, 0, 0}, {0, -5000, 5000}, {0, 0, 0}, {5000, -5000, -5000.984375}, {5000, -5000, 5000}};
  const Quat turned(0.9004471023526769, 0.11624942883566838, 0.23249885767133677, 0.3487482865070052);
  touching.pose_a = {Vec3(9121.465741890639, -2981.507775462955, 1861.2986769930556), turned};
  touching.pose_b = {Vec3(3381.4352386235996, 4315.70629138229, 5576.49946351857), turned};
  scenes.push_back(std::move(*make_scene(touching).scene));
  const size_t used = stack_bytes_used([&] {
    mfz_manifold out;
    for (const Scene& s : scenes) {
      const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
      const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
      mfz_builtin_generate(&a, &pa, &b, &pb, &out);
      mfz_builtin_generate(&b, &pb, &a, &pa, &out);
    }
  });
  EXPECT_GT(used, 4096u);  // the measurement sees the call at all
  EXPECT_LT(used, 64u * 1024) << used << " bytes";
}

TEST(AllocationCounter, SeesAnAllocation) {
  const long before = allocations.load();
  auto* p = new std::vector<int>(100);
  EXPECT_GT(allocations.load() - before, 0);
  delete p;
}

}  // namespace
}  // namespace mfz
