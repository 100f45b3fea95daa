// Cases per second on one core, on random 8-point and 32-point hulls: the
// whole property (the generator, the oracles, every invariant and every
// relation, which run the generator nine more times), and the invariants
// alone (one generator call, the oracles, the thirteen checks); then each
// stage of a case alone.
#include <benchmark/benchmark.h>

#include <random>

#include "bench_cases.h"

#include "case_property.h"
#include "geometry/tolerances.h"
#include "relations.h"

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

// Where a case's time goes, stage by stage, on the same 8- and 32-point
// cases: building the scene (both hulls: the 64 cases' 128 hulls are more
// than the hull cache keeps, so each is built again, as for a fuzz input of
// new points), one generator call, the oracles together and each alone, the
// invariants, and each relation whole (its generator calls and the
// invariants of its runs). On 32-point hulls the stages add up to about
// the case's time; on 8-point hulls to four fifths of it (each stage runs
// hot in the cache here).
void BM_CaseStage(benchmark::State& state, const std::string& stage) {
  const std::vector<CaseFile> cases = random_cases(static_cast<int>(state.range(0)));
  const auto session = in_process_session(Generator::builtin());
  struct Ready {
    Scene scene;
    OracleAnswers oracles;
    mfz_manifold manifold;
  };
  std::vector<Ready> ready;
  for (const CaseFile& c : cases) {
    Scene scene = *make_scene(c).scene;
    OracleAnswers oracles = consult_oracles(scene);
    mfz_manifold manifold{};
    int32_t status = 0;
    std::string failure;
    const mfz_hull a = scene.hull_a.view(), b = scene.hull_b.view();
    const mfz_pose pa = scene.abi_pose_a(), pb = scene.abi_pose_b();
    session->generate(a, pa, b, pb, manifold, status, failure);
    ready.push_back({std::move(scene), std::move(oracles), manifold});
  }
  size_t k = 0;
  for (auto _ : state) {
    const size_t i = k++ % cases.size();
    const Ready& r = ready[i];
    const Scene& s = r.scene;
    if (stage == "scene") {
      benchmark::DoNotOptimize(make_scene(cases[i]));
    } else if (stage == "generator") {
      const mfz_hull a = s.hull_a.view(), b = s.hull_b.view();
      const mfz_pose pa = s.abi_pose_a(), pb = s.abi_pose_b();
      mfz_manifold m;
      int32_t status = 0;
      std::string failure;
      benchmark::DoNotOptimize(session->generate(a, pa, b, pb, m, status, failure));
    } else if (stage == "oracles") {
      benchmark::DoNotOptimize(consult_oracles(s));
    } else if (stage == "brute-force-sat") {
      benchmark::DoNotOptimize(rank_sat_axes(s));
    } else if (stage == "exact-depth") {
      benchmark::DoNotOptimize(exact_depth(s, r.oracles.sat_axes));
    } else if (stage == "libccd") {
      benchmark::DoNotOptimize(ask_libccd(s));
    } else if (stage == "ties") {
      benchmark::DoNotOptimize(
          classify_ties(s, r.oracles.sat_axes, s.length_tolerance(tol::kTie), r.oracles.least_reverse_overlap));
    } else if (stage == "invariants") {
      benchmark::DoNotOptimize(check_manifold(s, r.oracles, 0, r.manifold, {}, PassDetails::left_out));
    } else {
      const props::RelationInput input{cases[i], s, r.manifold, r.oracles};
      benchmark::DoNotOptimize(props::check_relation(stage, input, *session));
    }
  }
  state.SetItemsProcessed(state.iterations());
}

const bool stages_registered = [] {
  std::vector<std::string> stages = {"scene", "generator", "oracles", "brute-force-sat", "exact-depth", "libccd", "ties",
                                     "invariants"};
  for (const std::string& name : props::relation_names()) stages.push_back(name);
  for (const std::string& stage : stages)
    benchmark::RegisterBenchmark(("BM_CaseStage/" + stage).c_str(), BM_CaseStage, stage)
        ->Arg(8)
        ->Arg(32)
        ->Unit(benchmark::kMicrosecond);
  return true;
}();

}  // namespace
}  // namespace mfz
