// Bug only near touching: an absolute slop of 1e-6 units, below which a
// penetration is reported as no collision.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-near-touching";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& out) {
  if (out.colliding == 1 && -out.penetration < 1e-6) out.colliding = 0, out.contact_count = 0;
}
