#pragma once
/// \file
/// What the geometry of a case leaves open (docs/contract.md, "Ties"), read
/// from the hulls and the brute-force SAT's ranked axes alone. A correct
/// generator may answer either way in a tie, so the relations compare only
/// what is determined: at the contract level, depth always; the normal unless
/// another direction is minimal; the contact set only when none of the other
/// ties holds.
#include <vector>

#include "case/scene.h"
#include "oracles/brute_force_sat.h"

namespace mfz {

struct Ties {
  /// Another candidate within the tie tolerance points another way, or the
  /// reverse of the best axis is minimal too: only depth is determined.
  bool direction = false;
  /// Another candidate along the same direction comes from another feature
  /// (two faces of one hull, a face of each, a face and an edge pair): the
  /// contact set is open, except that a single contact must lie in the region
  /// of the other answer's contacts.
  bool feature = false;
  /// Two or more faces through the incident hull's support are equally
  /// aligned with the normal (mirror faces, a folded face, a cube's corner).
  bool incident_face = false;
  /// An edge-pair axis is minimal and a hull has more than one edge at its
  /// support (a thin face, parallel edges).
  bool supporting_edge = false;

  /// Under a profile's precision (float) only: a face of either hull is
  /// perpendicular to the normal within that precision, so whether it faces
  /// the other hull, and adds its points to the contacts, is rounding (a
  /// float variant on a tetrahedron inside a cylinder: one of its side faces
  /// faced the cylinder's face in one frame and not in the moved one).
  bool perpendicular_face = false;

  bool any() const { return direction || feature || incident_face || supporting_edge || perpendicular_face; }
  /// The contact set is not determined by the geometry.
  bool contacts_open() const { return feature || incident_face || supporting_edge || perpendicular_face; }
};

/// Classifies the ties of `scene` given its ranked axes (best first) and
/// their least_reverse_overlap (brute_force_sat.h). `tie` is the overlap
/// tolerance (a length); the support window is tol::kSupportWindow L plus
/// the world frame's rounding.
Ties classify_ties(const Scene& scene, const std::vector<RankedAxis>& ranked, double tie, double least_reverse);

/// The ties along `normal`, a face axis a face-bias profile let the
/// generator take though it is not the least: the candidates along it and
/// within `tie` of its overlap, as classify_ties reads them about the least
/// axis. Shallower axes are choices the generator did not make. Where no
/// face axis lies along `normal`, only depth is determined (`direction`).
Ties classify_ties_along(const Scene& scene, const std::vector<RankedAxis>& ranked, const Vec3& normal, double tie);

}  // namespace mfz
