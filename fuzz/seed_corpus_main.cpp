// Writes the manifold fuzzer's seed corpus into FOLDER: one input for each
// hull family, drawn the way `manifuzz check` draws its cases
// (props::seed_inputs), as corpus/manifold_fuzzer/ holds it.
#include <cstdio>
#include <fstream>
#include <string>

#include "families.h"
#include "geometric_mutator.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FOLDER\n", argv[0]);
    return 2;
  }
  const auto inputs = mfz::props::seed_inputs();
  for (const auto& [name, bytes] : inputs) {
    std::ofstream out(std::string(argv[1]) + "/" + name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::fprintf(stderr, "cannot write into %s\n", argv[1]);
      return 2;
    }
  }
  std::printf("%zu seed inputs written\n", inputs.size());
  return inputs.size() == mfz::props::hull_family_names().size() ? 0 : 1;
}
