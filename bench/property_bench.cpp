// Cases per second of the whole property (generator, oracles, every invariant
// and relation) on one core, on random 8-point and 32-point hulls.
#include <benchmark/benchmark.h>

#include <random>

#include "bench_cases.h"

#include "case_property.h"

namespace mfz {
namespace {

void BM_WholePropertyPerCase(benchmark::State& state) {
  const int points = static_cast<int>(state.range(0));
  std::mt19937_64 random(0x1ee7c0de);
  std::vector<CaseFile> cases;
  for (int k = 0; k < 64; ++k) {
    CaseFile c;
    c.points_a = bench::sphere_cloud(points, random);
    c.points_b = bench::sphere_cloud(points, random);
    std::uniform_real_distribution<double> u(-1, 1);
    c.pose_b = {Vec3(u(random), u(random), u(random)), Quat(Eigen::AngleAxisd(3 * u(random), Vec3(1, 2, 3).normalized()))};
    cases.push_back(c);
  }
  const auto session = in_process_session(Generator::builtin());
  size_t k = 0;
  for (auto _ : state) {
    const props::CaseOutcome o = props::check_case(cases[k++ % cases.size()], *session);
    benchmark::DoNotOptimize(o);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WholePropertyPerCase)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mfz
