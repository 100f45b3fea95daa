#include "harness/run_statistics.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace mfz {

const std::array<const char*, kMarginBins>& margin_bin_names() {
  static const std::array<const char*, kMarginBins> names{"0",        "<=1e-3", "<=1e-2", "<=0.1",
                                                          "<=0.5",    "<=1",    ">1",     ">10"};
  return names;
}

int margin_bin(double error, double tolerance) {
  if (std::isnan(error)) return kMarginBins - 1;
  if (error <= 0) return 0;
  if (!(tolerance > 0)) return error > 0 ? kMarginBins - 1 : 0;
  const double ratio = error / tolerance;
  constexpr double kUpper[] = {1e-3, 1e-2, 0.1, 0.5, 1, 10};
  for (int k = 0; k < 6; ++k)
    if (ratio <= kUpper[k]) return k + 1;
  return kMarginBins - 1;
}

void RunStatistics::add_verdict(const Verdict& verdict, const std::string& prefix) {
  for (const InvariantCheck& c : verdict.checks) {
    CheckMargins& m = margins_[prefix + c.name];
    if (c.status == CheckStatus::skipped || c.status == CheckStatus::oracle_disagreement) {
      ++m.skipped;
      continue;
    }
    ++m.measured;
    ++m.bins[margin_bin(c.error, c.tolerance)];
    if (c.status == CheckStatus::fail) ++m.failed;
    else if (c.tolerance > 0) m.closest = std::max(m.closest, c.error / c.tolerance);
  }
}

void RunStatistics::merge(const RunStatistics& other) {
  for (const auto& [table, rows] : other.tables_)
    for (const auto& [key, n] : rows) tables_[table][key] += n;
  for (const auto& [name, m] : other.margins_) {
    CheckMargins& mine = margins_[name];
    mine.measured += m.measured, mine.skipped += m.skipped, mine.failed += m.failed;
    for (int k = 0; k < kMarginBins; ++k) mine.bins[k] += m.bins[k];
    mine.closest = std::max(mine.closest, m.closest);
  }
}

// Tabs separate the fields: table names and keys hold spaces, never tabs.
std::string RunStatistics::to_lines() const {
  std::ostringstream out;
  out << std::setprecision(17);
  for (const auto& [table, rows] : tables_)
    for (const auto& [key, n] : rows) out << "count\t" << table << "\t" << key << "\t" << n << "\n";
  for (const auto& [name, m] : margins_) {
    out << "margin\t" << name << "\t" << m.measured << "\t" << m.skipped << "\t" << m.failed << "\t" << m.closest;
    for (const long long n : m.bins) out << "\t" << n;
    out << "\n";
  }
  // At most kSentSamples samples (and the last): a job's lines go through a
  // pipe its parent reads only once the job has ended.
  constexpr size_t kSentSamples = 240;
  const size_t every = samples_.size() / kSentSamples + 1;
  for (size_t k = 0; k < samples_.size(); ++k)
    if (k % every == 0 || k + 1 == samples_.size())
      out << "sample\t" << samples_[k].seconds << "\t" << samples_[k].total << "\t" << samples_[k].coverage << "\n";
  return out.str();
}

bool RunStatistics::add_line(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
  try {
    if (fields.size() == 4 && fields[0] == "count") {
      tables_[fields[1]][fields[2]] += std::stoll(fields[3]);
      return true;
    }
    if (fields.size() == 6 + kMarginBins && fields[0] == "margin") {
      CheckMargins m;
      m.measured = std::stoll(fields[2]), m.skipped = std::stoll(fields[3]), m.failed = std::stoll(fields[4]);
      m.closest = std::stod(fields[5]);
      for (int k = 0; k < kMarginBins; ++k) m.bins[k] = std::stoll(fields[6 + k]);
      RunStatistics one;
      one.margins_[fields[1]] = m;
      merge(one);
      return true;
    }
    if (fields.size() == 4 && fields[0] == "sample") {
      samples_.push_back({std::stod(fields[1]), std::stoll(fields[2]), std::stoi(fields[3])});
      return true;
    }
  } catch (const std::exception&) {
  }
  return false;
}

std::vector<ProgressSample> combined_progress(const std::vector<std::vector<ProgressSample>>& jobs) {
  std::vector<double> times;
  for (const auto& job : jobs)
    for (const ProgressSample& p : job) times.push_back(p.seconds);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<ProgressSample> out;
  for (const double t : times) {
    ProgressSample sum{t, 0, -1};
    for (const auto& job : jobs) {
      if (job.empty()) continue;
      // The job's total at t: its line between the samples around t, its
      // last total past its end.
      const auto after = std::lower_bound(job.begin(), job.end(), t,
                                          [](const ProgressSample& p, double x) { return p.seconds < x; });
      if (after == job.end()) {
        sum.total += job.back().total;
      } else if (after == job.begin() || after->seconds == t) {
        sum.total += after == job.begin() && after->seconds > t ? 0 : after->total;
      } else {
        const ProgressSample& before = *(after - 1);
        const double s = (t - before.seconds) / (after->seconds - before.seconds);
        sum.total += before.total + static_cast<long long>(s * static_cast<double>(after->total - before.total));
      }
    }
    out.push_back(sum);
  }
  return out;
}

void RunStatistics::print_counts(std::ostream& out, const std::string& table) const {
  const auto found = tables_.find(table);
  if (found == tables_.end()) return;
  out << table << ":";
  for (const auto& [key, n] : found->second) out << " " << key << " " << n;
}

void RunStatistics::print(std::ostream& out, long long total) const {
  for (const auto& [table, rows] : tables_) {
    out << "  " << table << ":";
    for (const auto& [key, n] : rows)
      out << "  " << key << " " << std::fixed << std::setprecision(1) << 100.0 * n / std::max(1LL, total) << "%";
    out << std::defaultfloat << "\n";
  }
}

}  // namespace mfz
