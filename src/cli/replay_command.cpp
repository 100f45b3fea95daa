// manifuzz replay [--generator G] [--json] FILE...
#include <cstdio>
#include <iostream>

#include "harness/case_run.h"
#include "cli/arguments.h"
#include "harness/report.h"

namespace mfz::cli {
namespace {

struct Outcome {
  int exit_status = kExitClean;
  void worsen(int status) {
    // An input error outranks a violation: a script must not take a broken
    // file for a finding.
    if (status == kExitInputError || (status == kExitViolation && exit_status == kExitClean)) exit_status = status;
  }
};

void print_text(const std::string& file, const CaseRun& run) {
  std::cout << "case " << file << "\n"
            << manifold_text(run.manifold) << verdict_text(run.verdict) << "verdict " << verdict_word(run.verdict)
            << "\n\n";
}

void add_json(Json& json, const std::string& file, const CaseRun* run, const std::string& error) {
  json.begin_object().key("file").value(file);
  if (!run) {
    json.key("verdict").value("input-error").key("error").value(error);
  } else {
    json.key("scale").value(run->scene.scale);
    manifold_json(json, run->manifold);
    verdict_json(json, run->verdict);
  }
  json.end_object();
}

}  // namespace

int replay_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words, {"--generator"}, {"--json"}, error);
  if (!args || args->positional.empty()) {
    std::cerr << "manifuzz replay: " << (args ? "no case file given" : error)
              << " (usage: manifuzz replay [--generator G] [--json] FILE...)\n";
    return kExitInputError;
  }
  const auto generator = Generator::open(args->get("--generator", "builtin"), error);
  if (!generator) {
    std::cerr << "manifuzz replay: " << error << "\n";
    return kExitInputError;
  }
  const bool json_output = args->has("--json");
  Json json;
  json.begin_object().key("generator").value(generator->name()).key("cases").begin_array();
  Outcome outcome;
  for (const std::string& file : args->positional) {
    const CaseParse parsed = read_case_file(file);
    std::optional<CaseRun> run;
    if (parsed.value) run = run_case(*parsed.value, *generator, error);
    else error = parsed.error;
    if (!run) {
      std::cerr << "manifuzz replay: " << (parsed.value ? file + ": " : "") << error << "\n";
      outcome.worsen(kExitInputError);
    } else {
      const Verdict& v = run->verdict;
      if (v.refused() || v.first_violation()) {
        outcome.worsen(kExitViolation);
        std::printf("VIOLATION %s %s\n", v.refused() ? "refused" : v.first_violation()->name.c_str(), file.c_str());
      }
      if (!json_output) print_text(file, *run);
    }
    if (json_output) add_json(json, file, run ? &*run : nullptr, error);
  }
  json.end_array().end_object();
  if (json_output) std::cout << json.str() << "\n";
  return outcome.exit_status;
}

}  // namespace mfz::cli
