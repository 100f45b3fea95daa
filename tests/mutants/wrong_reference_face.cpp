// Bug: reference and incident face are the wrong way round.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-wrong-reference-face";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.reference_is_b = [](const mfz::SatResult& sat, const mfz::ClipFace& a, const mfz::ClipFace& b) {
    return !mfz::sat_face_is_reference(sat, a, b);
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
