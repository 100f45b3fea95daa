#pragma once
// The frame of every deliberately broken generator: the built-in generator's
// steps with one replaced (MUTANT_STEPS), or its output post-processed
// (MUTANT_AFTER). Each mutant file defines a name and one of the two.
#include <algorithm>
#include <cmath>

#include "generator/clip_polygon.h"
#include "generator/clipping_generator.h"
#include "geometry/tolerances.h"

namespace mutant {
/// The steps the mutant runs.
mfz::ClippingSteps steps();
/// Changes the finished manifold (identity unless the mutant says otherwise).
void after(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b, const mfz_pose& pose_b, mfz_manifold& out);
/// Changes the input poses (identity unless the mutant says otherwise).
void before(const mfz_hull& a, mfz_pose& pose_a, const mfz_hull& b, mfz_pose& pose_b);
extern const char* const name;
}  // namespace mutant

// A variant that declares a profile defines MUTANT_PROFILE before including
// this file; the others declare none.
#ifdef MUTANT_PROFILE
extern "C" __attribute__((visibility("default"))) const char* mfz_generator_profile(void) { return MUTANT_PROFILE; }
#endif

#define MFZ_EXPORT extern "C" __attribute__((visibility("default")))

MFZ_EXPORT int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
MFZ_EXPORT const char* mfz_generator_name(void) { return mutant::name; }
MFZ_EXPORT int32_t mfz_generate(const mfz_hull* a, const mfz_pose* pose_a, const mfz_hull* b, const mfz_pose* pose_b,
                                mfz_manifold* out) {
  static const mfz::ClippingSteps steps = mutant::steps();
  mfz_pose pa = *pose_a, pb = *pose_b;
  mutant::before(*a, pa, *b, pb);
  const int32_t status = mfz::generate_clipping_manifold(*a, pa, *b, pb, *out, nullptr, steps);
  mutant::after(*a, pa, *b, pb, *out);
  return status;
}
