#pragma once
/// \file
/// Calls into a generator that may crash or hang. The built-in generator runs
/// in process; a plugin runs in a worker process that the harness forks once
/// and restarts after a crash or a hang (not a process per call: throughput
/// matters). A crash or a hang is a finding, never a crash of the harness.
#include <memory>
#include <string>

#include "harness/generator.h"

namespace mfz {

/// interrupted: SIGINT or SIGTERM arrived while waiting for the answer
/// (harness/interruption.h): no verdict, and the run stops.
enum class CallOutcome { done, crashed, hung, interrupted };

class GeneratorSession {
 public:
  virtual ~GeneratorSession() = default;
  virtual const std::string& name() const = 0;
  /// The profile the generator declares (`mfz_generator_profile()`), as text;
  /// empty when it declares none.
  virtual const std::string& declared_profile() const = 0;
  /// Poisons `out` and calls the generator. On `done`, `status` is its return
  /// value; on `crashed` or `hung`, `failure` says how (signal, time limit).
  virtual CallOutcome generate(const mfz_hull& a, const mfz_pose& pose_a, const mfz_hull& b, const mfz_pose& pose_b,
                               mfz_manifold& out, int32_t& status, std::string& failure) = 0;
};

/// `builtin` in process; anything else (a plugin path) in a worker process
/// with `call_timeout_seconds` per call. nullptr and a one-line reason when
/// the generator cannot be loaded. With `share_plugin_coverage` (the
/// fuzzer), a plugin built with coverage counters has them carried here
/// after each call (harness/plugin_coverage.h).
std::unique_ptr<GeneratorSession> open_session(const std::string& spec, double call_timeout_seconds,
                                               std::string& error, bool share_plugin_coverage = false);

/// An in-process session over an already opened generator.
std::unique_ptr<GeneratorSession> in_process_session(Generator generator);

}  // namespace mfz
