#include "generator/edge_pair_batch.h"

#include <cmath>

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// Built for AVX2 and for any x86-64; file-local, as vector_lanes.h asks.
// Every lane divides, by 1 where the axis has no length: no branch, and no
// division by zero under the fuzzer's traps.
MFZ_VECTOR_LANES void normalise_in_lanes(double* x, double* y, double* z, int count, double* length) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const double l = std::sqrt((x[k] * x[k] + y[k] * y[k]) + z[k] * z[k]);
    const double divisor = l > 0 ? l : 1.0;
    x[k] /= divisor, y[k] /= divisor, z[k] /= divisor;
    length[k] = l;
  }
}

}  // namespace

void normalise_axes(double* x, double* y, double* z, int count, double* length) {
  normalise_in_lanes(x, y, z, count, length);
}

}  // namespace mfz
