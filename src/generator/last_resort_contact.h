#pragma once
/// \file
/// The last resort of the built-in generator, when neither clipping nor the
/// supporting edges give a contact at a positive depth (F17, F18, F26).
#include "geometry/posed_hull.h"
#include "manifuzz/abi.h"

namespace mfz {

/// Adds one contact: a point of one hull deepest inside the other (a vertex,
/// else a point of an edge running inside), paired with where a ray from it
/// along n leaves the other hull, no further than `depth` (the manifold's).
/// The incident hull (A when `flipped`) is tried first. Adds nothing when
/// neither hull has a point inside the other.
void deepest_point_contact(const PosedHull& a, const PosedHull& b, const Vec3& n, double depth, bool flipped,
                           mfz_manifold& out);

}  // namespace mfz
