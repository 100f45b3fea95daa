// ns per query of the built-in generator, through the same ABI call a plugin gets.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "bench_cases.h"

#include "generator/builtin_generator.h"
#include "families.h"
#include "case/scene.h"

namespace mfz {
namespace {

void run_queries(benchmark::State& state, const Scene& scene) {
  const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
  const mfz_pose pa = scene.abi_pose_a(), pb = scene.abi_pose_b();
  mfz_manifold out;
  for (auto _ : state) {
    mfz_builtin_generate(&a, &pa, &b, &pb, &out);
    benchmark::DoNotOptimize(out);
  }
  state.counters["contacts"] = out.contact_count;
}

void BM_BoxOnBoxFaceContact(benchmark::State& state) {
  CaseFile c;
  c.points_a = props::box_corners(2, 2, 0.5);
  c.points_b = props::box_corners(0.5, 0.5, 0.5);
  c.pose_b = {Vec3(0.1, 0.2, 0.9), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))};
  run_queries(state, *make_scene(c).scene);
}
BENCHMARK(BM_BoxOnBoxFaceContact);

void BM_Two32PointHulls(benchmark::State& state) {
  std::mt19937_64 random(0x1ee7c0de);
  CaseFile c;
  c.points_a = bench::sphere_cloud(32, random);
  c.points_b = bench::sphere_cloud(32, random);
  c.pose_b = {Vec3(0.3, 0.2, 1.4), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  run_queries(state, *make_scene(c).scene);
}
BENCHMARK(BM_Two32PointHulls);

}  // namespace
}  // namespace mfz

BENCHMARK_MAIN();
