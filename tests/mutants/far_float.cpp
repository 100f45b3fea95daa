// Bug only far from the origin: beyond 1000 sizes from it, positions are
// kept in single precision (a "large world" code path).
#include "mutant_plugin.h"

namespace {
double size_of(const mfz_hull& h) {
  double r = 0;
  for (int i = 0; i < h.vertex_count; ++i) r = std::max(r, mfz::to_vec(h.vertices[i]).norm());
  return r;
}
void to_float(mfz_pose& p) {
  p.position = {static_cast<float>(p.position.x), static_cast<float>(p.position.y), static_cast<float>(p.position.z)};
}
}  // namespace

const char* const mutant::name = "mutant-far-float";
mfz::ClippingSteps mutant::steps() { return {}; }
void mutant::before(const mfz_hull& a, mfz_pose& pa, const mfz_hull& b, mfz_pose& pb) {
  const double size = std::max(size_of(a), size_of(b));
  if (mfz::to_vec(pa.position).norm() > 1e3 * size) to_float(pa), to_float(pb);
}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
