// The manifold fuzzer's custom mutator: mostly geometric mutations
// (props/geometric_mutator.h) on the decoded case, and one time in four
// libFuzzer's own byte mutations, which reach the numeric edge cases (a
// flipped exponent bit, a denormal, a huge count) that geometry does not.
// Only in libFuzzer builds: the replay build has no LLVMFuzzerMutate.
#include <cstring>

#include "fuzz_input.h"
#include "geometric_mutator.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

using namespace mfz::props;

size_t emit(const FuzzCase& c, uint8_t* data, size_t max_size) {
  const std::vector<uint8_t> bytes = encode_fuzz_input(c);
  if (bytes.size() > max_size) return 0;
  std::memcpy(data, bytes.data(), bytes.size());
  return bytes.size();
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  MutationRandom random(seed);
  if (random() % 4 == 0) return LLVMFuzzerMutate(data, size, max_size);
  std::optional<FuzzCase> c = decode_fuzz_input(data, size);
  FuzzCase mutated = c ? *c : draw_fuzz_case(random());
  if (c) mutate_geometrically(mutated, random);
  const size_t written = emit(mutated, data, max_size);
  return written > 0 ? written : LLVMFuzzerMutate(data, size, max_size);
}

extern "C" size_t LLVMFuzzerCustomCrossOver(const uint8_t* data1, size_t size1, const uint8_t* data2, size_t size2,
                                            uint8_t* out, size_t max_out_size, unsigned int seed) {
  const std::optional<FuzzCase> x = decode_fuzz_input(data1, size1), y = decode_fuzz_input(data2, size2);
  if (!x || !y) return 0;
  MutationRandom random(seed);
  return emit(cross_over(*x, *y, random), out, max_out_size);
}
