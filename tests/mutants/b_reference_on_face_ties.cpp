// Correct: where A's face and a parallel face of B are both minimal (an
// exact face tie), B's face is the reference face. The built-in keeps the
// face SAT found; either is right at the contract level.
#include "mutant_plugin.h"

const char* const mutant::name = "correct-b-reference-on-face-ties";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.reference_is_b = [](const mfz::SatResult& sat, const mfz::ClipFace& a, const mfz::ClipFace& b) {
    const bool b_face_along_n = b.normal.dot(sat.normal) < 0 && b.normal.cross(sat.normal).norm() <= 1e-12;
    if (sat.kind == mfz::AxisKind::face_a && b_face_along_n) return true;
    return mfz::sat_face_is_reference(sat, a, b);
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
