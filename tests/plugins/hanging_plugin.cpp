// A generator that never returns on a vertex contact: the harness must report
// `hang` after its per-call time limit, and go on.
#include "generator/builtin_generator.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "hangs-on-single-contacts"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  const int32_t status = mfz_builtin_generate(a, pa, b, pb, out);
  volatile bool spin = out->contact_count == 1;
  while (spin) {
  }
  return status;
}
}
