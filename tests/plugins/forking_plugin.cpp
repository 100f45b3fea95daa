// A correct generator that starts a helper process on its first call and
// writes the helper's pid to $MFZ_TEST_CHILD_PID_FILE: when the harness is
// done, or dies, the helper must be gone too.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "generator/builtin_generator.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "forks-a-helper"; }
int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pa, const mfz_hull* b, const mfz_pose* pb, mfz_manifold* out) {
  static bool started = false;
  if (!started) {
    started = true;
    const pid_t child = fork();
    if (child == 0) {
      for (;;) pause();
    }
    if (const char* file = std::getenv("MFZ_TEST_CHILD_PID_FILE")) {
      if (FILE* f = std::fopen(file, "w")) std::fprintf(f, "%d\n", static_cast<int>(child)), std::fclose(f);
    }
  }
  return mfz_builtin_generate(a, pa, b, pb, out);
}
}
