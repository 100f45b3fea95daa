#include "generator/arc_grid.h"

#include <algorithm>
#include <cmath>

namespace mfz {

namespace {

// 30 times the widest gap tol::kGaussArcSlack lets through (sqrt of it).
constexpr double kBoxMargin = 1e-3;

int cell_of(double x, int resolution) {
  const int c = static_cast<int>(std::floor((x + 1) * 0.5 * resolution));
  return std::clamp(c, 0, resolution - 1);
}

}  // namespace

// An arc of at most 90 degrees lies in the triangle of its ends p, q and the
// tangents' meeting point t = (p + q) / (1 + p.q); a longer one is not
// binned. The box is that triangle's, with the margin.
ArcGrid::Box ArcGrid::box_of(const Vec3& p, const Vec3& q) const {
  Box box{{-1, -1, -1}, {-1, -1, -1}};
  const double cosine = p.dot(q);
  if (!(cosine > 0)) return box;
  const Vec3 t = (p + q) / (1 + cosine);
  for (int axis = 0; axis < 3; ++axis) {
    const double low = std::min({p[axis], q[axis], t[axis]}) - kBoxMargin;
    const double high = std::max({p[axis], q[axis], t[axis]}) + kBoxMargin;
    box.lo[axis] = cell_of(low, resolution_);
    box.hi[axis] = cell_of(high, resolution_);
  }
  const int cells = (box.hi[0] - box.lo[0] + 1) * (box.hi[1] - box.lo[1] + 1) * (box.hi[2] - box.lo[2] + 1);
  if (cells > kMaxCellsPerArc) box.lo[0] = -1;
  return box;
}

void ArcGrid::build(const EdgeArcs& arcs_b, const bool* left_out) {
  arc_count_ = arcs_b.size();
  everywhere_count_ = 0;
  query_ = 0;
  // A hull of F faces has arcs about sqrt(4 pi / F) rad long; cells of two
  // thirds of that (1.5 sqrt(F / 4 pi) across the sphere's 2 units) did best
  // of 1, 1.5 and 2 on the 128-point family, by little.
  const int faces = std::max(4, 2 * arc_count_ / 3);
  resolution_ = std::clamp(static_cast<int>(std::lround(1.5 * std::sqrt(faces / (4 * M_PI)))), 1, 8);
  const int cells = resolution_ * resolution_ * resolution_;
  Box boxes[kMaxArcs];
  std::fill(cell_start_, cell_start_ + cells + 1, 0);
  for (int j = 0; j < arc_count_; ++j) {
    stamp_[j] = 0;
    if (left_out && left_out[j]) {
      boxes[j] = {{-1, -1, -1}, {-1, -1, -1}};
      continue;
    }
    boxes[j] = box_of(-arcs_b[j].n_face, -arcs_b[j].n_twin);
    if (boxes[j].lo[0] < 0) {
      everywhere_[everywhere_count_++] = j;
      continue;
    }
    for (int x = boxes[j].lo[0]; x <= boxes[j].hi[0]; ++x)
      for (int y = boxes[j].lo[1]; y <= boxes[j].hi[1]; ++y)
        for (int z = boxes[j].lo[2]; z <= boxes[j].hi[2]; ++z) ++cell_start_[(x * resolution_ + y) * resolution_ + z + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  int filled[kMaxCells] = {};
  for (int j = 0; j < arc_count_; ++j) {
    if (boxes[j].lo[0] < 0) continue;
    for (int x = boxes[j].lo[0]; x <= boxes[j].hi[0]; ++x)
      for (int y = boxes[j].lo[1]; y <= boxes[j].hi[1]; ++y)
        for (int z = boxes[j].lo[2]; z <= boxes[j].hi[2]; ++z) {
          const int c = (x * resolution_ + y) * resolution_ + z;
          entries_[cell_start_[c] + filled[c]++] = j;
        }
  }
}

int ArcGrid::candidates(const EdgeArc& arc_a, int* out) const {
  const Box box = box_of(arc_a.n_face, arc_a.n_twin);
  int count = 0;
  if (box.lo[0] < 0) {
    for (int j = 0; j < arc_count_; ++j) out[count++] = j;
    return count;
  }
  ++query_;
  const auto offer = [&](int j) {
    if (stamp_[j] == query_) return;
    stamp_[j] = query_;
    out[count++] = j;
  };
  for (int i = 0; i < everywhere_count_; ++i) offer(everywhere_[i]);
  for (int x = box.lo[0]; x <= box.hi[0]; ++x)
    for (int y = box.lo[1]; y <= box.hi[1]; ++y)
      for (int z = box.lo[2]; z <= box.hi[2]; ++z) {
        const int c = (x * resolution_ + y) * resolution_ + z;
        for (int e = cell_start_[c]; e < cell_start_[c + 1]; ++e) offer(entries_[e]);
      }
  std::sort(out, out + count);
  return count;
}

}  // namespace mfz
