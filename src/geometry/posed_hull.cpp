#include "geometry/posed_hull.h"

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// Four vertices at a time where the processor has AVX2, two elsewhere: on
// 32-point hulls SAT projects a hull for every face and for every edge pair
// it bounds. File-local, like every such clone: clang 14 links a clone only
// where its callers see its definition.
MFZ_VECTOR_LANES Interval project_in_lanes(const double* xs, const double* ys, const double* zs, int n, double ax,
                                           double ay, double az) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
#pragma omp simd reduction(min : low) reduction(max : high)
  for (int i = 0; i < n; ++i) {
    const double d = (ax * xs[i] + ay * ys[i]) + az * zs[i];
    low = d < low ? d : low;
    high = d > high ? d : high;
  }
  return {low, high};
}

}  // namespace

Interval project_columns(const double* xs, const double* ys, const double* zs, int n, double ax, double ay,
                         double az) {
  return project_in_lanes(xs, ys, zs, n, ax, ay, az);
}

}  // namespace mfz
