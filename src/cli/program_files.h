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

/// The generators that come with manifuzz as plugins, by the names
/// `--generator` takes: the tutorial's unfixed method and the peers built
/// here (Bullet's and ODE's, when their libraries were found).
const std::vector<std::string>& bundled_generator_names();

/// `--generator`'s value as Generator::open takes it: a bundled name becomes
/// the path of its plugin; `builtin` and paths stay as they are. A bundled
/// name whose plugin was not built stays a name, and fails to open.
std::string resolve_generator(const std::string& spec);

}  // namespace mfz::cli
