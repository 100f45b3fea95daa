#pragma once
/// \file
/// Coplanar patches: the faces joined to a face by flat steps (each face's
/// normal within tol::kCoplanarSine of the face it is reached from), the
/// same faces from whichever of them the patch is gathered (F60), and the
/// patch's boundary loop, which runs along edges of the polyhedron.
#include "generator/clip_polygon.h"
#include "geometry/posed_hull.h"

namespace mfz {

/// The boundary of the patch around `face`, world space, counter-clockwise
/// about the face's normal; the face's own loop when it stands alone.
void coplanar_patch(const PosedHull& hull, int face, ClipPolygon& out);
/// The most corners a patch's loop has: every vertex of a hull the harness
/// takes (at most 1,024 points). At 512 a face of more corners was cut
/// short (F61).
inline constexpr int kMaxPatchLoop = 1024;
/// The same loop as the hull's vertex indices, in coplanar_patch's order:
/// writes at most kMaxPatchLoop to `loop` and returns how many, and in
/// `members` how many faces the patch holds; with `faces` (room for
/// kMaxPatchFaces), the patch's faces where it holds more than one.
int patch_loop(const PosedHull& hull, int face, int* loop, int& members, int* faces = nullptr);
/// The most faces a patch gathers; a patch that reaches it may hold more. A
/// face of a hull the harness takes, fanned into triangles, is at most
/// 1,021 of them; at 256 a triangulated 300-gon cap gathered a wedge of
/// itself, which triangle it started from chose (F61).
inline constexpr int kMaxPatchFaces = 1024;
/// The world points of a loop of vertex indices, in its order.
void loop_points(const PosedHull& hull, const int* loop, int size, ClipPolygon& out);
/// The patch's area (the same whether the face arrived whole or triangulated).
double patch_area(const PosedHull& hull, int face);

}  // namespace mfz
