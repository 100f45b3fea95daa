// A plugin that speaks a future ABI version: the harness must refuse to load it.
#include "manifuzz/abi.h"

extern "C" {
int32_t mfz_abi_version(void) { return 2; }
const char* mfz_generator_name(void) { return "from-the-future"; }
int32_t mfz_generate(const mfz_hull*, const mfz_pose*, const mfz_hull*, const mfz_pose*, mfz_manifold*) { return 0; }
}
