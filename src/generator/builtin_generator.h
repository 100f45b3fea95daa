#pragma once
/// \file
/// The built-in generator behind the plugin ABI, under its own symbol names so
/// that a harness which links it can still dlopen a plugin exporting the
/// standard `mfz_*` names.
#include "manifuzz/abi.h"

extern "C" {
int32_t mfz_builtin_abi_version(void);
const char* mfz_builtin_generator_name(void);
int32_t mfz_builtin_generate(const mfz_hull* a, const mfz_pose* pose_a, const mfz_hull* b, const mfz_pose* pose_b,
                             mfz_manifold* out);
}
