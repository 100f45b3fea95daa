#pragma once
/// \file
/// What a run covered and how close it came to failing, kept for its summary
/// and for its report (render/run_report.h): counts per category (hull
/// family, placement, contact kind, ...), each check's margins as a
/// histogram of error over tolerance, and samples of the run's progress over
/// time (cases or executions, and the fuzzer's coverage).
#include <array>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "harness/invariants.h"

namespace mfz {

/// The bins of error / tolerance: exactly 0, then up to 1e-3, 1e-2, 0.1,
/// 0.5, 1 (all passes), then past 1 (a failure) and past 10.
inline constexpr int kMarginBins = 8;
const std::array<const char*, kMarginBins>& margin_bin_names();
/// The bin of one measured check; a NaN error counts as past 10.
int margin_bin(double error, double tolerance);

struct CheckMargins {
  long long measured = 0, skipped = 0, failed = 0;
  std::array<long long, kMarginBins> bins{};
  double closest = 0;  ///< the largest error / tolerance of a pass
};

struct ProgressSample {
  double seconds = 0;
  long long total = 0;  ///< cases or executions so far
  int coverage = -1;    ///< the fuzzer's edges covered; -1: not a fuzz run
};

class RunStatistics {
 public:
  void count(const std::string& table, const std::string& key) { ++tables_[table][key]; }
  /// Every measured check of a verdict into its histogram, under the
  /// check's name after `prefix` (diff: whose answer it was).
  void add_verdict(const Verdict& verdict, const std::string& prefix = "");
  void sample(double seconds, long long total, int coverage = -1) { samples_.push_back({seconds, total, coverage}); }

  const std::map<std::string, std::map<std::string, long long>>& tables() const { return tables_; }
  const std::map<std::string, CheckMargins>& margins() const { return margins_; }
  const std::vector<ProgressSample>& samples() const { return samples_; }

  /// Adds another run's counts and margins (a job of `check --jobs`); its
  /// samples are combined by combined_progress.
  void merge(const RunStatistics& other);
  void set_samples(std::vector<ProgressSample> samples) { samples_ = std::move(samples); }

  /// The counts, margins and samples as text lines, one a line (a job sends
  /// them to its parent), and one such line read back; false for a line
  /// that is not one.
  std::string to_lines() const;
  bool add_line(const std::string& line);

  /// One table's counts on one line (the progress report).
  void print_counts(std::ostream& out, const std::string& table) const;
  /// Every table, in percent of `total`.
  void print(std::ostream& out, long long total) const;

 private:
  std::map<std::string, std::map<std::string, long long>> tables_;
  std::map<std::string, CheckMargins> margins_;
  std::vector<ProgressSample> samples_;
};

/// The progress of jobs run side by side: at each time any job sampled, the
/// sum of every job's total there (each job's line between its samples).
std::vector<ProgressSample> combined_progress(const std::vector<std::vector<ProgressSample>>& jobs);

}  // namespace mfz
