// Correct: where incident faces tie (mirror faces, a cube's corner, a folded
// face), clips only the last of them instead of joining them all. The
// geometry does not decide between them: it must pass at the contract level.
#include "mutant_plugin.h"

const char* const mutant::name = "correct-last-incident-face";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.incident_faces = [](const mfz::PosedHull& hull, const mfz::Vec3& direction, int* out, int capacity) {
    const int tied = mfz::tied_significant_faces(hull, direction, out, capacity);
    if (tied > 1) out[0] = out[tied - 1];
    return tied > 0 ? 1 : 0;
  };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
