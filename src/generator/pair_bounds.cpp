#include "generator/pair_bounds.h"

#include <algorithm>
#include <cmath>

#include "generator/edge_arcs.h"
#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// Each line is the operation SAT's single bound makes with Vec3 (Eigen's
// cross, norm, dot and division), written out per lane: a dot product is
// (x * x' + y * y') + z * z'. Every lane computes every term, the choices
// as selects, so that the loop runs in vector lanes; the axis is divided by
// 1 where it has no length (no division by zero under the fuzzer's traps),
// and such a pair is left to the single bound. Built for AVX2 and for any
// x86-64; file-local, as vector_lanes.h asks.
MFZ_VECTOR_LANES void bound_in_lanes(const RowOfPairs& row, const PairColumns& b, int count, int64_t* hopeless) {
  const int lanes = lanes_of(count);
  if (lanes % kArcLanes != 0) __builtin_unreachable();
  const double ex = row.edge_a.x(), ey = row.edge_a.y(), ez = row.edge_a.z();
  const double ox = row.out_of_a.x(), oy = row.out_of_a.y(), oz = row.out_of_a.z();
  const double cx = row.centres.x(), cy = row.centres.y(), cz = row.centres.z();
  const double ax = row.vertex_a.x(), ay = row.vertex_a.y(), az = row.vertex_a.z();
  const double pax = row.back_a.x(), pay = row.back_a.y(), paz = row.back_a.z();
  const double pbx = row.back_b.x(), pby = row.back_b.y(), pbz = row.back_b.z();
  const double inner_a = row.inner_a, inner_b = row.inner_b, threshold = row.threshold;
  const double *b0x = b.b0_x, *b0y = b.b0_y, *b0z = b.b0_z;
  const double *fx = b.edge_x, *fy = b.edge_y, *fz = b.edge_z;
#pragma omp simd
  for (int k = 0; k < lanes; ++k) {
    const double nx = ey * fz[k] - ez * fy[k], ny = ez * fx[k] - ex * fz[k], nz = ex * fy[k] - ey * fx[k];
    const double length = std::sqrt((nx * nx + ny * ny) + nz * nz);
    const double divisor = length > 0 ? length : 1.0;
    // The axis turned outward by a factor of 1 or -1 (exact: the bits of
    // -n), so that the division is made on every lane, not on one arm.
    const double turn = (nx * ox + ny * oy) + nz * oz >= 0 ? 1.0 : -1.0;
    const double mx = nx * turn / divisor, my = ny * turn / divisor, mz = nz * turn / divisor;
    const double balls = (((mx * cx + my * cy) + mz * cz) + inner_a) + inner_b;
    const double ends = ((mx * pbx + my * pby) + mz * pbz) - ((mx * pax + my * pay) + mz * paz);
    const double edges = ((mx * ax + my * ay) + mz * az) - ((mx * b0x[k] + my * b0y[k]) + mz * b0z[k]);
    // Each test a difference that is positive when it passes, "or" the
    // greater of two and "and" the least: as booleans, the tests were
    // branches, and the loop stayed scalar.
    const double against = std::max(balls - threshold, ends - threshold);
    hopeless[k] = std::min(std::min(against, edges - threshold), length) > 0;
  }
}

}  // namespace

void bound_pairs_in_lanes(const RowOfPairs& row, const PairColumns& b, int count, int64_t* hopeless) {
  bound_in_lanes(row, b, count, hopeless);
}

}  // namespace mfz
