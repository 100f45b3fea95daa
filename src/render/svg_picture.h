#pragma once
/// \file
/// A case as an SVG: per run, three orthographic views in the contact frame
/// (along the normal, and across it twice with n pointing up) and one
/// oblique view, then a legend of the numbers. A relation finding's two runs
/// stand side by side. The output is stable: the same pictures give the same
/// bytes (fixed-point coordinates, no dates, no ids from addresses).
#include <string>
#include <vector>

#include "render/case_picture.h"

namespace mfz {

std::string svg_of(const std::vector<CasePicture>& runs);

/// One view's size in the SVG's user units; tests check every drawn point
/// against its view's box.
inline constexpr double kSvgViewSize = 280;

}  // namespace mfz
