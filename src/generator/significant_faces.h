#pragma once
/// \file
/// The significant faces of the clipping method: for a hull and a direction
/// (n for A, -n for B), the face the contact is clipped from or against. The
/// tutorial's rule is the face holding the vertex furthest along the
/// direction, the most parallel one; the built-in widens "the vertex" to the
/// support (every vertex as far within rounding) and clips every face the
/// support leaves undecided.
#include "geometry/posed_hull.h"

namespace mfz {

/// The face of `hull` the tutorial calls significant for `direction`: of the faces
/// that contain the vertex furthest along `direction`, the one whose normal is
/// most parallel to it (first of equals). Sets `support` to that vertex.
/// With `over_ties`, every vertex within rounding of the furthest is support,
/// and a face holding more of it wins before the more parallel one (F10, F24).
int significant_face(const PosedHull& hull, const Vec3& direction, int& support, bool over_ties = false);

/// The incident faces to clip (F11, F24, F25): every face as parallel as the
/// most parallel, and the face holding the most of the support with its
/// equals; at most `capacity` into `out`. Returns the count.
int tied_significant_faces(const PosedHull& hull, const Vec3& direction, int* out, int capacity);

/// Orders `faces` (stably) so that those as parallel to `direction` as the
/// most parallel of them come first, and returns how many they are; the
/// rest are held for the support alone (F24), and are clipped as F27's
/// faces are (F58).
int parallel_faces_first(const PosedHull& hull, const Vec3& direction, int* faces, int count);

}  // namespace mfz
