// manifuzz fuzz --generator G [--seconds T] [--jobs J] [--max-points N|A..B] [--corpus DIR] [--out DIR] [--strict]
// libFuzzer's manifold_fuzzer in fork mode on J cores (props/fuzz_campaign.h).
// The fuzzer program comes with the clang build (beside this manifuzz) or
// is named by MANIFUZZ_FUZZER.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "cli/arguments.h"
#include "cli/program_files.h"
#include "harness/junit_report.h"
#include "cli/run_reports.h"
#include "families.h"
#include "fuzz_campaign.h"
#include "fuzz_input.h"

namespace mfz::cli {
namespace {

constexpr const char* kUsage =
    "usage: manifuzz fuzz --generator G [--seconds T] [--jobs J] [--max-points N|A..B] [--corpus DIR] [--out DIR] [--strict] [--profile P] [--report DIR]";

int fail(const std::string& why) {
  std::cerr << "manifuzz fuzz: " << why << "\n";
  return kExitInputError;
}

std::string fuzzer_program() {
  if (const char* named = std::getenv("MANIFUZZ_FUZZER"); named && *named) return named;
  return beside_this_program({"../fuzz/manifold_fuzzer", "manifold_fuzzer", "../lib/manifuzz/manifold_fuzzer"});
}

/// The corpus replayed for a report's statistics: at most this many
/// inputs, for at most this long (the campaign's own numbers are libFuzzer's,
/// which knows nothing of families, contact kinds or margins).
constexpr size_t kReplayedInputs = 2000;
constexpr double kReplaySeconds = 60;

// What the final corpus covers, through the one pipeline: the families, the
// contact kinds and each check's margins. Returns the inputs replayed.
long long replay_corpus(const props::FuzzOptions& options, RunStatistics& statistics) {
  std::error_code ec;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(options.corpus_dir, ec))
    if (entry.is_regular_file()) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  std::string error;
  auto session = open_session(options.generator, options.call_timeout, error);
  if (!session) return 0;
  props::Selection selection;
  selection.level = options.level;
  const auto profile = profile_in_force(session->declared_profile(), options.profile_override, error);
  if (!profile) return 0;
  selection.profile = *profile;
  selection.profile_from_command_line = true;
  const auto started = std::chrono::steady_clock::now();
  long long replayed = 0;
  for (const std::string& file : files) {
    if (static_cast<size_t>(replayed) >= kReplayedInputs) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() > kReplaySeconds) break;
    std::ifstream in(file, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto decoded = props::decode_fuzz_input(bytes.data(), bytes.size());
    if (!decoded) continue;
    const props::CaseOutcome o = props::check_case(decoded->file, *session, selection);
    if (o.invalid || o.interrupted) continue;
    ++replayed;
    const auto& names = props::hull_family_names();
    statistics.count("hull family A", decoded->family_a < names.size() ? names[decoded->family_a] : "other");
    statistics.count("hull family B", decoded->family_b < names.size() ? names[decoded->family_b] : "other");
    statistics.count("contact kind", o.tags.contact_kind);
    if (o.finding) statistics.count("outcome", o.finding->name);
    else statistics.count("outcome", "pass");
    if (o.verdict) statistics.add_verdict(*o.verdict);
  }
  return replayed;
}

void write_fuzz_report(const std::string& dir, const props::FuzzOptions& options, const props::FuzzResult& result,
                       const ReplayWith& replay) {
  RunReport report;
  report.title = "manifuzz fuzz --generator " + replay.generator + " --jobs " + std::to_string(options.jobs);
  report.progress_unit = "executions";
  report.statistics = result.statistics;
  const long long replayed = replay_corpus(options, report.statistics);
  report.summary = {{"generator", replay.generator},
                    {"level", replay.strict ? "strict" : "contract"},
                    {"seconds", std::to_string(result.seconds)},
                    {"executions", std::to_string(result.execs)},
                    {"exec/s", std::to_string(static_cast<long long>(result.execs / std::max(result.seconds, 1e-9)))},
                    {"coverage (edges, features)", std::to_string(result.coverage) + ", " + std::to_string(result.features)},
                    {"corpus", std::to_string(result.corpus_inputs) + " inputs (" + std::to_string(result.corpus_added) +
                                   " added by this run) in " + options.corpus_dir},
                    {"statistics below", "from " + std::to_string(replayed) + " corpus inputs replayed after the run"}};
  if (options.confirm_with) report.summary.push_back({"rounding only (passed over)", std::to_string(result.rounding_only)});
  for (const props::FuzzFinding& f : result.findings)
    report.findings.push_back(reported_finding(f.name, f.kind + " case, after " +
                                                           std::to_string(static_cast<long long>(f.after_seconds)) +
                                                           " s, in " + std::to_string(f.artefacts) + " artefacts",
                                               f.case_path, replay));
  write_report_to(dir, report, "fuzz", std::cerr);
}

}  // namespace

