// manifuzz replay [--generator G] [--json] [--strict] [--profile P] FILE...
// Each case goes through the one pipeline (props/case_property.h): a plugin
// runs in its worker, and a relation finding replays its relation with the
// recorded parameters, so it exits 1 as it did when found.
#include <cstdio>
#include <iostream>

#include "case_property.h"
#include "cli/arguments.h"
#include "case_pictures.h"
#include "cli/program_files.h"
#include "harness/junit_report.h"
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

const char* word_of(const props::CaseOutcome& o) {
  if (o.finding) return "violation";
  return o.verdict ? verdict_word(*o.verdict) : "pass";
}

void print_text(const std::string& file, const props::CaseOutcome& o) {
  std::cout << "case " << file << "\n";
  if (!o.profile.empty()) std::cout << "  profile " << o.profile.text() << " (in force; its share of a tolerance in brackets)\n";
  if (o.manifold) std::cout << manifold_text(*o.manifold);
  if (o.verdict) std::cout << verdict_text(*o.verdict);
  if (o.finding) std::cout << "  FAIL " << o.finding->name << ": " << o.finding->detail << "\n";
  std::cout << "verdict " << word_of(o) << "\n\n";
}

void add_json(Json& json, const std::string& file, const props::CaseOutcome* o, const std::string& error) {
  json.begin_object().key("file").value(file);
  if (!o) {
    json.key("verdict").value("input-error").key("error").value(error);
  } else {
    json.key("scale").value(o->scale);
    json.key("profile").value(o->profile.text());
    if (o->manifold) manifold_json(json, *o->manifold);
    if (o->verdict) verdict_json(json, *o->verdict);
    if (o->finding) json.key("finding").begin_object().key("name").value(o->finding->name).key("detail").value(o->finding->detail).end_object();
    json.key("outcome").value(word_of(*o));
  }
  json.end_object();
}

}  // namespace

int replay_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words, {"--generator", "--call-timeout", "--profile", "--junit", "--render"},
                                    {"--json", "--strict"}, error);
  if (!args || args->positional.empty()) {
    std::cerr << "manifuzz replay: " << (args ? "no case file given" : error)
              << " (usage: manifuzz replay [--generator G] [--json] [--strict] [--profile P] [--junit FILE] [--render DIR] FILE...)\n";
    return kExitInputError;
  }
  std::unique_ptr<GeneratorSession> session = nullptr;
  if (const auto timeout = call_timeout(*args, error))
    session = open_session(resolve_generator(args->get("--generator", "builtin")), *timeout, error);
  if (!session) {
    std::cerr << "manifuzz replay: " << error << "\n";
    return kExitInputError;
  }
  props::Selection selection;
  selection.pass_details = true;  // replay prints every check
  if (args->has("--strict")) selection.level = props::Level::strict;
  if (!apply_profile(*args, *session, selection, error)) {
    std::cerr << "manifuzz replay: " << error << "\n";
    return kExitInputError;
  }
  const bool render = args->options.count("--render") > 0;
  selection.keep_transformed_run = render;
  const std::string junit = args->get("--junit", "");
  if (args->options.count("--junit") && !junit_writable(junit, error)) {
    std::cerr << "manifuzz replay: " << error << "\n";
    return kExitInputError;
  }
  std::vector<JunitCase> junit_cases;
  const bool json_output = args->has("--json");
  Json json;
  json.begin_object().key("generator").value(session->name()).key("cases").begin_array();
  Outcome outcome;
  for (const std::string& file : args->positional) {
    const CaseParse parsed = read_case_file(file);
    std::optional<props::CaseOutcome> run;
    if (parsed.value) {
      run = props::check_case(*parsed.value, *session, selection);
      if (run->invalid) error = file + ": " + run->invalid_reason, run.reset();
    } else {
      error = parsed.error;
    }
    if (!run) {
      std::cerr << "manifuzz replay: " << error << "\n";
      outcome.worsen(kExitInputError);
    } else {
      if (run->finding) {
        outcome.worsen(kExitViolation);
        // --json prints JSON alone on stdout; the VIOLATION line is in it.
        if (!json_output) std::printf("VIOLATION %s %s\n", run->finding->name.c_str(), file.c_str());
      }
      if (!json_output) print_text(file, *run);
      // --render DIR: each case's pictures beside its verdict.
      if (render && !props::write_case_pictures(args->get("--render", ""), props::file_stem(file),
                                         props::pictures_of_outcome(*parsed.value, *run, session->name()),
                                         "manifuzz replay: " + file, error)) {
        std::cerr << "manifuzz replay: " << error << "\n";
        outcome.worsen(kExitInputError);
      }
    }
    if (json_output) add_json(json, file, run ? &*run : nullptr, error);
    JunitCase c{"manifuzz.replay." + session->name(), file};
    if (!run) c.failure_message = "input error: " + error;
    else if (run->finding) c.failure_message = run->finding->name + ": " + run->finding->detail, c.failure_text = file;
    junit_cases.push_back(c);
  }
  if (!junit.empty() && !write_junit(junit, "manifuzz replay", junit_cases, 0, error)) {
    std::cerr << "manifuzz replay: " << error << "\n";
    outcome.worsen(kExitInputError);
  }
  json.end_array().end_object();
  if (json_output) std::cout << json.str() << "\n";
  std::cout.flush();
  return outcome.exit_status;
}

}  // namespace mfz::cli
