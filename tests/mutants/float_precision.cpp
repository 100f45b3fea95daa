// Correct under its profile: the built-in with its poses and results in
// single precision (float_rounding.h). It declares precision=float; held to
// double's tolerances (--profile precision=double) it fails, which shows the
// profile is what lets it pass.
#define MUTANT_PROFILE "precision=float"
#include "float_rounding.h"
#include "mutant_plugin.h"

const char* const mutant::name = "correct-float-precision";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose& pa, const mfz_hull&, mfz_pose& pb) { round_pose(pa), round_pose(pb); }
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  round_manifold(m);
}
