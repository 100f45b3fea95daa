#include "generator/edge_pair_batch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/vector_lanes.h"

namespace mfz {

namespace {

// Built for AVX2 and for any x86-64; file-local, as vector_lanes.h asks.
// Every lane divides, by the least positive double where the axis has no
// length (any positive length is at least that, so it is the length
// itself everywhere else): no branch, and no division by zero under the
// fuzzer's traps. Picked by a comparison instead, the lanes divided by the
// zero length too and kept the other pick: two parallel edges of a box
// raised SIGFPE (fuzz_corpus_replays_manifold). Where the length is zero
// the axis bounds nothing and is never read.
MFZ_VECTOR_LANES void normalise_in_lanes(double* x, double* y, double* z, int count, double* length) {
  constexpr double least = std::numeric_limits<double>::denorm_min();
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const double l = std::sqrt((x[k] * x[k] + y[k] * y[k]) + z[k] * z[k]);
    const double divisor = std::max(l, least);
    x[k] /= divisor, y[k] /= divisor, z[k] /= divisor;
    length[k] = l;
  }
}

}  // namespace

void normalise_axes(double* x, double* y, double* z, int count, double* length) {
  normalise_in_lanes(x, y, z, count, length);
}

}  // namespace mfz
