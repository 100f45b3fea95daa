#include "generator/builtin_generator.h"

#include "generator/clipping_generator.h"

extern "C" {

int32_t mfz_builtin_abi_version(void) { return MFZ_ABI_VERSION; }

const char* mfz_builtin_generator_name(void) { return "manifuzz-clipping"; }

int32_t mfz_builtin_generate(const mfz_hull* a, const mfz_pose* pose_a, const mfz_hull* b, const mfz_pose* pose_b,
                             mfz_manifold* out) {
  if (!a || !pose_a || !b || !pose_b || !out) return 1;
  static const mfz::ClippingSteps steps = [] {
    mfz::ClippingSteps s;
    s.box_path = true;
    return s;
  }();
  return mfz::generate_clipping_manifold(*a, *pose_a, *b, *pose_b, *out, nullptr, steps);
}
}
