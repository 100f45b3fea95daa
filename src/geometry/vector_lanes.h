#pragma once
/// \file
/// Loops that run over many columns at once in vector lanes are built twice,
/// for AVX2 and for any x86-64, and the processor picks at load time. Each
/// lane does the same operations in the same order either way (AVX2 brings
/// no fused multiply-add, and the build forbids contraction), so both give
/// the same bits; AVX2 only runs four doubles at a time instead of two.
///
/// Mark only a function local to its file (an anonymous namespace), and call
/// it from an ordinary one, as the brute-force oracle's rows always were: a
/// member function defined apart from its class and marked there built with
/// g++ but not with clang++ 14, whose callers in other files found no symbol
/// (`EdgeArcs::crossing`, from sat.cpp).
#if defined(__x86_64__) && defined(__GNUC__)
#define MFZ_VECTOR_LANES __attribute__((target_clones("avx2", "default")))
#else
#define MFZ_VECTOR_LANES
#endif
