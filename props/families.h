#pragma once
/// \file
/// The case families: RapidCheck generators of hulls and poses, each named,
/// each shrinking towards small round cases (fewer points, coordinates with
/// few digits, identity rotation, unit size, the origin). Shared by the
/// properties, `manifuzz check` and the fuzzer's decoder.
#include <rapidcheck.h>

#include <ostream>
#include <limits>
#include <optional>
#include <string>

#include "case/case_file.h"

namespace mfz::props {

/// A generated case and the names of the families it came from.
struct GeneratedCase {
  CaseFile file;
  std::string hull_a, hull_b;  ///< hull family of each
  std::string placement;       ///< face-on-face, edge-edge, ...
  std::string overlap;         ///< shallow (1e-15 .. 0.9 of the size), touching, one-ulp, separated, deep, concentric
  std::string tilt;            ///< exact, 1e-15, ..., degrees
  std::string frame;           ///< origin, far-1e3 ... far-1e6
  std::string scale;           ///< unit, small, large, ratio
};

/// The eight corners of the box [-hx, hx] x [-hy, hy] x [-hz, hz].
std::vector<Vec3> box_corners(double hx, double hy, double hz);

/// The 24 rotations that map a cube onto itself, exactly (entries 0 and +-1).
const std::vector<Quat>& cube_symmetries();

/// Every hull family's name, in the order the generator picks them from.
const std::vector<std::string>& hull_family_names();
/// The hull families drawn only where `--family` names them (wide-face:
/// a pyramid on a polygon of 65 to 520 corners; slow against itself).
const std::vector<std::string>& named_only_family_names();
/// Every placement family's name.
const std::vector<std::string>& placement_names();

/// Points of one hull family (local space, size about 1).
rc::Gen<std::vector<Vec3>> hull_points(const std::string& family);
/// `--family`'s value: comma-separated hull family names or groups
/// (`boxes`: the cube and the box families, which a box-only generator such
/// as ODE's dBoxBox takes; `hulls`: every family but those drawn only where
/// named). nullopt and a one-line
/// `error` for a name that is neither.
std::optional<std::vector<std::string>> hull_families_named(const std::string& text, std::string& error);

/// A whole case: two hulls, each from any of `hull_families` (empty: every
/// family), placed by any placement. `farthest_frame`: the far frames drawn
/// lie at most this many diameters of A from the origin (a float profile
/// resolves only 130 L out).
rc::Gen<GeneratedCase> any_case(double farthest_frame = std::numeric_limits<double>::infinity(),
                                std::vector<std::string> hull_families = {});

/// RapidCheck prints a counterexample with this: the case file itself.
void showValue(const GeneratedCase& c, std::ostream& os);

}  // namespace mfz::props
