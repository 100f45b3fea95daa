#include "harness/case_run.h"

namespace mfz {

std::optional<CaseRun> run_case(const CaseFile& c, const Generator& generator, std::string& error) {
  SceneBuild built = make_scene(c);
  if (!built.scene) {
    error = built.error;
    return std::nullopt;
  }
  CaseRun run{std::move(*built.scene), {}, {}, {}};
  const mfz_hull a = run.scene.hull_a.view(), b = run.scene.hull_b.view();
  const mfz_pose pa = run.scene.abi_pose_a(), pb = run.scene.abi_pose_b();
  const int32_t status = generator.generate(a, pa, b, pb, run.manifold);
  run.oracles = consult_oracles(run.scene);
  run.verdict = check_manifold(run.scene, run.oracles, status, run.manifold);
  return run;
}

}  // namespace mfz
