// Bug: declares max-contacts=4 and keeps the first four contacts in the
// order the clipping made them, as `count = std::min(count, 4)` does. Each
// kept point is right; on a face of more than four corners they bunch on one
// side of the contact region, and a stack rocks over the other.
#define MUTANT_PROFILE "max-contacts=4"
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-truncating-reducer";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  m.contact_count = std::min(m.contact_count, 4);
}
