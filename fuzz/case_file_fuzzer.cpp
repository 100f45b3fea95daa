// case_file_fuzzer: the case-file reader on arbitrary bytes. Whatever it is
// given, it answers with a case or a one-line error, never a crash; a case it
// reads, written back, reads to the same case bit for bit; and building the
// scene from it never crashes either.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "case/case_file.h"
#include "case/scene.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "case_file_fuzzer: %s\n", what);
  std::abort();
}

bool same_bits(const mfz::CaseFile& x, const mfz::CaseFile& y) {
  return mfz::format_case(x) == mfz::format_case(y);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const mfz::CaseParse parsed = mfz::parse_case(text);
  if (!parsed.value) {
    if (parsed.error.empty()) fail("a refused case file without a reason");
    if (parsed.error.find('\n') != std::string::npos) fail("an error of more than one line");
    return 0;
  }
  const mfz::CaseParse again = mfz::parse_case(mfz::format_case(*parsed.value));
  if (!again.value) fail(("a written case does not read back: " + again.error).c_str());
  if (!same_bits(*parsed.value, *again.value)) fail("a written case reads back different");
  const mfz::SceneBuild scene = mfz::make_scene(*parsed.value);
  if (!scene.scene && scene.error.find('\n') != std::string::npos) fail("a scene error of more than one line");
  return 0;
}
