#pragma once
/// \file
/// The exact distance between two separated hulls, by brute force over their
/// features: each vertex of one against each face polygon of the other, and
/// each edge against each edge. For convex polyhedra the nearest pair of
/// points is one of those, so the minimum is the gap, to rounding of the
/// world coordinates alone. Independent of Qhull and of any axis test.
#include "case/scene.h"

namespace mfz {

struct HullGap {
  double distance = 0;
  Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();  ///< a nearest pair of points
};

/// Meaningful only when the posed hulls do not overlap (otherwise some
/// feature pairs meet and the answer is 0).
HullGap hull_gap(const Scene& scene);

}  // namespace mfz
