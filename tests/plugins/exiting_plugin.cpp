// A generator that calls exit(0) on a face contact, as an engine's fatal
// error handler might: a finding (`crash`), never a silent end of the harness
// with status 0.
#include <cstdlib>

#include "generator/builtin_generator.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "exits-on-face-contacts"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  const int32_t status = mfz_builtin_generate(a, pa, b, pb, out);
  if (out->contact_count >= 3) std::exit(0);
  return status;
}
}
