// manifold_fuzzer: one fuzz input is one case (props/fuzz_input.h) run
// through the one pipeline, every invariant and every relation, as
// `manifuzz check` runs it. On a finding it writes the case file beside
// libFuzzer's artefact (`crash-<sha1>.case`) and aborts with the check's name.
//
// The generator is the built-in, or the plugin named by MANIFUZZ_GENERATOR
// (run in its worker with the call limit MANIFUZZ_CALL_TIMEOUT, seconds);
// MANIFUZZ_LEVEL=strict asks for one canonical answer in ties;
// MANIFUZZ_PROFILE=... replaces keys of the generator's declared profile.
// A plugin built with coverage counters (clang's -fsanitize=fuzzer-no-link)
// has them carried from its worker to the fuzzer after every call
// (harness/plugin_coverage.h), so its own branches guide the fuzzing too;
// MANIFUZZ_PLUGIN_COVERAGE=off leaves them in the worker, to measure what
// they bring.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "case_property.h"
#include "fuzz_input.h"
#include "harness/floating_point_traps.h"
#include "input_name.h"

namespace {

using namespace mfz;

// The built-in generator runs with floating-point traps: an invalid
// operation or a division by zero stops the run where it is made, not three
// checks later as a NaN in a report.
class TrappingSession : public GeneratorSession {
 public:
  explicit TrappingSession(std::unique_ptr<GeneratorSession> inner) : inner_(std::move(inner)) {}
  const std::string& name() const override { return inner_->name(); }
  const std::string& declared_profile() const override { return inner_->declared_profile(); }
  CallOutcome generate(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b, const mfz_pose& pose_b,
                       mfz_manifold& out, int32_t& status, std::string& failure) override {
    const FloatingPointTraps traps;
    return inner_->generate(a, pose_a, b, pose_b, out, status, failure);
  }

 private:
  std::unique_ptr<GeneratorSession> inner_;
};

struct Target {
  std::string generator_spec = "builtin";
  std::unique_ptr<GeneratorSession> generator;
  props::Selection selection;
  std::string artifact_prefix = "./";  // libFuzzer's default: the current folder
  std::string exact_artifact_path;
};

Target& target() {
  static Target t;
  return t;
}

std::string option_value(int argc, char** argv, const char* name) {
  const size_t length = std::strlen(name);
  std::string value;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], name, length) == 0) value = argv[i] + length;
  return value;
}

std::string case_path_for(const uint8_t* data, size_t size) {
  const Target& t = target();
  if (!t.exact_artifact_path.empty()) return t.exact_artifact_path + ".case";
  return t.artifact_prefix + "crash-" + props::input_name(data, size) + ".case";
}

[[noreturn]] void report_finding(const uint8_t* data, size_t size, props::FuzzCase c, const props::Finding& f) {
  const Target& t = target();
  const std::string path = case_path_for(data, size);
  c.file.extensions.push_back("note found by: manifold_fuzzer --generator " + t.generator_spec + " (input crash-" +
                              props::input_name(data, size) + ")");
  c.file.extensions.push_back("note violation: " + f.name + ": " + f.detail);
  for (const std::string& line : props::replay_lines(f, t.selection)) c.file.extensions.push_back(line);
  std::string error;
  if (!write_case_file(path, c.file, error)) std::fprintf(stderr, "manifold_fuzzer: %s\n", error.c_str());
  std::fprintf(stderr, "VIOLATION %s %s\n%s: %s\n", f.name.c_str(), path.c_str(), f.name.c_str(), f.detail.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  Target& t = target();
  t.artifact_prefix = option_value(*argc, *argv, "-artifact_prefix=");
  if (t.artifact_prefix.empty()) t.artifact_prefix = "./";
  t.exact_artifact_path = option_value(*argc, *argv, "-exact_artifact_path=");
  if (const char* spec = std::getenv("MANIFUZZ_GENERATOR"); spec && *spec) t.generator_spec = spec;
  if (const char* level = std::getenv("MANIFUZZ_LEVEL"); level && std::strcmp(level, "strict") == 0)
    t.selection.level = props::Level::strict;
  double call_timeout = 5;
  if (const char* seconds = std::getenv("MANIFUZZ_CALL_TIMEOUT"); seconds && *seconds) {
    char* end = nullptr;
    call_timeout = std::strtod(seconds, &end);
    if (*end != '\0' || !(call_timeout >= 0.05 && call_timeout <= 3600)) {
      std::fprintf(stderr, "manifold_fuzzer: MANIFUZZ_CALL_TIMEOUT takes seconds from 0.05 to 3600\n");
      std::exit(2);
    }
  }
  std::string error;
  const char* plugin_coverage = std::getenv("MANIFUZZ_PLUGIN_COVERAGE");
  const bool share_plugin_coverage = !plugin_coverage || std::strcmp(plugin_coverage, "off") != 0;
  t.generator = open_session(t.generator_spec, call_timeout, error, share_plugin_coverage);
  if (!t.generator) {
    std::fprintf(stderr, "manifold_fuzzer: %s\n", error.c_str());
    std::exit(2);
  }
  if (t.generator_spec == "builtin") t.generator = std::make_unique<TrappingSession>(std::move(t.generator));
  // The generator's declared profile applies, with MANIFUZZ_PROFILE's keys
  // replacing its own (manifuzz fuzz passes the profile in force whole).
  std::optional<std::string> override_text;
  if (const char* text = std::getenv("MANIFUZZ_PROFILE"); text && *text) override_text = text;
  const std::optional<Profile> profile = profile_in_force(t.generator->declared_profile(), override_text, error);
  if (!profile) {
    std::fprintf(stderr, "manifold_fuzzer: %s\n", error.c_str());
    std::exit(2);
  }
  t.selection.profile = *profile;
  t.selection.profile_from_command_line = true;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::optional<props::FuzzCase> c = props::decode_fuzz_input(data, size);
  if (!c) return -1;  // no case: keep it out of the corpus
  const props::CaseOutcome outcome = props::check_case(c->file, *target().generator, target().selection);
  if (outcome.invalid) return -1;
  if (outcome.finding) report_finding(data, size, *c, *outcome.finding);
  return 0;
}
