// Broken: the built-in generator writing its contacts through a ring whose
// cursor persists from call to call (a contact cache's write position never
// reset), so the same input gives the same contacts in another order on
// the next call. `deterministic` must catch it.
#include "mutant_plugin.h"

const char* const mutant::name = "persistent-cursor";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold& m) {
  static thread_local int cursor = 0;
  if (m.contact_count < 2) return;
  std::rotate(m.contacts, m.contacts + cursor++ % m.contact_count, m.contacts + m.contact_count);
}
