// A correct generator that chatters on stdout and stderr on every call, as
// debugging code left in an engine does: the harness's stdout must stay
// VIOLATION lines and JSON only.
#include <cstdio>

#include "generator/builtin_generator.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "prints-on-every-call"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  std::printf("debug: generating\n");
  std::fflush(stdout);
  std::fprintf(stderr, "debug: on stderr\n");
  return mfz_builtin_generate(a, pa, b, pb, out);
}
}
