// Bug: the clip against the reference face's side planes is skipped.
#include "mutant_plugin.h"

const char* const mutant::name = "mutant-side-clip-skipped";
mfz::ClippingSteps mutant::steps() {
  mfz::ClippingSteps s;
  s.clip_to_sides = [](const mfz::ClipFace&, mfz::ClipPolygon&, mfz::ClipTrace*) { return true; };
  return s;
}
void mutant::before(const mfz_hull&, mfz_pose&, const mfz_hull&, mfz_pose&) {}
void mutant::after(const mfz_hull&, const mfz_pose&, const mfz_hull&, const mfz_pose&, mfz_manifold&) {}
