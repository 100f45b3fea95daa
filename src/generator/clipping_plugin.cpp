// The built-in generator as a stand-alone plugin (libmanifuzz_clipping.so), so
// that other harnesses, and this one's plugin path, can load it like any other.
#include "generator/builtin_generator.h"

extern "C" {
__attribute__((visibility("default"))) int32_t mfz_abi_version(void) { return mfz_builtin_abi_version(); }
__attribute__((visibility("default"))) const char* mfz_generator_name(void) { return mfz_builtin_generator_name(); }
__attribute__((visibility("default"))) int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pose_a,
                                                            const mfz_hull* b, const mfz_pose* pose_b,
                                                            mfz_manifold* out) {
  return mfz_builtin_generate(a, pose_a, b, pose_b, out);
}
}
