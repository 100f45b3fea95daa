#include "check_driver.h"

#include "geometry/tolerances.h"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>

#include <unistd.h>

#include "families.h"
#include "finding_file.h"
#include "finding_minimiser.h"
#include "harness/interruption.h"

namespace mfz::props {
namespace {

using Clock = std::chrono::steady_clock;

/// Budgets of the two shrinking stages (both also end at the run's deadline).
constexpr double kShrinkTreeSeconds = 120;
constexpr double kShrinkFileSeconds = 60;
/// Seconds between the samples of the run's progress (its report's chart).
constexpr double kSampleEvery = 1;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string count_bucket(int n) {
  if (n <= 4) return std::to_string(n);
  return n <= 8 ? "5-8" : (n <= 16 ? "9-16" : "17+");
}

// The exact depth in units of L by decade, from one ulp to past half of L.
std::string depth_decade(double depth_over_l) {
  if (!(depth_over_l > 0)) return "apart or touching";
  if (depth_over_l >= 0.5) return ">=0.5";
  const int decade = std::max(-16, static_cast<int>(std::floor(std::log10(depth_over_l))));
  return "1e" + std::to_string(decade);
}

void record(RunStatistics& stats, const GeneratedCase& g, const CaseOutcome& o) {
  stats.count("depth (x L)", depth_decade(o.tags.depth_over_l));
  stats.count("hull family A", g.hull_a);
  stats.count("placement", g.placement);
  stats.count("overlap", g.overlap);
  stats.count("tilt", g.tilt);
  stats.count("frame", g.frame);
  stats.count("scale", g.scale);
  stats.count("contact kind", o.tags.contact_kind);
  stats.count("contacts", count_bucket(o.tags.contact_count));
  if (o.tags.touching) stats.count("special", "touching");
  if (o.tags.tie) stats.count("special", "axis tie");
  if (o.verdict) stats.add_verdict(*o.verdict);
}

// The run's end: --seconds covers shrinking too.
struct Deadline {
  std::optional<Clock::time_point> at;
  double left() const {
    if (interrupted()) return 0;
    return at ? std::chrono::duration<double>(*at - Clock::now()).count() : INFINITY;
  }
};

// Greedy shrinking over RapidCheck's shrink tree: take the first smaller case
// that fails the same way, until none does.
rc::Shrinkable<GeneratedCase> shrink(rc::Shrinkable<GeneratedCase> failing, Finding& finding, GeneratorSession& g,
                                     const Selection& selection, const Deadline& deadline, int& steps) {
  const auto started = Clock::now();
  const Finding original = finding;
  bool smaller = true;
  while (smaller && since(started) < kShrinkTreeSeconds && deadline.left() > 0) {
    smaller = false;
    auto candidates = failing.shrinks();
    while (auto candidate = candidates.next()) {
      if (deadline.left() <= 0) break;
      const CaseOutcome o = check_case(candidate->value().file, g, selection);
      if (!o.invalid && o.finding && same_failure(original, *o.finding)) {
        failing = *candidate;
        finding = *o.finding;
        smaller = true;
        ++steps;
        break;
      }
    }
  }
  return failing;
}

std::string write_case(const CheckOptions& options, const GeneratedCase& g, const Finding& f, long long index,
                       std::string& text, std::string& error) {
  const std::string found_by = "found by: manifuzz check --generator " + options.generator + " --seed " +
                               std::to_string(options.seed) +
                               (options.selection.level == Level::strict ? " --strict" : "") +
                               (options.profile_override ? " --profile '" + *options.profile_override + "'" : "") + " (case " +
                               std::to_string(index) + ", then shrunk)";
  return write_finding(options.out_dir, g.file, f, options.selection, {found_by}, text, error);
}

}  // namespace

std::optional<CheckResult> run_check(const CheckOptions& given, std::ostream& log, std::string& error) {
  CheckOptions options = given;
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit is a write error to report, not a death
  // A finding must never be lost to an unwritable folder after minutes of
  // shrinking: the folder is tried first.
  if (!prepare_out_dir(options.out_dir, error)) return std::nullopt;
  auto generator = open_session(options.generator, options.call_timeout, error);
  if (!generator) return std::nullopt;
  const auto profile = profile_in_force(generator->declared_profile(), options.profile_override, error);
  if (!profile) return std::nullopt;
  options.selection.profile = *profile;
  options.selection.profile_from_command_line = true;
  // Ctrl-C and SIGTERM stop the run, which writes what it has and prints
  // its summary.
  catch_interruptions();
  log << "manifuzz check: generator " << generator->name() << ", seed " << options.seed << ", "
      << (options.selection.level == Level::strict ? "strict" : "contract") << " level (replay with --seed "
      << options.seed << "), profile " << profile->text();
  if (!options.hull_families.empty()) {
    log << ", families";
    for (const std::string& family : options.hull_families) log << " " << family;
  }
  log << "\n";
  // A profile's precision resolves cases only so far out (tolerances.h):
  // farther frames are not drawn.
  const double farthest = options.selection.profile.precision_epsilon > 0
                              ? tol::kProfileFarthestFrame / (tol::kWorldUlps * options.selection.profile.precision_epsilon)
                              : std::numeric_limits<double>::infinity();
  const auto gen = any_case(farthest, options.hull_families);
  // The double build a float finding must fail too, under its own profile.
  std::unique_ptr<GeneratorSession> confirmer;
  Selection confirm_selection = options.selection;
  if (options.confirm_with) {
    confirmer = open_session(*options.confirm_with, options.call_timeout, error);
    if (!confirmer) return std::nullopt;
    const auto own = profile_in_force(confirmer->declared_profile(), std::nullopt, error);
    if (!own) return std::nullopt;
    confirm_selection.profile = *own;
    log << "manifuzz check: each finding is confirmed against " << confirmer->name() << " (profile " << own->text()
        << "); one it does not make is rounding, counted and passed over\n";
  }
  rc::Random random(options.seed);
  CheckResult result;
  RunStatistics& stats = result.statistics;
  const auto started = Clock::now();
  Deadline deadline;
  if (options.seconds)
    deadline.at = started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*options.seconds));
  double last_progress = 0, last_sample = 0;
  stats.sample(0, 0);
  for (long long index = 0;; ++index) {
    if (options.cases && result.cases >= *options.cases) break;
    if (deadline.left() <= 0) break;
    const auto shrinkable = gen(random.split(), static_cast<int>(index % 100));
    const GeneratedCase generated = shrinkable.value();
    const CaseOutcome outcome = check_case(generated.file, *generator, options.selection);
    if (outcome.interrupted) break;
    if (outcome.invalid) {
      ++result.invalid;
      continue;
    }
    ++result.cases;
    record(stats, generated, outcome);
    if (outcome.finding && confirmer) {
      const CaseOutcome again = check_case(generated.file, *confirmer, confirm_selection);
      if (!again.invalid && !(again.finding && same_failure(*outcome.finding, *again.finding))) {
        ++result.rounding_only;
        log << "  rounding only: " << outcome.finding->name << " at case " << index << " ("
            << outcome.finding->detail << "), which " << confirmer->name() << " does not make\n";
        continue;
      }
    }
    if (outcome.finding) {
      Finding finding = *outcome.finding;
      log << "found " << finding.name << " at case " << index << ": " << finding.detail << "\nshrinking...\n";
      const Finding original = finding;
      const auto minimal = shrink(shrinkable, finding, *generator, options.selection, deadline, result.shrink_steps);
      GeneratedCase smallest = minimal.value();
      const Minimised smaller = minimise_finding(smallest.file, original, *generator, options.selection,
                                                 std::min(kShrinkFileSeconds, deadline.left()),
                                                 [&] { return deadline.left() <= 0; });
      smallest.file = smaller.file;
      result.shrink_steps += smaller.steps;
      if (smaller.steps > 0) finding = smaller.finding;
      result.finding = finding;
      result.found_at_case = index;
      result.case_path = write_case(options, smallest, finding, index, result.minimised_text, error);
      if (result.case_path.empty()) return std::nullopt;
      break;
    }
    const double now = since(started);
    if (now - last_sample >= kSampleEvery) last_sample = now, stats.sample(now, result.cases);
    if (options.progress_every > 0 && now - last_progress >= options.progress_every) {
      last_progress = now;
      log << "  " << result.cases << " cases, " << static_cast<long long>(result.cases / now) << " cases/s, "
          << result.invalid << " invalid; ";
      stats.print_counts(log, "placement");
      log << "\n";
    }
  }
  result.seconds = since(started);
  stats.sample(result.seconds, result.cases);
  result.interrupted = interrupted();
  release_interruptions();
  if (result.interrupted) log << "manifuzz check: interrupted; the summary so far:\n";
  log << "manifuzz check: " << result.cases << " cases in " << std::setprecision(3) << result.seconds << " s ("
      << static_cast<long long>(result.cases / std::max(result.seconds, 1e-9)) << " cases/s), " << result.invalid
      << " invalid inputs discarded";
  if (confirmer) log << ", " << result.rounding_only << " findings of rounding only passed over";
  log << "\n";
  stats.print(log, result.cases);
  return result;
}

}  // namespace mfz::props
