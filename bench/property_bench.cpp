// Cases per second on one core, on random 8-point and 32-point hulls: the
// whole property (the generator, the oracles, every invariant and every
// relation, which run the generator nine more times), and the invariants
// alone (one generator call, the oracles, the thirteen checks).
#include <benchmark/benchmark.h>

#include <random>

#include "bench_cases.h"

#include "case_property.h"

namespace mfz {
namespace {

std::vector<CaseFile> random_cases(int points) {
  std::mt19937_64 random(0x1ee7c0de);
  std::vector<CaseFile> cases;
  for (int k = 0; k < 64; ++k) cases.push_back(bench::random_cloud_pair(points, random));
  return cases;
}

void run_cases(benchmark::State& state, const props::Selection& selection) {
  const std::vector<CaseFile> cases = random_cases(static_cast<int>(state.range(0)));
  const auto session = in_process_session(Generator::builtin());
  size_t k = 0;
  for (auto _ : state) {
    const props::CaseOutcome o = props::check_case(cases[k++ % cases.size()], *session, selection);
    if (o.finding) state.SkipWithError(("a finding: " + o.finding->name).c_str());
    benchmark::DoNotOptimize(o);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_WholePropertyPerCase(benchmark::State& state) { run_cases(state, {}); }
BENCHMARK(BM_WholePropertyPerCase)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

void BM_InvariantsPerCase(benchmark::State& state) {
  const std::vector<std::string>& names = invariant_names();
  run_cases(state, props::Selection{{names.begin(), names.end()}});
}
BENCHMARK(BM_InvariantsPerCase)->Arg(8)->Arg(32)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mfz
