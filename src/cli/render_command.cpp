// manifuzz render FILE -o OUT.svg|OUT.html [--generator G] [--strict] [--profile P]
// A picture of one case, through the one pipeline: the generator's answer,
// the check that breaks, and for a relation finding its transformed run.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/arguments.h"
#include "case_pictures.h"
#include "cli/program_files.h"
#include "fuzz_input.h"
#include "render/html_case_view.h"
#include "render/svg_picture.h"

namespace mfz::cli {
namespace {

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

int render_command(const std::vector<std::string>& words) {
  std::string error;
  const auto args = parse_arguments(words, {"-o", "--output", "--generator", "--call-timeout", "--profile"},
                                    {"--strict"}, error);
  const std::string usage = " (usage: manifuzz render FILE -o OUT.svg|OUT.html [--generator G] [--strict] [--profile P])";
  const auto fail = [&](const std::string& why) {
    std::cerr << "manifuzz render: " << why << "\n";
    return kExitInputError;
  };
  if (!args) return fail(error + usage);
  if (args->positional.size() != 1) return fail("expected exactly one case file" + usage);
  const std::string out = args->options.count("-o") ? args->get("-o", "") : args->get("--output", "");
  if (out.empty()) return fail("no output file: -o OUT.svg or -o OUT.html" + usage);
  if (!ends_with(out, ".svg") && !ends_with(out, ".html")) return fail("the output must end in .svg or .html: " + out);
  std::unique_ptr<GeneratorSession> session;
  if (const auto timeout = call_timeout(*args, error))
    session = open_session(resolve_generator(args->get("--generator", "builtin")), *timeout, error);
  if (!session) return fail(error);
  props::Selection selection;
  if (args->has("--strict")) selection.level = props::Level::strict;
  if (!apply_profile(*args, *session, selection, error)) return fail(error);
  const std::string& file = args->positional[0];
  const CaseParse parsed = props::read_case_or_fuzz_input(file);
  if (!parsed.value) return fail(parsed.error);
  const std::vector<CasePicture> runs = props::pictures_of_case(*parsed.value, *session, selection, error);
  if (runs.empty()) return fail(file + ": " + error);
  const std::string text = ends_with(out, ".svg") ? svg_of(runs) : html_case_view(runs, "manifuzz: " + file);
  std::error_code ec;
  if (const auto folder = std::filesystem::path(out).parent_path(); !folder.empty())
    std::filesystem::create_directories(folder, ec);
  std::ofstream stream(out, std::ios::binary);
  stream << text;
  stream.close();
  if (!stream) return fail("cannot write " + out);
  // The picture is written either way; a case that fails (or a generator
  // that crashed or hung on it) is a finding, as in every command.
  for (const CasePicture& run : runs)
    if (run.broken) return kExitViolation;
  return kExitClean;
}

}  // namespace mfz::cli
