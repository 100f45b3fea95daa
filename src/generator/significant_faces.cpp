#include "generator/significant_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/tolerances.h"

namespace mfz {
namespace {

// F10's slack: within it of the furthest, a vertex is as far. The hull's
// extent along the direction sets the scale, the world coordinates the rounding.
double furthest_slack(const PosedHull& hull, const Vec3& direction, double furthest) {
  double nearest = furthest;
  for (int i = 0; i < hull.vertex_count(); ++i) nearest = std::min(nearest, direction.dot(hull.world_vertex(i)));
  return tol::kTie * (furthest - nearest) + tol::world_rounding(std::abs(furthest));
}

// Which vertices are support: the support vertex itself, and with over_ties
// every vertex within F10's slack of it. Each vertex is measured once, not
// once for each face it is a corner of: two scans of every face's loop, one
// dot product a corner, were 12% of a 128-point pair's call (756 corners for
// 128 vertices).
class SupportMarks {
 public:
  SupportMarks(const PosedHull& hull, const Vec3& direction, int support, bool over_ties)
      : hull_(hull), direction_(direction), support_(support) {
    const double furthest = direction.dot(hull.world_vertex(support));
    const double slack = over_ties ? furthest_slack(hull, direction, furthest) : -1;
    threshold_ = furthest - slack;
    marked_ = hull.vertex_count() <= kCachedVertices;
    if (!marked_) return;
    for (int v = 0; v < hull.vertex_count(); ++v) at_[v] = measure(v);
  }
  bool at(int v) const { return marked_ ? at_[v] : measure(v); }
  int support() const { return support_; }

 private:
  bool measure(int v) const { return v == support_ || direction_.dot(hull_.world_vertex(v)) >= threshold_; }

  const PosedHull& hull_;
  Vec3 direction_;
  int support_;
  double threshold_;
  bool marked_;
  bool at_[kCachedVertices];
};

// Faces that hold the support vertex, or with over_ties any vertex as far;
// `visit(face, alignment, held)` also gets how many of those support vertices
// the face holds. With over_ties the support can be an edge or a face, and a
// significant face must hold all of it that any face holds: a face with only
// one end of a supporting edge can lie wholly outside the reference prism
// while the edge crosses it (F24).
template <class Visit>
void faces_at_support(const PosedHull& hull, const Vec3& direction, const SupportMarks& marks, bool over_ties,
                      Visit&& visit) {
  for (int f = 0; f < hull.face_count(); ++f) {
    int held = 0;
    bool contains_support = false;
    for (int k = 0; k < hull.face_size(f); ++k) {
      const int v = hull.face_vertex(f, k);
      held += marks.at(v) ? 1 : 0;
      contains_support |= v == marks.support();
    }
    if (held > 0 && (over_ties || contains_support)) visit(f, hull.world_face_normal(f).dot(direction), held);
  }
}

// A face beats another when it holds more of the support, then when it is
// more parallel to the direction.
struct FaceRank {
  int held = 0;
  double alignment = -std::numeric_limits<double>::infinity();
  bool beats(const FaceRank& other) const {
    return held != other.held ? held > other.held : alignment > other.alignment;
  }
};

}  // namespace

int significant_face(const PosedHull& hull, const Vec3& direction, int& support, bool over_ties) {
  support = hull.support_vertex(direction);
  int best = -1;
  FaceRank best_rank;
  const SupportMarks marks(hull, direction, support, over_ties);
  faces_at_support(hull, direction, marks, over_ties, [&](int f, double alignment, int held) {
    const FaceRank rank{held, alignment};
    if (rank.beats(best_rank)) best_rank = rank, best = f;
  });
  return best;
}

// The faces to clip: those as parallel as the most parallel (F11), and the
// face that holds the most of the support with its equals (F24). Either rule
// alone loses contacts: F24's alone kept one half of a face folded by 1e-9
// whose other half held one support vertex fewer, by 4e-10 of rounding (F25).
int tied_significant_faces(const PosedHull& hull, const Vec3& direction, int* out, int capacity) {
  const SupportMarks marks(hull, direction, hull.support_vertex(direction), true);
  FaceRank best;
  double most_parallel = -std::numeric_limits<double>::infinity();
  faces_at_support(hull, direction, marks, true, [&](int, double alignment, int held) {
    if (const FaceRank rank{held, alignment}; rank.beats(best)) best = rank;
    most_parallel = std::max(most_parallel, alignment);
  });
  int count = 0;
  faces_at_support(hull, direction, marks, true, [&](int f, double alignment, int held) {
    const bool holds_the_support = held == best.held && alignment >= best.alignment - tol::kTie;
    const bool as_parallel = alignment >= most_parallel - tol::kTie;
    if ((holds_the_support || as_parallel) && count < capacity) out[count++] = f;
  });
  return count;
}

// F58: a face held for the support alone may reach far past the support,
// where its points add depth and nothing to the region's span, as F27's
// faces' points do in a column already held; clipped as an incident face,
// every such point was kept, and as F27's face (the same face triangulated,
// whose triangles hold fewer of the support) none was. So it is clipped as
// F27's faces are, in either form.
int parallel_faces_first(const PosedHull& hull, const Vec3& direction, int* faces, int count) {
  double most_parallel = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i) most_parallel = std::max(most_parallel, hull.world_face_normal(faces[i]).dot(direction));
  // In place and in order, without std::stable_partition's buffer, which
  // may come from the heap.
  int first = 0;
  for (int i = 0; i < count; ++i) {
    if (!(hull.world_face_normal(faces[i]).dot(direction) >= most_parallel - tol::kTie)) continue;
    std::rotate(faces + first, faces + i, faces + i + 1);
    ++first;
  }
  return first;
}

}  // namespace mfz
