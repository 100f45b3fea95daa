#pragma once
/// \file
/// A plugin's own coverage, carried from its worker process to the fuzzer.
///
/// A plugin built with clang's `-fsanitize=fuzzer-no-link` counts every
/// edge it takes in its inline 8-bit counters, one byte an edge, which the
/// shared object keeps in its `__sancov_cntrs` section. libFuzzer reads the
/// counters of the modules loaded in its own process; the plugin runs in a
/// worker process (harness/generator_session.h), so what it counts there
/// would never reach the fuzzer, and fuzzing a plugin would be guided by the
/// checks' branches alone. So the worker sends, after each call, the
/// counters the call set (and clears them), and the fuzzer's process, which
/// has loaded the same library without calling it (so that libFuzzer knows
/// its counters and their edges), writes them into its own copy before
/// libFuzzer reads them. A library built without the counters has no
/// section: nothing is sent.
#include <cstddef>
#include <cstdint>
#include <string>

namespace mfz {

/// The inline 8-bit counters of one loaded shared object, in this process.
struct CoverageCounters {
  uint8_t* begin = nullptr;
  size_t size = 0;
};

/// The counters of the loaded shared object that holds `address` (say, its
/// `mfz_generate`): its `__sancov_cntrs` section, read off the file's section
/// headers and moved by the object's load address. Empty when the object
/// was built without them, when the file cannot be read, or when the
/// section does not lie in a writable segment of the object.
CoverageCounters coverage_counters_at(const void* address);

/// Appends to `message` the counters this process's call set: their count,
/// then each as one word (its index shifted up a byte, its value in the low
/// byte); and clears them for the next call. Counters past kMaxSharedCounters
/// are cleared and not sent.
void take_coverage_hits(const CoverageCounters& counters, std::string& message);

/// Adds hits read from the worker to this process's counters (a fuzz
/// execution makes several calls), stopping at 255; false when a hit's index
/// is past them (a worker that speaks of another library).
bool apply_coverage_hits(const CoverageCounters& counters, const uint32_t* hits, size_t count);

/// A hit's index has 24 bits.
inline constexpr size_t kMaxSharedCounters = size_t{1} << 24;

}  // namespace mfz
