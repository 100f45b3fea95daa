// A generator that dereferences a null pointer on any face contact: the
// harness must report `crash` with a shrunk case, and survive.
#include <csignal>

#include "generator/builtin_generator.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "crashes-on-face-contacts"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  const int32_t status = mfz_builtin_generate(a, pa, b, pb, out);
  if (out->contact_count >= 3) std::raise(SIGSEGV);
  return status;
}
}
