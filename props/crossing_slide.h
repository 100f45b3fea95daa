#pragma once
/// \file
/// Where a contact may slide between two runs of a relation: a crossing of an
/// incident edge with a side plane of the reference face moves along that
/// edge by the frame's rounding over the sine of the angle between them, and
/// both places are right (docs/contract.md, "Metamorphic relations").
#include <vector>

#include "case/scene.h"

namespace mfz::props {

/// One way a contact may slide: its point on the incident hull along that
/// hull's edge (`along_incident`, unit), its point on the reference hull
/// along the edge's shadow on the reference plane, by s in [least, most].
struct CrossingSlide {
  bool incident_is_a = false;
  Vec3 along_incident, along_reference;
  double least = 0, most = 0;
};

/// The slides of the contact (on_a, on_b) of a manifold with normal `normal`
/// (from A to B): for each edge of one hull the contact's point lies on and
/// each edge of the other hull its other point lies on (within `on_edge`),
/// the side plane through the second edge along the normal, and the first
/// edge's sine against it. A slide reaches `rounding` / sine either way, no
/// further than the edge's ends; slides that reach no further than
/// `worth` are left out, since the plain comparison covers them.
std::vector<CrossingSlide> crossing_slides(const Scene& scene, const Vec3& normal, const Vec3& on_a, const Vec3& on_b,
                                           double on_edge, double rounding, double worth);

}  // namespace mfz::props
