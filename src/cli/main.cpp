// manifuzz: the command line (docs/contract.md, "Command line").
#include <iostream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/program_files.h"

namespace {

constexpr const char* kUsage =
    "usage: manifuzz <command> ...\n"
    "  replay  [--generator G] [--json] FILE...   check the cases in FILE... and print their verdicts\n"
    "  explain [--generator G] FILE               walk through one case step by step\n"
    "  check   [--generator G] [--cases N] [--seed S] [--seconds T] [--out DIR] [--strict]\n"
    "                                             run the property suite on random cases; write a\n"
    "                                             minimised case for the first violation;\n"
    "                                             --strict asks for one canonical answer in ties,\n"
    "                                             --only NAME checks one invariant or relation,\n"
    "                                             --call-timeout T limits each plugin call (s)\n"
    "                                             --profile P replaces keys of the generator's declared\n"
    "                                             profile: precision=float|double max-contacts=K\n"
    "                                             face-bias=F margin=M, or none (every command takes it)\n"
    "                                             --family F draws only these hull families: boxes,\n"
    "                                             hulls or family names, comma-separated; wide-face\n"
    "                                             (faces of 65 to 520 corners) only where named\n"
    "                                             --confirm-with G2 replays each finding against G2 (a\n"
    "                                             float engine's double build): one G2 does not make is\n"
    "                                             rounding, counted, and the run goes on\n"
    "  fuzz    [--generator G] [--seconds T] [--jobs J] [--corpus DIR] [--out DIR] [--strict]\n"
    "                                             libFuzzer on J cores; each distinct finding is minimised\n"
    "                                             and written to --out; the corpus (default fuzz-corpus)\n"
    "                                             grows and is resumed from; needs the clang build;\n"
    "                                             --confirm-with G2 as for check\n"
    "  diff    --generator G1 --against G2 [--cases N] [--seconds T] [--seed S] [--family F] [--out DIR]\n"
    "                                             the same cases to both; where they disagree (colliding,\n"
    "                                             depth, normal, contact region) beyond both profiles, whom\n"
    "                                             the oracles side with; a minimised case per kind; with\n"
    "                                             FILE... compares those; --against-profile P for G2\n"
    "  promote FILE [--name NAME] [--dir DIR] [--generator G] [--strict]\n"
    "                                             minimise a finding (case file or fuzz artefact) into\n"
    "                                             DIR/NAME.case (default corpus/regressions), a regression case\n"
    "  render  FILE -o OUT.svg|OUT.html [--generator G] [--strict]\n"
    "                                             a picture of the case: both hulls in the contact frame,\n"
    "                                             the reference and incident faces, the clipped polygon,\n"
    "                                             the contacts, n, and the check that breaks; .html can be\n"
    "                                             rotated and zoomed. explain and replay take --render DIR;\n"
    "                                             check, fuzz and diff take --report DIR (DIR/report.html)\n"
    "Exit status: 0 nothing found, 1 an invariant was violated, 2 usage, load or input error.\n";

// What --help lists after the usage: the generators G may name (those whose
// plugin is here) and the checks --only takes.
void print_names() {
  std::cout << "G is 'builtin' (the default), a path to a generator plugin .so, or one of:";
  for (const std::string& name : mfz::cli::bundled_generator_names())
    if (mfz::cli::resolve_generator(name) != name) std::cout << " " << name;
  std::cout << "\n  checks:";
  for (const std::string& name : mfz::invariant_names()) std::cout << " " << name;
  for (const std::string& name : mfz::props::relation_names()) std::cout << " " << name;
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
    std::cout << kUsage;
    print_names();
    return words.empty() ? mfz::cli::kExitInputError : mfz::cli::kExitClean;
  }
  const std::string command = words[0];
  words.erase(words.begin());
  if (command == "replay") return mfz::cli::replay_command(words);
  if (command == "explain") return mfz::cli::explain_command(words);
  if (command == "check") return mfz::cli::check_command(words);
  if (command == "fuzz") return mfz::cli::fuzz_command(words);
  if (command == "promote") return mfz::cli::promote_command(words);
  if (command == "diff") return mfz::cli::diff_command(words);
  if (command == "render") return mfz::cli::render_command(words);
  std::cerr << "manifuzz: unknown command '" << command << "' (try manifuzz --help)\n";
  return mfz::cli::kExitInputError;
}
