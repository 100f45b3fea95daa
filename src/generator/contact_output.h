#pragma once
/// \file
/// Writing one contact into a manifold: the two points and the contact's own
/// penetration. Callers keep contact_count below MFZ_MAX_CONTACTS.
#include "geometry/vec.h"
#include "manifuzz/abi.h"

namespace mfz {

inline void add_contact(mfz_manifold& out, const Vec3& on_a, const Vec3& on_b, double penetration) {
  mfz_contact& c = out.contacts[out.contact_count++];
  c.point_on_a = to_abi(on_a);
  c.point_on_b = to_abi(on_b);
  c.penetration = penetration;
}

}  // namespace mfz
