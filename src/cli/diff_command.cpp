// manifuzz diff --generator G1 --against G2 [--cases N] [--seconds T] [--seed S] [--family F] [--out DIR]
//               [--profile P] [--against-profile P] [--junit FILE] [FILE...]
// The same cases to both generators; where they disagree beyond both
// profiles, which one the oracles side with; the first case of each kind
// minimised into --out; a summary table. With case files, compares those.
#include <iostream>
#include <random>

#include "cli/arguments.h"
#include "cli/run_reports.h"
#include "cli/program_files.h"
#include "differential_run.h"
#include "families.h"
#include "harness/junit_report.h"

namespace mfz::cli {
namespace {

constexpr const char* kUsage =
    "usage: manifuzz diff --generator G1 --against G2 [--cases N] [--seconds T] [--seed S] [--family F] [--out DIR] "
    "[--profile P] [--against-profile P] [--junit FILE] [--report DIR] [FILE...]";

/// Without --cases or --seconds a diff compares this many cases.
constexpr long long kDefaultCases = 2000;

int fail(const std::string& why) {
  std::cerr << "manifuzz diff: " << why << "\n";
  return kExitInputError;
}

std::vector<JunitCase> junit_cases(const props::DiffResult& r) {
  std::vector<JunitCase> cases;
  const std::string classname = "manifuzz.diff." + r.first_name + ".against." + r.second_name;
  for (const std::string& kind : props::disagreement_kinds()) {
    JunitCase c{classname, kind};
    if (const auto found = r.kinds.find(kind); found != r.kinds.end()) {
      c.failure_message = std::to_string(found->second.cases) + " cases disagree on " + kind;
      c.failure_text = found->second.example_detail + "\nminimised case: " + found->second.example_path;
    }
    cases.push_back(c);
  }
  for (const auto& [kind, tally] : r.kinds)
    if (kind == "crash" || kind == "hang" || kind == "refused")
      cases.push_back({classname, kind, 0, false, tally.example_detail, tally.example_path});
  return cases;
}

// `diff ... FILE...`: the comparison on each given case.
int compare_files(const Arguments& args, const std::vector<std::string>& files, props::DiffSide& first,
                  props::DiffSide& second) {
  int status = kExitClean;
  for (const std::string& file : files) {
    const CaseParse parsed = read_case_file(file);
    if (!parsed.value) {
      std::cerr << "manifuzz diff: " << parsed.error << "\n";
      status = kExitInputError;
      continue;
    }
    bool invalid = false;
    const auto d = props::compare_generators(*parsed.value, first, second, invalid);
    if (invalid) {
      std::cerr << "manifuzz diff: " << file << ": not a valid case for this pair\n";
      status = kExitInputError;
    } else if (d && d->sides_with == "both") {
      std::cout << "tie " << file << ": " << d->kind << ", " << d->detail << "; the oracles confirm both\n";
    } else if (d) {
      std::cout << "DISAGREE " << d->kind << " " << file << ": " << d->detail << "; the oracles side with "
                << d->sides_with << "\n";
      if (status == kExitClean) status = kExitViolation;
    } else {
      std::cout << "agree " << file << "\n";
    }
  }
  (void)args;
  return status;
}

// A disagreement's picture: each generator's answer to the example case,
// side by side.
ReportedFinding disagreement_finding(const std::string& kind, const props::KindTally& tally, const ReplayWith& first,
                                     const ReplayWith& second) {
  const std::string detail = std::to_string(tally.cases) + " cases; the first, before it was minimised: " +
                             tally.example_detail;
  ReportedFinding f = reported_finding(kind, detail, tally.example_path, first);
  const ReportedFinding other = reported_finding(kind, detail, tally.example_path, second);
  if (!f.pictures.empty()) f.pictures[0].title = first.generator + "'s answer";
  if (!other.pictures.empty()) {
    f.pictures.resize(std::min<size_t>(f.pictures.size(), 1));
    f.pictures.push_back(other.pictures[0]);
    f.pictures.back().title = second.generator + "'s answer";
  }
  f.replay_command = "manifuzz diff --generator " + first.generator + " --against " + second.generator + " " +
                     tally.example_path;
  return f;
}

bool write_diff_report(const std::string& dir, const Arguments& args, const props::DiffOptions& options,
                       const props::DiffResult& result) {
  const ReplayWith first{args.get("--generator", ""), false, options.profile_override, options.call_timeout};
  const ReplayWith second{args.get("--against", ""), false, options.against_profile_override, options.call_timeout};
  RunReport report;
  report.title = "manifuzz diff --generator " + first.generator + " --against " + second.generator + " --seed " +
                 std::to_string(options.seed);
  report.statistics = result.statistics;
  long long disagreeing = 0;
  for (const auto& [kind, tally] : result.kinds) disagreeing += tally.cases;
  report.summary = {{"generators", result.first_name + " (profile " + result.first_profile.text() + ") against " +
                                       result.second_name + " (profile " + result.second_profile.text() + ")"},
                    {"seed", std::to_string(options.seed)},
                    {"cases", std::to_string(result.cases)},
                    {"seconds", std::to_string(result.seconds)},
                    {"cases/s", std::to_string(static_cast<long long>(result.cases / std::max(result.seconds, 1e-9)))},
                    {"agreeing", std::to_string(result.agreeing)},
                    {"ties (both confirmed by the oracles)", std::to_string(result.ties)},
                    {"disagreeing", std::to_string(disagreeing)},
                    {"checks made", "whether they collide, the depth, the normal, the contact region"}};
  for (const auto& [kind, tally] : result.kinds) report.findings.push_back(disagreement_finding(kind, tally, first, second));
  return write_report_to(dir, report, "diff", std::cerr);
}

}  // namespace

int diff_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words,
                                    {"--generator", "--against", "--cases", "--seconds", "--seed", "--out", "--family",
                                     "--call-timeout", "--profile", "--against-profile", "--junit", "--report"},
                                    {"--quiet"}, error);
  if (!args) return fail(error + " (" + kUsage + ")");
  if (!args->options.count("--generator") || !args->options.count("--against"))
    return fail(std::string("give both --generator and --against (") + kUsage + ")");
  props::DiffOptions options;
  options.generator = resolve_generator(args->get("--generator", ""));
  options.against = resolve_generator(args->get("--against", ""));
  options.out_dir = args->get("--out", "failures");
  const auto budget = run_budget(*args, kDefaultCases, error);
  if (!budget) return fail(error);
  options.cases = budget->cases;
  options.seconds = budget->seconds;
  options.seed = budget->seed;
  if (args->options.count("--family")) {
    const auto families = props::hull_families_named(args->get("--family", ""), error);
    if (!families) return fail(error);
    options.hull_families = *families;
  }
  const auto timeout = call_timeout(*args, error);
  if (!timeout) return fail(error);
  options.call_timeout = *timeout;
  options.profile_override = profile_override(*args);
  if (args->options.count("--against-profile")) options.against_profile_override = args->get("--against-profile", "");
  if (args->has("--quiet")) options.progress_every = 0;
  const std::string junit = args->get("--junit", "");
  if (args->options.count("--junit") && !junit_writable(junit, error)) return fail(error);

  if (!args->positional.empty()) {
    auto one = open_session(options.generator, options.call_timeout, error);
    auto two = one ? open_session(options.against, options.call_timeout, error) : nullptr;
    if (!two) return fail(error);
    const auto p1 = profile_in_force(one->declared_profile(), options.profile_override, error);
    const auto p2 = p1 ? profile_in_force(two->declared_profile(), options.against_profile_override, error) : std::nullopt;
    if (!p2) return fail(error);
    props::DiffSide first{one.get(), *p1}, second{two.get(), *p2};
    return compare_files(*args, args->positional, first, second);
  }

  const std::string report_dir = args->get("--report", "");
  if (args->options.count("--report") && !report_dir_writable(report_dir, error)) return fail(error);
  const auto result = props::run_diff(options, std::cerr, error);
  if (!result) return fail(error);
  props::print_diff_summary(*result, std::cout);
  if (!report_dir.empty() && !write_diff_report(report_dir, *args, options, *result)) return kExitInputError;
  if (!junit.empty() &&
      !write_junit(junit, "manifuzz diff", junit_cases(*result), result->seconds, error))
    return fail(error);
  if (!result->kinds.empty()) return kExitViolation;
  return result->interrupted ? kExitInterrupted : kExitClean;
}

}  // namespace mfz::cli
