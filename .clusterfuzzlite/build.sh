#!/bin/bash -eu
# Builds the fuzz targets under OSS-Fuzz's and ClusterFuzzLite's conventions:
# the compilers and flags come from $CC $CXX $CFLAGS $CXXFLAGS (the
# sanitizer and the coverage instrumentation are theirs), the engine from
# $LIB_FUZZING_ENGINE, and everything a target needs lands in $OUT: the
# program, <target>_seed_corpus.zip, <target>.dict, <target>.options, and
# the shared libraries the runner image lacks (lib/, found through an rpath).
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${WORK:-/tmp}/manifuzz-fuzz-build"
targets=(manifold_fuzzer case_file_fuzzer)

cmake -S "$source_dir" -B "$build_dir" -G Ninja \
  -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_C_FLAGS="$CFLAGS" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DCMAKE_BUILD_RPATH='$ORIGIN/lib' \
  -DMANIFUZZ_BUILD_FUZZERS=ON -DMANIFUZZ_FUZZING_ENGINE="$LIB_FUZZING_ENGINE" \
  -DMANIFUZZ_BUILD_TESTS=OFF -DMANIFUZZ_BUILD_BENCHMARKS=OFF -DMANIFUZZ_BUILD_PEERS=OFF -DMANIFUZZ_BUILD_MUTANTS=OFF
cmake --build "$build_dir" --target "${targets[@]}"

mkdir -p "$OUT/lib"
for target in "${targets[@]}"; do
  cp "$build_dir/fuzz/$target" "$OUT/"
  cp "$source_dir/fuzz/$target.dict" "$source_dir/fuzz/$target.options" "$OUT/"
  rm -f "$OUT/${target}_seed_corpus.zip"
  (cd "$source_dir/corpus/$target" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
  # The libraries from the build image's archive that a runner image lacks.
  ldd "$build_dir/fuzz/$target" | awk '/libqhull|libccd|libcrypto/ { print $3 }' | xargs -r -I{} cp -L {} "$OUT/lib/"
done
