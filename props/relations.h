#pragma once
/// \file
/// Metamorphic relations: run the generator on a transformed case and compare
/// with the original manifold. Depth is always compared; the normal and the
/// contacts only where the minimal axis is unique (no tie), as docs/contract.md
/// says. Contacts are compared as point sets, ignoring contacts within
/// tolerance of zero depth (they come and go with rounding); when both
/// manifolds hold four or more contacts their sets are not compared, because
/// which contacts a reducing generator keeps is a tie.
#include <optional>

#include "case_property.h"

namespace mfz::props {

/// The original run, which every relation transforms.
struct RelationInput {
  const CaseFile& file;
  const Scene& scene;
  const mfz_manifold& manifold;
  bool tie = false;
  bool touching = false;
};

/// Checks one relation; nullopt when it holds. Crashes, hangs and refusals in
/// the transformed runs are findings too.
std::optional<Finding> check_relation(const std::string& name, const RelationInput& input, GeneratorSession& generator);

}  // namespace mfz::props
