// Bug: the reference face is the LESS parallel of the two significant faces.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-wrong-reference-face";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.reference_is_b = [](const mfz::Vec3& n, const mfz::ClipFace& a, const mfz::ClipFace& b) {
    return !mfz::seed_reference_is_b(n, a, b);
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
