// manifuzz promote FILE [--name NAME] [--dir DIR] [--generator G] [--strict] [--seconds T]
// A finding (a case file, or libFuzzer's raw artefact) becomes a regression
// case in one command: it is checked against the generator it failed,
// minimised, and written as DIR/NAME.case with a header that says what it
// checks, when and how it was found, and what a fixed generator answers.
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "case_property.h"
#include "cli/arguments.h"
#include "cli/program_files.h"
#include "finding_minimiser.h"
#include "fuzz_input.h"

namespace mfz::cli {
namespace {

constexpr const char* kUsage =
    "usage: manifuzz promote FILE [--name NAME] [--dir DIR] [--generator G] [--strict] [--profile P] [--seconds T]";
/// Regression cases land here unless --dir says otherwise.
constexpr const char* kDefaultDir = "corpus/regressions";
/// How long minimising may take, unless --seconds says otherwise.
constexpr double kDefaultShrinkSeconds = 30;

std::string today() {
  const std::time_t now = std::time(nullptr);
  char day[16];
  std::strftime(day, sizeof day, "%Y-%m-%d", std::gmtime(&now));
  return day;
}

// The generator a finding was made with, as its `note found by:` line says.
std::string generator_in_notes(const CaseFile& c) {
  for (const std::string& line : c.extensions) {
    if (line.rfind("note found by:", 0) != 0) continue;
    const size_t at = line.find("--generator ");
    if (at == std::string::npos) continue;
    const size_t start = at + std::string("--generator ").size();
    return line.substr(start, line.find(' ', start) - start);
  }
  return {};
}

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > 120 || name[0] == '.') return false;
  for (char ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_' && ch != '.') return false;
  return true;
}

// How the project's own tutorial method answers, for the regression test's
// `expect-tutorial` line; empty outside the project's build tree.
std::string tutorial_answer(const CaseFile& c, const props::Selection& selection) {
  const std::string plugin = beside_this_program({"../plugins/libmanifuzz_tutorial.so"});
  if (plugin.empty()) return {};
  std::string error;
  const auto tutorial = open_session(plugin, 5, error);
  if (!tutorial) return {};
  const props::CaseOutcome o = props::check_case(c, *tutorial, selection);
  return o.finding ? o.finding->name : "pass";
}

int fail(const std::string& why) {
  std::cerr << "manifuzz promote: " << why << "\n";
  return kExitInputError;
}

}  // namespace

int promote_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words, {"--name", "--dir", "--generator", "--seconds", "--call-timeout", "--profile"},
                                    {"--strict"}, error);
  if (!args) return fail(error + " (" + kUsage + ")");
  if (args->positional.size() != 1) return fail(std::string("give one finding (") + kUsage + ")");
  const std::string file = args->positional[0];
  const CaseParse parsed = props::read_case_or_fuzz_input(file);
  if (!parsed.value) return fail(parsed.error);
  const CaseFile& finding_case = *parsed.value;
  std::string spec = args->get("--generator", generator_in_notes(finding_case));
  if (spec.empty()) spec = "builtin";
  spec = resolve_generator(spec);
  const std::string dir = args->get("--dir", kDefaultDir);
  const double seconds = args->options.count("--seconds") ? parse_seconds(args->get("--seconds", "")).value_or(-1)
                                                           : kDefaultShrinkSeconds;
  if (seconds < 0) return fail("--seconds takes a number >= 0");
  const auto timeout = call_timeout(*args, error);
  if (!timeout) return fail(error);
  auto generator = open_session(spec, *timeout, error);
  if (!generator) return fail(error);
  props::Selection selection;
  if (args->has("--strict")) selection.level = props::Level::strict;
  if (!apply_profile(*args, *generator, selection, error)) return fail(error);

  // 1. The finding must still fail against its generator.
  const props::CaseOutcome outcome = props::check_case(finding_case, *generator, selection);
  if (outcome.invalid) return fail(file + ": " + outcome.invalid_reason);
  // The profile the finding failed under (its `profile` line, or the one in
  // force) goes with it into the regression case.
  selection.profile = outcome.profile;
  selection.profile_from_command_line = true;
  if (!outcome.finding)
    return fail(quoted(file, 4096) + " passes against " + generator->name() +
                ": nothing to promote (--generator names the generator it failed)");
  // 2. Minimised, keeping the failure's margin.
  const props::Minimised minimal =
      props::minimise_finding(finding_case, *outcome.finding, *generator, selection, seconds);
  // 3. Named, with its header.
  const std::string name = args->get("--name", minimal.finding.name + "-" + today());
  if (!valid_name(name)) return fail("--name takes letters, digits, '-', '_' and '.', not " + mfz::quoted(name));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail("cannot create " + quoted(dir, 4096) + ": " + ec.message());
  const std::string path = dir + "/" + name + ".case";
  if (std::filesystem::exists(path)) return fail(quoted(path, 4096) + " exists: choose another --name");
  CaseFile promoted = minimal.file;
  promoted.extensions.clear();
  promoted.extensions.push_back("note promoted: " + today() + " by manifuzz promote from " + printable(file, 200));
  promoted.extensions.push_back("note check: " + minimal.finding.name + ": " + minimal.finding.detail);
  promoted.extensions.push_back("note generator it failed: " + generator->name() + " (" + spec + ")");
  for (const std::string& line : finding_case.extensions)
    if (line.rfind("note found by:", 0) == 0) promoted.extensions.push_back(line);
  for (const std::string& line : props::replay_lines(minimal.finding, selection))
    promoted.extensions.push_back(line);
  // What a correct generator answers: every check passes.
  promoted.extensions.push_back("expect pass");
  if (const std::string tutorial = tutorial_answer(promoted, selection); !tutorial.empty())
    promoted.extensions.push_back("expect-tutorial " + tutorial);
  if (!write_case_file(path, promoted, error)) return fail(error);
  std::cout << "promoted " << path << ": " << minimal.finding.name << " against " << generator->name() << " ("
            << minimal.steps << " shrink steps); a fixed generator passes it\n";
  return kExitClean;
}

}  // namespace mfz::cli
