#pragma once
/// \file
/// Where findings are written: the out folder, tried before a run so that a
/// finding is never lost to it after minutes of shrinking, and the case file
/// of a finding, with what reproduces it.
#include <string>
#include <vector>

#include "case_property.h"

namespace mfz::props {

/// Creates `dir` and writes a probe file into it; false and a one-line
/// `error` when it cannot (an empty name included).
bool prepare_out_dir(const std::string& dir, std::string& error);

/// Writes `file` into `dir` as `<check>-<hash>.case`, with `notes` (how it
/// was found), the violation, and the lines that make it replay (the
/// relation, the level). Returns the path, and the text written in `text`;
/// an empty path and a one-line `error` when the write fails.
std::string write_finding(const std::string& dir, CaseFile file, const Finding& finding, const Selection& selection,
                          const std::vector<std::string>& notes, std::string& text, std::string& error);

}  // namespace mfz::props
