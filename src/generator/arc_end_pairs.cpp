#include "generator/arc_end_pairs.h"

#include <algorithm>
#include <cmath>

#include "geometry/tolerances.h"
#include "geometry/vector_lanes.h"

namespace mfz {

// In the direction where the pair's edges support their hulls, the face's
// axis has the pair's overlap (to the tilt, short of F3's bias: the pair
// could not beat it); the other way the overlap is at least the depth,
// which the faces of A - B attain. SAT has measured or bounded every face
// before the edge pairs, so such a pair changes nothing. A cylinder's rim
// edges against the other cylinder's rim all meet at the caps' normals: in
// a grown fuzz corpus of 2,700 inputs, 61% of the pairs SAT projected were
// these, and its replay took 1.81-1.86 s where it took 2.00-2.04. Random
// 8-point hulls, whose arcs seldom meet at an end, take 2.9% more
// instructions a call; skipping the test on pairs of 16 vertices in all
// left them at 2.7%, so the cost is in how the compiler lays out SAT, not
// in the test, and the test stays for every pair.
bool axis_along_arc_end(const Vec3& axis, const EdgeArc& x, const EdgeArc& y) {
  // First the ends against the other's circle: an axis along an end has
  // that end on both circles, within the sine of the circle's pole (whose
  // length is at most 1). Four dot products, where the cross products
  // below cost the 8-point hulls' calls 6% more instructions.
  constexpr double near = 2 * tol::kAxisAlongFaceSine;
  const double ends = std::min(std::min(std::abs(y.n_face.dot(x.across)), std::abs(y.n_twin.dot(x.across))),
                               std::min(std::abs(x.n_face.dot(y.across)), std::abs(x.n_twin.dot(y.across))));
  if (!(ends <= near)) return false;
  const double room = tol::kAxisAlongFaceSine * tol::kAxisAlongFaceSine * axis.squaredNorm();
  return axis.cross(x.n_face).squaredNorm() <= room || axis.cross(x.n_twin).squaredNorm() <= room ||
         axis.cross(y.n_face).squaredNorm() <= room || axis.cross(y.n_twin).squaredNorm() <= room;
}

namespace {

// The lesser of two doubles, as a value: std::min's reference kept the
// loop's choices as branches, and the loop out of vector lanes.
[[gnu::always_inline]] inline double least_of(double x, double y) { return y < x ? y : x; }

// The squared length of (ax, ay, az) crossed with (nx, ny, nz), as Eigen's
// cross and squaredNorm make it.
[[gnu::always_inline]] inline double cross_squared(double ax, double ay, double az, double nx, double ny, double nz) {
  const double cx = ay * nz - az * ny, cy = az * nx - ax * nz, cz = ax * ny - ay * nx;
  return (cx * cx + cy * cy) + cz * cz;
}

// axis_along_arc_end per lane: each line the operation the single test
// makes with Vec3 (a dot product is (x * x' + y * y') + z * z'), every
// lane computing every term, the "or" of the four cross products their
// least, and the two stages joined by a bitwise "and", so that nothing
// branches. Built for AVX2 and for any x86-64; file-local, as
// vector_lanes.h asks.
MFZ_VECTOR_LANES void along_in_lanes(const EdgeArc& x, const Vec3& edge_a, const ArcEndColumns& b, int count,
                                     int64_t* along) {
  const int lanes = lanes_of(count);
  if (lanes % kArcLanes != 0) __builtin_unreachable();
  constexpr double near = 2 * tol::kAxisAlongFaceSine;
  constexpr double sine_squared = tol::kAxisAlongFaceSine * tol::kAxisAlongFaceSine;
  const double ex = edge_a.x(), ey = edge_a.y(), ez = edge_a.z();
  const double px = x.n_face.x(), py = x.n_face.y(), pz = x.n_face.z();
  const double qx = x.n_twin.x(), qy = x.n_twin.y(), qz = x.n_twin.z();
  const double sx = x.across.x(), sy = x.across.y(), sz = x.across.z();
  const double *face_x = b.face_x, *face_y = b.face_y, *face_z = b.face_z;
  const double *twin_x = b.twin_x, *twin_y = b.twin_y, *twin_z = b.twin_z;
  const double *across_x = b.across_x, *across_y = b.across_y, *across_z = b.across_z;
  const double *edge_x = b.edge_x, *edge_y = b.edge_y, *edge_z = b.edge_z;
#pragma omp simd
  for (int k = 0; k < lanes; ++k) {
    const double fx = face_x[k], fy = face_y[k], fz = face_z[k];
    const double tx = twin_x[k], ty = twin_y[k], tz = twin_z[k];
    const double cx = across_x[k], cy = across_y[k], cz = across_z[k];
    const double ends_a = least_of(std::abs((fx * sx + fy * sy) + fz * sz), std::abs((tx * sx + ty * sy) + tz * sz));
    const double ends_b = least_of(std::abs((px * cx + py * cy) + pz * cz), std::abs((qx * cx + qy * cy) + qz * cz));
    const double ax = ey * edge_z[k] - ez * edge_y[k], ay = ez * edge_x[k] - ex * edge_z[k],
                 az = ex * edge_y[k] - ey * edge_x[k];
    const double room = sine_squared * ((ax * ax + ay * ay) + az * az);
    const double off_a = least_of(cross_squared(ax, ay, az, px, py, pz), cross_squared(ax, ay, az, qx, qy, qz));
    const double off_b = least_of(cross_squared(ax, ay, az, fx, fy, fz), cross_squared(ax, ay, az, tx, ty, tz));
    const int64_t ends_on_circles = least_of(ends_a, ends_b) <= near, axis_on_end = least_of(off_a, off_b) <= room;
    along[k] = ends_on_circles & axis_on_end;
  }
}

}  // namespace

void axes_along_arc_ends_in_lanes(const EdgeArc& x, const Vec3& edge_a, const ArcEndColumns& b, int count,
                                  int64_t* along) {
  along_in_lanes(x, edge_a, b, count, along);
}

}  // namespace mfz
