// The tutorial's method exactly as written, before the harness's fixes: a plugin
// so that each finding's minimised case can be replayed against it
// (manifuzz replay --generator build/default/plugins/libmanifuzz_tutorial.so corpus/regressions/*).
#include "generator/baseline/tutorial_method.h"

extern "C" {
__attribute__((visibility("default"))) int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
__attribute__((visibility("default"))) const char* mfz_generator_name(void) { return "tutorial-clipping"; }
__attribute__((visibility("default"))) int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pose_a,
                                                            const mfz_hull* b, const mfz_pose* pose_b,
                                                            mfz_manifold* out) {
  if (!a || !pose_a || !b || !pose_b || !out) return 1;
  return mfz::generate_tutorial_manifold(*a, *pose_a, *b, *pose_b, *out);
}
}
