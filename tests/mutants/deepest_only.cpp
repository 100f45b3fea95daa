// Bug: keeps only the deepest contact, as a generator that reports "the"
// contact point would. Every contact is right; the manifold is incomplete.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-deepest-only";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  if (m.contact_count <= 1) return;
  int deepest = 0;
  for (int i = 1; i < m.contact_count; ++i)
    if (m.contacts[i].penetration < m.contacts[deepest].penetration) deepest = i;
  m.contacts[0] = m.contacts[deepest];
  m.contact_count = 1;
}
