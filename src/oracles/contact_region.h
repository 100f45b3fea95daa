#pragma once
/// \file
/// The contact region of two overlapping hulls, from the hulls alone: their
/// intersection, projected onto the contact plane (perpendicular to n). The
/// completeness invariant (spans-contact-region) asks that a manifold's
/// contacts enclose its centroid. Nothing here uses the generator's method.
#include <vector>

#include "case/scene.h"

namespace mfz {

struct ContactRegion {
  bool empty = true;
  /// Area centroid of the projected intersection (the middle of a segment,
  /// the point itself), on the plane through the origin perpendicular to n,
  /// in the plane's coordinates (u, v).
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  /// Greatest distance between two points of the projected region.
  double width = 0;
  /// The projected region's corners, counter-clockwise.
  std::vector<Eigen::Vector2d> corners;
  /// How many faces of A (of B) facing the other hull, within kFoldAngle of
  /// n, the region lies against: two or more is a face folded under it.
  int facing_faces_a = 0, facing_faces_b = 0;
};

/// A basis (u, v) of the plane perpendicular to unit `n`.
void plane_basis(const Vec3& n, Vec3& u, Vec3& v);

/// The intersection of A and B (B moved by `shift_b`), projected onto the
/// plane perpendicular to unit `n`. `slack` (a length) keeps points on a
/// boundary within rounding.
ContactRegion contact_region(const Scene& scene, const Vec3& n, const Vec3& shift_b, double slack);

/// No contact_region(scene, n, shift_b, slack) is wider than this: its
/// corners lie within the slack of both hulls, so within each hull's section
/// by the slab where the two overlap along n, and within the bounding
/// rectangles of those sections' shadows.
double region_width_bound(const Scene& scene, const Vec3& n, const Vec3& shift_b, double slack);

/// The convex hull of `points`, counter-clockwise (collinear points dropped).
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points);
/// The area of the convex hull of `points` (0 for fewer than three).
double convex_hull_area_2d(const std::vector<Eigen::Vector2d>& points);

/// The distance from point `p` to the convex hull of `points` (0 inside).
double distance_to_convex_hull_2d(const Eigen::Vector2d& p, std::vector<Eigen::Vector2d> points);

}  // namespace mfz
