#pragma once
/// \file
/// The built-in contact-manifold generator: the tutorial's clipping method
/// ("Physics Tutorial 5: Collision Manifolds", docs/generator.md), fixed where
/// the harness showed it wrong (FINDINGS.md), with the project's conventions.
#include <string>
#include <vector>

#include "manifuzz/abi.h"
#include "generator/clip_polygon.h"
#include "generator/sat.h"
#include "generator/significant_faces.h"

namespace mfz {

/// What the generator did, step by step, for `manifuzz explain`. Filled only
/// when a trace is asked for; the hot path passes nullptr and allocates nothing.
struct ClipTrace {
  SatResult sat;
  int face_a = -1, face_b = -1;  ///< significant faces
  int support_a = -1, support_b = -1;  ///< the vertices they were chosen from
  bool flipped = false;          ///< true: B's face is the reference face
  bool edge_contact = false;     ///< the contact came from the two supporting edges
  struct Step {
    std::string what;
    std::vector<Vec3> polygon;
  };
  std::vector<Step> steps;       ///< the incident polygon after each clip
};

/// The sides of the prism over a reference polygon of up to this many
/// corners are computed once per call and kept; a larger polygon's are
/// computed as each is clipped against.
inline constexpr int kKeptPrismSides = 64;

/// The caps of a loop's extent (F65), where an acute corner's edges are too
/// short for a cap of its own.
inline constexpr int kExtentCaps = 4;

/// The kept sides of the reference prism (reference_side for each edge of
/// the loop, in loop order). Every face clipped against the prism reads
/// them: the incident faces, and F27's faces below the reference plane
/// (a 64-gon cap's sides were computed again for each of its cylinder's
/// faces, 4% of the benchmark's instructions).
struct PrismSides {
  int count = 0;  ///< the loop's size; 0: not kept
  Plane plane[kKeptPrismSides];
  SideEdge edge[kKeptPrismSides];
  bool spans[kKeptPrismSides];  ///< false for an edge of no length
  /// The caps of the loop's sharp corners (sharp_corner_cap), in loop
  /// order. A sharp corner is acute, and a convex loop has at most three
  /// acute corners (their outer angles, each over 90 degrees, sum to at most
  /// 360); one more is room for a loop that rounding bends, and four more
  /// for the loop's extent (F65). Room for one a side put the sanitized
  /// build's call past 64 KiB of stack (66,616 bytes).
  static constexpr int kMaxCaps = 4 + kExtentCaps;
  Plane cap[kMaxCaps];
  int cap_count = 0;
  /// The loop's largest coordinate, which side_bands reads for every face
  /// clipped (kept whatever the loop's size).
  double largest = 0;
};

/// A significant face in world space, and the polygon that stands for it.
struct ClipFace {
  const PosedHull* hull = nullptr;
  int index = -1;
  Vec3 normal;  ///< world, outward
  const ClipPolygon* polygon = nullptr;  ///< world loop, counter-clockwise about normal
  /// The magnitude of the world the frame's positions were rounded in: the
  /// longer pose position (the frame itself is centred on A, F21; a length,
  /// which a turn of the world keeps, F35).
  double world_resolution = 0;
  /// The reference prism's sides, when kept (keep_prism_sides).
  const PrismSides* sides = nullptr;
  /// A polygon the clip against the prism may use as its other buffer;
  /// null: it takes one on the stack.
  ClipPolygon* scratch = nullptr;
};

/// The generator's steps, each replaceable: the project's deliberately broken
/// generators (tests/mutants) swap one step each, so the harness can be shown
/// to catch each bug. The defaults are the built-in generator.
struct ClippingSteps {
  /// The separating-axis test.
  SatResult (*sat)(const PosedHull& a, const PosedHull& b) = run_sat;
  /// F11: the incident faces to clip, all equally aligned (at most `capacity`
  /// into `out`); the count is returned.
  int (*incident_faces)(const PosedHull& hull, const Vec3& direction, int* out, int capacity);
  /// The world polygon of a significant face.
  void (*face_polygon)(const PosedHull& hull, int face, ClipPolygon& out);
  /// True when B's significant face is the reference face.
  bool (*reference_is_b)(const SatResult& sat, const ClipFace& face_a, const ClipFace& face_b);
  /// Clips the incident polygon against the reference face's side planes;
  /// false if a buffer would overflow.
  bool (*clip_to_sides)(const ClipFace& reference, ClipPolygon& incident, ClipTrace* trace);
  /// On an edge-edge axis: writes the contact(s) into `out` and returns true,
  /// or returns false to clip faces as for a face axis.
  bool (*edge_contact)(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out);
  /// Writes the contacts for the clipped points into `out`.
  void (*emit_contacts)(const ClipFace& reference, const ClipPolygon& clipped, const Vec3& n, bool flipped,
                        mfz_manifold& out);
  /// Two boxes whose face axis and incident face clear every tie take the
  /// box path (generator/box_axis.h), which answers as the steps
  /// above would. The built-in sets it; a variant that changes a step
  /// leaves it off, so that its change is met by every pair.
  bool box_path = false;
  ClippingSteps();
};

/// A face's own loop as its polygon.
void face_loop(const PosedHull& hull, int face, ClipPolygon& out);

/// F3: the closest points of the two supporting edges are the one contact.
bool closest_points_of_edges(const PosedHull& a, const PosedHull& b, const SatResult& sat, mfz_manifold& out);

/// The tutorial's single-point branch: when a significant face has fewer than
/// three vertices (only a malformed hull handed in through the ABI), the
/// support point is the one contact. True when it applied.
bool single_point_contact(const ClipFace& face_a, int support_a, const ClipFace& face_b, int support_b,
                          const Vec3& n, mfz_manifold& out);

/// The tutorial's rule: the significant face more parallel to n is the reference.
bool more_parallel_is_reference_b(const SatResult& sat, const ClipFace& face_a, const ClipFace& face_b);
/// F13: on a face axis, that face is the reference face; otherwise the tutorial's rule.
bool sat_face_is_reference(const SatResult& sat, const ClipFace& face_a, const ClipFace& face_b);
/// The bands of the reference prism's sides for clip_to_plane: a point within
/// `on_plane` of a side is on it (F23); an outside point within `near_plane`
/// crosses it at its foot (F32, the world's rounding).
struct SideBands {
  double on_plane = 0, near_plane = 0;
  /// An incident edge this near a side plane, as a sine, lies in it; the
  /// sine times the longest edge the incident polygon can have, past which
  /// no point lies in such an edge.
  double in_plane_sine = 0, in_plane_band = 0;
};
SideBands side_bands(const ClipFace& reference, const ClipPolygon& incident);
/// The side of the reference prism through edge k of the reference loop:
/// the plane through the edge perpendicular to the face, facing out, and the
/// edge itself (F36 bounds a foot crossing by it). False for an edge of no
/// length.
bool reference_side(const ClipFace& reference, int k, Plane& side, SideEdge& edge);
/// The cap of corner k of a reference loop: the plane through the corner
/// across its bisector, facing out, when the corner is so sharp that its two
/// sides, each placed to `rounding`, may cross further than 1e-9 of its
/// longer edge from it (rounding over the corner's sine). False for any other
/// corner, and for one whose edges are too short for their directions to
/// be known. The polygon lies behind the cap, so clipping against it takes
/// nothing away; it holds the clip to the corner where the sides do not.
bool sharp_corner_cap(const ClipPolygon& loop, int k, double rounding, Plane& cap);
/// The rounding sharp_corner_cap is given for the reference face: the
/// world's, at the larger of the loop's largest coordinate and the frame's
/// resolution.
double corner_rounding(const ClipFace& reference);
/// Computes each side of the prism over `reference`'s polygon into `sides`,
/// when it has at most kKeptPrismSides corners (else sides.count is 0), the
/// caps of its sharp corners, and the loop's largest coordinate.
void keep_prism_sides(const ClipFace& reference, PrismSides& sides);
/// Side k of the reference prism and the edge it stands on: the kept ones,
/// read where they are, when `reference` has them, else reference_side's,
/// computed into `computed` and `computed_edge`. A null plane for an edge
/// of no length. Inline, and no copy: copied out for each side of each
/// face clipped, the kept sides were a tenth of a cylinder pair's call, and
/// called out of line 3%.
struct PrismSide {
  const Plane* plane = nullptr;
  const SideEdge* edge = nullptr;
};
inline PrismSide prism_side(const ClipFace& reference, int k, Plane& computed, SideEdge& computed_edge) {
  const PrismSides* kept = reference.sides;
  if (!kept || kept->count == 0)
    return reference_side(reference, k, computed, computed_edge) ? PrismSide{&computed, &computed_edge} : PrismSide{};
  return kept->spans[k] ? PrismSide{&kept->plane[k], &kept->edge[k]} : PrismSide{};
}
/// Sutherland-Hodgman against the prism over the reference face: through each
/// edge, the plane perpendicular to the face.
bool clip_to_reference_prism(const ClipFace& reference, ClipPolygon& incident, ClipTrace* trace);
/// Each point a contact, its depth measured from the reference polygon along n.
void emit_clipped_contacts(const ClipFace& reference, const ClipPolygon& clipped, const Vec3& n, bool flipped,
                           mfz_manifold& out);

/// Fills `out` for hulls a and b at their poses (orientations unit length).
/// Returns 0, or 1 when it refuses: a face too large for its fixed buffers.
int32_t generate_clipping_manifold(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b,
                                   const mfz_pose& pose_b, mfz_manifold& out, ClipTrace* trace = nullptr,
                                   const ClippingSteps& steps = ClippingSteps());

}  // namespace mfz
