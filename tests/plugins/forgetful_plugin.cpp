// A generator that says "colliding" and forgets to write the normal and the
// contact count: the harness's poisoning must make that visible.
#include "manifuzz/abi.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "forgetful"; }
int32_t mfz_generate(const mfz_hull*, const mfz_pose*, const mfz_hull*, const mfz_pose*, mfz_manifold* out) {
  out->colliding = 1;
  out->penetration = -0.1;
  return 0;
}
}