int fuzz_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(
      words, {"--generator", "--seconds", "--jobs", "--max-points", "--corpus", "--out", "--call-timeout", "--minimise-seconds", "--profile", "--junit", "--confirm-with", "--report"},
      {"--strict", "--quiet"}, error);
  if (!args) return fail(error + " (" + kUsage + ")");
  if (!args->positional.empty()) return fail("unexpected argument " + mfz::quoted(args->positional[0]) + " (" + kUsage + ")");
  props::FuzzOptions options;
  options.generator = resolve_generator(args->get("--generator", "builtin"));
  options.corpus_dir = args->get("--corpus", options.corpus_dir);
  options.out_dir = args->get("--out", options.out_dir);
  if (options.corpus_dir.empty()) return fail("--corpus needs a folder name");
  if (args->options.count("--seconds")) {
    options.seconds = parse_seconds(args->get("--seconds", ""));
    if (!options.seconds || *options.seconds < 1) return fail("--seconds takes a number >= 1");
  }
  if (args->options.count("--minimise-seconds")) {
    const auto seconds = parse_seconds(args->get("--minimise-seconds", ""));
    if (!seconds) return fail("--minimise-seconds takes a number >= 0");
    options.minimise_seconds = *seconds;
  }
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  const auto jobs = parse_count(args->get("--jobs", "1"), 1, 4 * cores);
  if (!jobs) return fail("--jobs takes a whole number from 1 to " + std::to_string(4 * cores));
  options.jobs = static_cast<int>(*jobs);
  // --max-points N, or A..B: a campaign growing from A points to B.
  const std::string points = args->get("--max-points", std::to_string(props::kFuzzMaxPoints));
  const size_t dots = points.find("..");
  const auto max_points = parse_count(dots == std::string::npos ? points : points.substr(dots + 2), 4,
                                      props::kFuzzMaxPoints);
  const auto least_points =
      dots == std::string::npos ? std::optional<long long>(0) : parse_count(points.substr(0, dots), 4, props::kFuzzMaxPoints);
  if (!max_points || !least_points || (dots != std::string::npos && !(*least_points < *max_points)))
    return fail("--max-points takes a whole number from 4 to " + std::to_string(props::kFuzzMaxPoints) +
                ", or A..B with A < B (a campaign growing from A points to B)");
  options.max_points = static_cast<int>(*max_points);
  options.least_points = static_cast<int>(*least_points);
  if (options.least_points > 0 && !options.seconds) return fail("--max-points A..B needs --seconds");
  const auto timeout = call_timeout(*args, error);
  if (!timeout) return fail(error);
  options.call_timeout = *timeout;
  if (args->has("--strict")) options.level = props::Level::strict;
  if (args->has("--quiet")) options.progress_every = 0;
  options.profile_override = profile_override(*args);
  if (args->options.count("--confirm-with")) options.confirm_with = resolve_generator(args->get("--confirm-with", ""));
  options.fuzzer = fuzzer_program();
  if (options.fuzzer.empty())
    return fail("no manifold_fuzzer beside this manifuzz: fuzzing needs the clang build (cmake --preset clang; "
                "then build/clang/src/manifuzz fuzz), or MANIFUZZ_FUZZER naming the program");
  const std::string junit = args->get("--junit", "");
  if (args->options.count("--junit") && !junit_writable(junit, error)) return fail(error);
  const std::string report_dir = args->get("--report", "");
  if (args->options.count("--report") && !report_dir_writable(report_dir, error)) return fail(error);
  const auto result = props::run_fuzz(options, std::cerr, std::cout, error);
  if (!result) return fail(error);
  if (!report_dir.empty())
    write_fuzz_report(report_dir, options, *result,
                      {args->get("--generator", "builtin"), args->has("--strict"), options.profile_override,
                       options.call_timeout});
  if (!junit.empty()) {
    // One test case for the campaign, and one per distinct finding.
    const std::string classname = "manifuzz.fuzz." + args->get("--generator", "builtin");
    std::vector<JunitCase> cases = {{classname, "campaign", result->seconds}};
    if (!result->findings.empty()) cases[0].failure_message = std::to_string(result->findings.size()) + " findings";
    for (const props::FuzzFinding& f : result->findings)
      cases.push_back({classname, f.name + " (" + f.kind + ")", f.after_seconds, false, f.name + " after " +
                       std::to_string(static_cast<long long>(f.after_seconds)) + " s", f.case_path});
    if (!write_junit(junit, "manifuzz fuzz", cases, result->seconds, error)) return fail(error);
  }
  if (!result->findings.empty()) return kExitViolation;
  return result->interrupted ? kExitInterrupted : kExitClean;
}

}  // namespace mfz::cli
