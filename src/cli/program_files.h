#pragma once
/// \file
/// Files that come with the manifuzz program, found beside it: in a build
/// tree (src/manifuzz, fuzz/, plugins/) and in an installed prefix (bin/,
/// lib/manifuzz/) alike.
#include <string>
#include <vector>

namespace mfz::cli {

/// The first of `candidates` (paths relative to the folder of the running
/// manifuzz) that exists, as an absolute path; empty when none does.
std::string beside_this_program(const std::vector<std::string>& candidates);

}  // namespace mfz::cli
