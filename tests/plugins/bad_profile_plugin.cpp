// A generator whose declared profile the harness cannot read: a load error
// in every command, never a silent contract-level run.
#include "manifuzz/abi.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "bad-profile"; }
const char* mfz_generator_profile(void) { return "precision=quad"; }
int32_t mfz_generate(const mfz_hull*, const mfz_pose*, const mfz_hull*, const mfz_pose*, mfz_manifold* out) {
  out->colliding = 0;
  out->contact_count = 0;
  return 0;
}
}
