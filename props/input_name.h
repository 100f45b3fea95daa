#pragma once
/// \file
/// The name libFuzzer gives an input, in its corpus and in its artefacts
/// (`crash-<name>`): the SHA-1 of its bytes, in hex. A corpus file whose
/// name is not the hash of its bytes was cut short while being written.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace mfz::props {

std::string input_name(const uint8_t* data, size_t size);
inline std::string input_name(std::string_view bytes) {
  return input_name(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace mfz::props
