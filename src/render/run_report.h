#pragma once
/// \file
/// A run's report as one self-contained HTML file (`check`, `fuzz` and
/// `diff` with --report DIR): what the run covered (counts per family,
/// placement, contact kind), the checks made and how close the generator came
/// to failing each (histograms of error over tolerance), its speed over time
/// (and the fuzzer's coverage), and every finding with its picture, its case
/// file and the command that replays it. Charts are inline SVG; the case
/// views use the viewer script inlined; nothing loads from the network.
#include <string>
#include <utility>
#include <vector>

#include "harness/run_statistics.h"
#include "render/case_picture.h"

namespace mfz {

struct ReportedFinding {
  std::string name, detail;
  std::string case_path, case_text;
  std::string replay_command;
  std::vector<CasePicture> pictures;  ///< empty: not drawn, `note` says why
  std::string note;
};

struct RunReport {
  std::string title;         ///< the command that ran
  std::vector<std::pair<std::string, std::string>> summary;  ///< rows of the summary table
  RunStatistics statistics;
  std::string progress_unit = "cases";  ///< what the samples count: cases, executions
  std::vector<ReportedFinding> findings;
};

std::string html_run_report(const RunReport& report);

/// Writes DIR/report.html (making DIR); false and a one-line `error` when it
/// cannot.
bool write_run_report(const std::string& dir, const RunReport& report, std::string& error);

}  // namespace mfz
