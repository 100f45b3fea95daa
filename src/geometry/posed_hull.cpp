#include "geometry/posed_hull.h"

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// On 32-point hulls SAT projects a hull for every face and for every edge
// pair it bounds. File-local, as vector_lanes.h asks.
MFZ_VECTOR_LANES Interval project_in_lanes(const double* xs, const double* ys, const double* zs, int n, double ax,
                                           double ay, double az) {
  return columns_interval(xs, ys, zs, n, ax, ay, az);
}

}  // namespace

Interval project_columns(const double* xs, const double* ys, const double* zs, int n, double ax, double ay,
                         double az) {
  return project_in_lanes(xs, ys, zs, n, ax, ay, az);
}

}  // namespace mfz
