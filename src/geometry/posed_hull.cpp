#include "geometry/posed_hull.h"

#include <cmath>

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// On 32-point hulls SAT projects a hull for every face and for every edge
// pair it bounds. File-local, as vector_lanes.h asks.
//
// clang 14 keeps columns_interval's min and max reduction out of vector
// lanes unless NaNs and zeros' signs may be ignored (another order of the
// reduction may keep the other zero), so it takes one point at a time: in
// the clang-built fuzzer this function was a tenth of a real run (perf,
// replaying a grown corpus). Four running bounds, each point's taken into
// the bound of its place among four, are the same selects in an order the
// code fixes, and clang puts the four in lanes. The bounds are the same
// numbers; of a +0 and a -0 either may be kept, as with any order of lanes.
MFZ_VECTOR_LANES Interval project_in_lanes(const double* xs, const double* ys, const double* zs, int n, double ax,
                                           double ay, double az) {
#if defined(__clang__)
  double low[4] = {INFINITY, INFINITY, INFINITY, INFINITY}, high[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};
  int i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) {
      const double d = (ax * xs[i + k] + ay * ys[i + k]) + az * zs[i + k];
      low[k] = d < low[k] ? d : low[k];
      high[k] = d > high[k] ? d : high[k];
    }
  for (; i < n; ++i) {
    const double d = (ax * xs[i] + ay * ys[i]) + az * zs[i];
    low[0] = d < low[0] ? d : low[0];
    high[0] = d > high[0] ? d : high[0];
  }
  Interval range{low[0], high[0]};
  for (int k = 1; k < 4; ++k) {
    range.min = low[k] < range.min ? low[k] : range.min;
    range.max = high[k] > range.max ? high[k] : range.max;
  }
  return range;
#else
  return columns_interval(xs, ys, zs, n, ax, ay, az);
#endif
}

// Four points at a time, each axis's bounds read and written once per four:
// one point at a time, the loop spent its time moving them. The loop over
// the axes stays the one in vector lanes: eight axes at a time with the
// points inside (a07c4ae) was faster only at -O3 and only with g++; at -O2
// g++ took 1.4x the time of one point at a time, and clang with libFuzzer's
// coverage unrolled the eight into branches, 4x (the fuzzer's executions
// went 1,300 -> 800 a second). Four points: 0.55x at -O2 and -O3 with g++,
// 0.6x with clang, 0.7x with coverage (a 33-point hull against a row of 90
// of the brute-force SAT's axes). Per axis the points come in the same
// order.
MFZ_VECTOR_LANES void project_onto_axes_in_lanes(const double* px, const double* py, const double* pz, int n,
                                                 const double* nx, const double* ny, const double* nz, int count,
                                                 double* lowest, double* highest) {
  for (int j = 0; j < count; ++j) lowest[j] = INFINITY, highest[j] = -INFINITY;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const double x0 = px[i], y0 = py[i], z0 = pz[i];
    const double x1 = px[i + 1], y1 = py[i + 1], z1 = pz[i + 1];
    const double x2 = px[i + 2], y2 = py[i + 2], z2 = pz[i + 2];
    const double x3 = px[i + 3], y3 = py[i + 3], z3 = pz[i + 3];
#pragma omp simd
    for (int j = 0; j < count; ++j) {
      const double d0 = nx[j] * x0 + ny[j] * y0 + nz[j] * z0;
      const double d1 = nx[j] * x1 + ny[j] * y1 + nz[j] * z1;
      const double d2 = nx[j] * x2 + ny[j] * y2 + nz[j] * z2;
      const double d3 = nx[j] * x3 + ny[j] * y3 + nz[j] * z3;
      double low = lowest[j], high = highest[j];
      low = d0 < low ? d0 : low, high = d0 > high ? d0 : high;
      low = d1 < low ? d1 : low, high = d1 > high ? d1 : high;
      low = d2 < low ? d2 : low, high = d2 > high ? d2 : high;
      low = d3 < low ? d3 : low, high = d3 > high ? d3 : high;
      lowest[j] = low, highest[j] = high;
    }
  }
  for (; i < n; ++i) {
    const double x = px[i], y = py[i], z = pz[i];
#pragma omp simd
    for (int j = 0; j < count; ++j) {
      const double d = nx[j] * x + ny[j] * y + nz[j] * z;
      lowest[j] = d < lowest[j] ? d : lowest[j];
      highest[j] = d > highest[j] ? d : highest[j];
    }
  }
}

}  // namespace

void project_onto_axes(const double* xs, const double* ys, const double* zs, int n, const double* ax,
                       const double* ay, const double* az, int count, double* lowest, double* highest) {
  project_onto_axes_in_lanes(xs, ys, zs, n, ax, ay, az, count, lowest, highest);
}

Interval project_columns(const double* xs, const double* ys, const double* zs, int n, double ax, double ay,
                         double az) {
  return project_in_lanes(xs, ys, zs, n, ax, ay, az);
}

}  // namespace mfz
