#pragma once
/// \file
/// What a picture of one run shows, in world space and without any drawing:
/// both hulls (vertices and face loops), the manifold, the clipping method's
/// reference and incident faces and its clipped polygon, the contact frame,
/// the check that broke (and the contact it names), and the numbers of the
/// legend. The SVG (svg_picture.h) and the HTML view (html_case_view.h) draw
/// the same model, so the two never tell different stories.
#include <optional>
#include <string>
#include <vector>

#include "manifuzz/abi.h"
#include "case/scene.h"
#include "harness/invariants.h"
#include "oracles/exact_depth.h"

namespace mfz {

struct DrawnHull {
  std::vector<Vec3> vertices;           ///< world space
  std::vector<std::vector<int>> faces;  ///< loops, counter-clockwise seen from outside
};

/// A failed check, as a finding names it: the contact its detail names is
/// the point circled (-1: the check is about the whole manifold).
struct BrokenCheck {
  std::string name, detail;
  double error = 0, tolerance = 0;  ///< x L; 0 where none was measured
  int contact = -1;
};

struct CasePicture {
  std::string title;  ///< "the case", "the swap-symmetry run"
  DrawnHull a, b;
  std::optional<mfz_manifold> manifold;  ///< empty: the generator gave no answer
  /// The clipping method's choice on this geometry (the built-in's, run with
  /// a trace): a plugin's own faces are not visible through the ABI.
  char reference_hull = 'A';
  int reference_face = -1, incident_face = -1;
  std::vector<Vec3> clipped_polygon;  ///< the incident face after the side planes
  /// The contact frame: n from A to B (the manifold's, else the exact
  /// oracle's), and two directions across it.
  Vec3 normal = Vec3::UnitZ(), across_1 = Vec3::UnitX(), across_2 = Vec3::UnitY();
  double scale = 1;  ///< L
  std::optional<BrokenCheck> broken;
  std::vector<std::string> legend;  ///< one line each, the numbers of the run
};

/// The picture of one run: `manifold` as the generator returned it (nullptr:
/// none), `verdict` its checks (nullptr: not checked), `exact` the exact
/// depth's oracle (nullptr: not consulted).
CasePicture picture_of_run(const Scene& scene, const mfz_manifold* manifold, const Verdict* verdict,
                           const ExactDepth* exact, const std::string& title, const std::string& generator);

/// Marks the finding `name` on the picture: the check, its margin, and the
/// contact its detail names.
void mark_broken_check(CasePicture& picture, const std::string& name, const std::string& detail, double error,
                       double tolerance);

/// The two directions across a unit normal used by every view: fixed by the
/// normal alone, so the same case always gives the same picture.
void frame_across(const Vec3& normal, Vec3& across_1, Vec3& across_2);

}  // namespace mfz
