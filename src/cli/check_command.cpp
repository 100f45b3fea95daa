// manifuzz check --generator G [--cases N] [--seed S] [--seconds T] [--jobs J] [--out DIR]
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "check_driver.h"
#include "families.h"
#include "finding_file.h"
#include "cli/arguments.h"
#include "cli/program_files.h"
#include "harness/junit_report.h"
#include "cli/run_reports.h"

namespace mfz::cli {

/// Without --cases or --seconds the check runs this many cases: the main job's budget.
constexpr long long kDefaultCases = 20000;

namespace {

/// What one job of `check --jobs` tells the parent on its stdout, besides
/// its VIOLATION line: "cases N seconds T".
constexpr const char* kJobTally = "cases ";
/// The prefix of a job's statistics lines (RunStatistics::to_lines).
const std::string kJobStatistics = "statistics ";

// One job: the check on its own stream (seed + job), its log into a file
// (the first job's to the terminal, for the progress lines).
int run_one_job(props::CheckOptions options, int job, int jobs, int tally_fd) {
  options.seed += static_cast<uint64_t>(job);
  if (options.cases) options.cases = (*options.cases + jobs - 1 - job) / jobs;
  if (job > 0) options.progress_every = 0;
  std::ostringstream quiet;
  std::ostream& log = job == 0 ? std::cerr : static_cast<std::ostream&>(quiet);
  std::string error;
  const auto result = props::run_check(options, log, error);
  std::string tally;
  int status = kExitClean;
  if (!result) {
    std::cerr << "manifuzz check: job " << job + 1 << ": " << error << "\n";
    status = kExitInputError;
  } else {
    tally = std::string(kJobTally) + std::to_string(result->cases) + " seconds " + std::to_string(result->seconds) + "\n";
    // Its statistics, a line each behind kJobStatistics, for the report.
    std::istringstream lines(result->statistics.to_lines());
    for (std::string line; std::getline(lines, line);) tally += kJobStatistics + line + "\n";
    if (result->finding) {
      if (job > 0) std::cerr << quiet.str();
      tally += "VIOLATION " + result->finding->name + " " + result->case_path + "\n";
      status = kExitViolation;
    } else if (result->interrupted) {
      status = kExitInterrupted;
    }
  }
  if (write(tally_fd, tally.data(), tally.size()) < 0) status = kExitInputError;
  return status;
}

// `check --jobs J`: J processes, each on its own stream (seeds S .. S+J-1),
// the cases shared out; the first finding stops the others (SIGTERM: they
// end with their summary) and is the run's.
int run_jobs(const props::CheckOptions& options, int jobs, std::string& violation, long long& cases, double& seconds,
             RunStatistics& statistics) {
  std::vector<std::vector<ProgressSample>> progress(static_cast<size_t>(jobs));
  std::vector<pid_t> children;
  std::vector<int> tallies;
  std::cerr << "manifuzz check: " << jobs << " jobs on seeds " << options.seed << " to " << options.seed + jobs - 1
            << " (replay one with --seed S and no --jobs)\n";
  std::cerr.flush();
  for (int job = 0; job < jobs; ++job) {
    int fds[2];
    if (pipe(fds) != 0) return kExitInputError;
    const pid_t pid = fork();
    if (pid == 0) {
      close(fds[0]);
      _exit(run_one_job(options, job, jobs, fds[1]));
    }
    close(fds[1]);
    children.push_back(pid);
    tallies.push_back(fds[0]);
  }
  int worst = kExitClean;
  for (size_t done = 0; done < children.size(); ++done) {
    int status = 0;
    const pid_t pid = wait(&status);
    const auto at = std::find(children.begin(), children.end(), pid) - children.begin();
    if (at >= static_cast<long>(children.size())) continue;
    std::string text;
    char buffer[512];
    for (ssize_t n; (n = read(tallies[at], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<size_t>(n));
    close(tallies[at]);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind(kJobTally, 0) == 0) {
        long long n = 0;
        double t = 0;
        std::sscanf(line.c_str(), "cases %lld seconds %lf", &n, &t);
        cases += n;
        seconds = std::max(seconds, t);
      } else if (line.rfind(kJobStatistics, 0) == 0) {
        RunStatistics one;
        if (one.add_line(line.substr(kJobStatistics.size()))) statistics.merge(one);
        if (!one.samples().empty()) progress[at].push_back(one.samples()[0]);
      } else if (line.rfind("VIOLATION ", 0) == 0 && violation.empty()) {
        violation = line;
      }
    }
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : kExitInputError;
    if (code == kExitViolation && worst != kExitInputError) {
      worst = kExitViolation;
      for (const pid_t other : children)
        if (other != pid) kill(other, SIGTERM);
    } else if (code == kExitInputError) {
      worst = kExitInputError;
    } else if (code == kExitInterrupted && worst == kExitClean) {
      worst = kExitInterrupted;
    }
  }
  statistics.set_samples(combined_progress(progress));
  std::cerr << "manifuzz check: " << jobs << " jobs, " << cases << " cases in " << seconds << " s ("
            << static_cast<long long>(cases / std::max(seconds, 1e-9)) << " cases/s)\n";
  if (!violation.empty()) std::printf("%s\n", violation.c_str());
  return worst;
}

// The JUnit report of a check: one test case per invariant and relation,
// the finding's failed, those --only left out skipped.
bool write_check_junit(const std::string& path, const std::string& generator, const props::CheckOptions& options,
                       const std::string& violation, double seconds, std::string& error) {
  std::string name, file;
  std::istringstream words(violation);
  std::string keyword;
  words >> keyword >> name >> file;
  std::vector<JunitCase> cases;
  std::vector<std::string> names = invariant_names();
  for (const std::string& relation : props::relation_names()) names.push_back(relation);
  for (const std::string& check : names) {
    JunitCase c{"manifuzz.check." + generator, check};
    c.skipped = !options.selection.wants(check);
    if (check == name) c.failure_message = check + " violated", c.failure_text = "minimised case: " + file;
    cases.push_back(c);
  }
  if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
    cases.push_back({"manifuzz.check." + generator, name, 0, false, name, "minimised case: " + file});
  return write_junit(path, "manifuzz check " + generator + " --seed " + std::to_string(options.seed), cases,
                     seconds, error);
}

}  // namespace


int check_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(
      words, {"--generator", "--cases", "--seed", "--seconds", "--jobs", "--out", "--call-timeout", "--only", "--profile", "--family", "--junit", "--confirm-with", "--report"},
      {"--quiet", "--strict"}, error);
  const auto usage = [](const std::string& why) {
    std::cerr << "manifuzz check: " << why
              << " (usage: manifuzz check --generator G [--cases N] [--seed S] [--seconds T] [--jobs J] [--out DIR] [--strict] [--profile P] [--family F] [--junit FILE] [--confirm-with G2] [--report DIR])\n";
    return kExitInputError;
  };
  if (!args) return usage(error);
  if (!args->positional.empty()) return usage("unexpected argument '" + args->positional[0] + "'");
  props::CheckOptions options;
  options.generator = resolve_generator(args->get("--generator", "builtin"));
  options.out_dir = args->get("--out", "failures");
  const auto budget = run_budget(*args, kDefaultCases, error);
  if (!budget) return usage(error);
  options.cases = budget->cases;
  options.seconds = budget->seconds;
  options.seed = budget->seed;
  if (const auto timeout = call_timeout(*args, error)) options.call_timeout = *timeout;
  else return usage(error);
  if (args->options.count("--only")) {
    // A misspelt name would check nothing and pass: refuse it.
    const std::string only = args->get("--only", "");
    const auto& invariants = invariant_names();
    const auto& relations = props::relation_names();
    if (std::find(invariants.begin(), invariants.end(), only) == invariants.end() &&
        std::find(relations.begin(), relations.end(), only) == relations.end())
      return usage("--only takes an invariant or relation name, not '" + only + "'");
    options.selection.names.insert(only);
  }
  if (args->options.count("--family")) {
    const auto families = props::hull_families_named(args->get("--family", ""), error);
    if (!families) return usage(error);
    options.hull_families = *families;
  }
  if (args->options.count("--confirm-with")) options.confirm_with = resolve_generator(args->get("--confirm-with", ""));
  if (args->has("--quiet")) options.progress_every = 0;
  if (args->has("--strict")) options.selection.level = props::Level::strict;
  options.profile_override = profile_override(*args);
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  const auto jobs = parse_count(args->get("--jobs", "1"), 1, 4 * cores);
  if (!jobs) return usage("--jobs takes a whole number from 1 to " + std::to_string(4 * cores));
  const std::string junit = args->get("--junit", "");
  if (args->options.count("--junit") && !junit_writable(junit, error)) return usage(error);
  const std::string report_dir = args->get("--report", "");
  if (args->options.count("--report") && !report_dir_writable(report_dir, error)) return usage(error);
  const ReplayWith replay{args->get("--generator", "builtin"), args->has("--strict"), options.profile_override,
                          options.call_timeout};
  // --report DIR: the run's statistics, and the finding with its picture.
  const auto write_report = [&](const std::string& violation, long long cases, double seconds, long long invalid,
                                const RunStatistics& statistics, const std::string& detail) {
    RunReport report;
    report.title = "manifuzz check --generator " + replay.generator + " --seed " + std::to_string(options.seed) +
                   (*jobs > 1 ? " --jobs " + std::to_string(*jobs) : "") + (replay.strict ? " --strict" : "");
    report.summary = {{"generator", replay.generator},
                      {"seed", std::to_string(options.seed)},
                      {"level", replay.strict ? "strict" : "contract"},
                      {"cases", std::to_string(cases)},
                      {"seconds", std::to_string(seconds)},
                      {"cases/s", std::to_string(static_cast<long long>(cases / std::max(seconds, 1e-9)))}};
    if (invalid >= 0) report.summary.push_back({"invalid inputs discarded", std::to_string(invalid)});
    report.statistics = statistics;
    if (!violation.empty()) {
      // "VIOLATION <name> <file>"
      const size_t name_end = violation.find(' ', 10);
      report.findings.push_back(reported_finding(violation.substr(10, name_end - 10), detail,
                                                 violation.substr(name_end + 1), replay));
    }
    return write_report_to(report_dir, report, "check", std::cerr);
  };
  const auto reported = [&](int status, const std::string& violation, double seconds) {
    if (!junit.empty() && !write_check_junit(junit, args->get("--generator", "builtin"), options, violation, seconds, error)) {
      std::cerr << "manifuzz check: " << error << "\n";
      return kExitInputError;
    }
    return status;
  };
  if (*jobs > 1) {
    // The out folder and the generator are tried once, before any job starts.
    if (!props::prepare_out_dir(options.out_dir, error) || !open_session(options.generator, options.call_timeout, error)) {
      std::cerr << "manifuzz check: " << error << "\n";
      return kExitInputError;
    }
    std::string violation;
    long long cases = 0;
    double seconds = 0;
    RunStatistics statistics;
    const int status = run_jobs(options, static_cast<int>(*jobs), violation, cases, seconds, statistics);
    if (!report_dir.empty() && !write_report(violation, cases, seconds, -1, statistics, "")) return kExitInputError;
    return reported(status, violation, seconds);
  }
  const auto result = props::run_check(options, std::cerr, error);
  if (!result) {
    std::cerr << "manifuzz check: " << error << "\n";
    return kExitInputError;
  }
  const std::string violation =
      result->finding ? "VIOLATION " + result->finding->name + " " + result->case_path : std::string();
  if (!report_dir.empty() && !write_report(violation, result->cases, result->seconds, result->invalid,
                                           result->statistics, result->finding ? result->finding->detail : ""))
    return kExitInputError;
  if (!result->finding) return reported(result->interrupted ? kExitInterrupted : kExitClean, "", result->seconds);
  std::cerr << "minimised case (" << result->shrink_steps << " shrink steps):\n" << result->minimised_text;
  std::printf("%s\n", violation.c_str());
  return reported(kExitViolation, violation, result->seconds);
}

}  // namespace mfz::cli
