// Bug: every contact is given the manifold's penetration instead of its own
// (points kept consistent along the normal).
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-uniform-depth";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& out) {
  for (int i = 0; i < out.contact_count; ++i) {
    mfz_contact& c = out.contacts[i];
    c.penetration = out.penetration;
    c.point_on_b = {c.point_on_a.x + out.penetration * out.normal.x, c.point_on_a.y + out.penetration * out.normal.y,
                    c.point_on_a.z + out.penetration * out.normal.z};
  }
}
