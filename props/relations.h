#pragma once
/// \file
/// Metamorphic relations: run the generator on a transformed case, hold that
/// run to the invariants, and compare it with the original manifold where
/// the geometry determines the answer (docs/contract.md, "Ties"). Contacts are compared as point sets, ignoring contacts within
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
  const OracleAnswers& oracles;
  Level level = Level::contract;
  /// The generator's profile: each run is held to the invariants under it,
  /// and the comparisons accept what it declares (docs/profiles.md).
  Profile profile = {};
  /// When set, each transformed run is kept here (the last one run): a
  /// picture of a relation finding shows it beside the case.
  TransformedRun* keep = nullptr;
};

/// A relation named by a case file: `relation NAME numbers...` (the motion,
/// the factor, the fractions it used), so that a finding replays exactly.
struct RelationCall {
  std::string name;
  std::vector<double> numbers;
};

/// The case file's relation line, if any; nullopt with `error` set when the
/// line names no relation or holds a word that is not a finite number.
std::optional<RelationCall> relation_in(const CaseFile& c, std::string& error);

/// Checks one relation; nullopt when it holds. Crashes, hangs and refusals in
/// the transformed runs are findings too, and so is a transformed run whose
/// manifold fails an invariant. `numbers` are the relation's parameters as
/// recorded (nullptr: derived from the case). A finding carries the relation
/// line that reproduces it.
std::optional<Finding> check_relation(const std::string& name, const RelationInput& input, GeneratorSession& generator,
                                      const std::vector<double>* numbers = nullptr);

}  // namespace mfz::props
