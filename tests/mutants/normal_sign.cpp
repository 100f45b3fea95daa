// Bug: the normal is reported from B towards A.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-normal-sign";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& out) {
  out.normal = {-out.normal.x, -out.normal.y, -out.normal.z};
}
