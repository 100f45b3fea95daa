// Bug, under a float profile: single precision (float_rounding.h) and the
// clip against the reference face's side planes skipped. The float profile
// must not hide a fault of the logic.
#define MUTANT_PROFILE "precision=float"
#include "float_rounding.h"
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-float-side-clip-skipped";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.clip_to_sides = [](const mfz::ClipFace&, mfz::ClipPolygon&, mfz::ClipTrace*) { return true; };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose& pa, const mfz_hull&, mfz_pose& pb) { round_pose(pa), round_pose(pb); }
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  round_manifold(m);
}
