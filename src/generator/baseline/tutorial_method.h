#pragma once
/// \file
/// The tutorial's clipping method as written ("Physics Tutorial 5: Collision
/// Manifolds", CollisionDetectionSAT::GenContactPoints), before the harness's
/// findings fixed it: kept beside the built-in generator so that every
/// finding's case can be replayed against the method it was found in
/// (`expect-tutorial` in corpus/regressions). It shares the built-in's leaf
/// steps (significant face, Sutherland-Hodgman pass, contact emission) and
/// none of its fixes.
#include "generator/clipping_generator.h"

namespace mfz {

/// SAT as the tutorial runs it: A's faces, B's faces, then every edge pair;
/// the smaller overlap of each axis either way round; a candidate replaces
/// the best only when strictly smaller, so the earlier axis wins a tie. Stops
/// at the first separating axis. Allocates nothing.
SatResult tutorial_sat(const PosedHull& a, const PosedHull& b);

/// The tutorial's clip: Sutherland-Hodgman against the planes of the faces
/// adjacent to the reference face. Wrong where those faces slope inwards
/// (FINDINGS.md F1). False if a buffer would overflow.
bool clip_to_adjacent_face_planes(const ClipFace& reference, ClipPolygon& incident);

/// The tutorial's manifold for hulls a and b at their poses, in world
/// coordinates. Returns 0, or 1 when a face is too large for its buffers.
int32_t generate_tutorial_manifold(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b,
                                   const mfz_pose& pose_b, mfz_manifold& out);

}  // namespace mfz
