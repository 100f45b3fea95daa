// A shared library that is not a generator: it exports no mfz_generate.
#include "manifuzz/abi.h"

extern "C" {
int32_t mfz_abi_version(void) { return MFZ_ABI_VERSION; }
const char* mfz_generator_name(void) { return "half-a-generator"; }
}
