// A generator whose recursion never ends on a face contact: a stack
// overflow is a `crash` finding, and the harness survives it.
#include "generator/builtin_generator.h"

namespace {
volatile int sink = 0;
// The recursion without end is the point: compilers that see it say so.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Winfinite-recursion"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Winfinite-recursion"
#endif
int deeper(int n) {
  volatile char frame[4096];
  frame[0] = static_cast<char>(n);
  return deeper(n + 1) + frame[0] + sink;
}
}  // namespace

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "overflows-its-stack-on-face-contacts"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  const int32_t status = mfz_builtin_generate(a, pa, b, pb, out);
  if (out->contact_count >= 3) sink = deeper(0);
  return status;
}
}
