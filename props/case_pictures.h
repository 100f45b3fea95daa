#pragma once
/// \file
/// Pictures of a case file as the one pipeline sees it (`render`,
/// `explain --render`, `replay --render`, and the findings of a report):
/// the generator's run, and for a relation finding its transformed run
/// beside it, each marked with the check that broke.
#include <string>
#include <vector>

#include "case_property.h"
#include "render/case_picture.h"

namespace mfz::props {

/// The runs of `c` through `session`, checked as `selection` says. Empty,
/// with a one-line `error`, when the case is no valid input.
std::vector<CasePicture> pictures_of_case(const CaseFile& c, GeneratorSession& session, Selection selection,
                                          std::string& error);

/// The pictures of a case that `outcome` already holds (the pipeline ran):
/// the scene is rebuilt from `c`, the generator is not called again.
std::vector<CasePicture> pictures_of_outcome(const CaseFile& c, const CaseOutcome& outcome,
                                             const std::string& generator_name);

/// Writes DIR/STEM.svg and DIR/STEM.html; false and a one-line `error` when
/// it cannot.
bool write_case_pictures(const std::string& dir, const std::string& stem, const std::vector<CasePicture>& runs,
                         const std::string& title, std::string& error);

/// A file name's stem: "failures/f28-swap.case" -> "f28-swap".
std::string file_stem(const std::string& path);

}  // namespace mfz::props
