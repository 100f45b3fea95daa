#include "generator/arc_bounds.h"

#include <algorithm>

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// One arc's ends p, q and its great circle's normal c = p x q, with
// s2 = |c|^2.
struct LaneArc {
  double px, py, pz, qx, qy, qz;
  double cx, cy, cz, s2;
};

// A margin that is positive exactly when m . v > floor for every unit m on
// the arc and on the margin past its ends (which moves m . v by at most the
// margin times |v|, less than its L1 norm). The least of m . v on the arc
// is at an end, or where the great circle comes nearest to -v, there -|v's
// part in the circle's plane|. Each test is a difference that is positive
// when it passes, "and" is the least of two, "or" the greatest and "not" a
// negation (which takes a zero as failing: a row kept, never one dropped),
// so that every lane computes every term and the loop runs in vector
// lanes: g++ would not vectorise the tests as booleans. Inlined by force:
// clang called it twice a step from the fuzz build's loop, which then ran
// a lane at a time (tests/fuzz_lane_loops_test.sh).
[[gnu::always_inline]] inline double lane_margin(const LaneArc& k, double vx, double vy, double vz, double floor) {
  floor += 2 * kArcBoundMargin * ((vx < 0 ? -vx : vx) + (vy < 0 ? -vy : vy) + (vz < 0 ? -vz : vz));
  const double pv = (k.px * vx + k.py * vy) + k.pz * vz;
  const double qv = (k.qx * vx + k.qy * vy) + k.qz * vz;
  const double ends = std::min(pv, qv) - floor;
  // An arc too short to have an inside lies within the margin of its ends.
  const double ahead = (k.px * k.qx + k.py * k.qy) + k.pz * k.qz;
  const double along = (k.cx * vx + k.cy * vy) + k.cz * vz;
  // -v in the circle's plane, times s2.
  const double nx = along * k.cx - k.s2 * vx, ny = along * k.cy - k.s2 * vy, nz = along * k.cz - k.s2 * vz;
  // Whether that point lies on the arc: (p x n) . c > 0 and (n x q) . c > 0.
  const double pn = ((k.py * nz - k.pz * ny) * k.cx + (k.pz * nx - k.px * nz) * k.cy) + (k.px * ny - k.py * nx) * k.cz;
  const double nq = ((ny * k.qz - nz * k.qy) * k.cx + (nz * k.qx - nx * k.qz) * k.cy) + (nx * k.qy - ny * k.qx) * k.cz;
  const double inside = std::min(pn, nq);
  const double s2 = std::max(k.s2, kArcBoundMargin * kArcBoundMargin);
  const double v2 = (vx * vx + vy * vy) + vz * vz;
  const double deep = std::min(-floor, floor * floor - (v2 - along * along / s2));
  const double beyond = std::max(-inside, deep);
  return std::min(ends, k.s2 > kArcBoundMargin * kArcBoundMargin ? beyond : ahead);
}

// Built for AVX2 and for any x86-64; file-local, as vector_lanes.h asks.
// Whole fours, the padding's lanes' margins thrown away (ArcColumns).
MFZ_VECTOR_LANES void margins_in_lanes(const ArcColumns& c, int count, const Vec3& centre, double vertex_floor,
                                       const Vec3& shared, double shared_floor, double* margin) {
  const int lanes = lanes_of(count);
  if (lanes % kArcLanes != 0) __builtin_unreachable();
  const double ox = centre.x(), oy = centre.y(), oz = centre.z();
  const double sx = shared.x(), sy = shared.y(), sz = shared.z();
  const double *fx = c.face_x, *fy = c.face_y, *fz = c.face_z;
  const double *tx = c.twin_x, *ty = c.twin_y, *tz = c.twin_z;
  const double *vx = c.v0_x, *vy = c.v0_y, *vz = c.v0_z;
#pragma omp simd
  for (int i = 0; i < lanes; ++i) {
    LaneArc k;
    k.px = fx[i], k.py = fy[i], k.pz = fz[i];
    k.qx = tx[i], k.qy = ty[i], k.qz = tz[i];
    k.cx = k.py * k.qz - k.pz * k.qy, k.cy = k.pz * k.qx - k.px * k.qz, k.cz = k.px * k.qy - k.py * k.qx;
    k.s2 = (k.cx * k.cx + k.cy * k.cy) + k.cz * k.cz;
    margin[i] = std::min(lane_margin(k, vx[i] - ox, vy[i] - oy, vz[i] - oz, vertex_floor),
                         lane_margin(k, sx, sy, sz, shared_floor));
  }
}

}  // namespace

void arcs_above(const EdgeArcs& arcs, const Vec3& centre, double vertex_floor, const Vec3& shared,
                double shared_floor, double* margin) {
  margins_in_lanes(arcs.columns(), arcs.size(), centre, vertex_floor, shared, shared_floor, margin);
}

}  // namespace mfz
