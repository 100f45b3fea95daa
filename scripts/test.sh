#!/usr/bin/env bash
# Builds and runs every test: g++ (the default preset), clang++ (with the
# libFuzzer targets and `manifuzz fuzz`), and clang++ with ASan + UBSan; then
# ClusterFuzzLite's build.sh with ASan + UBSan, each target run for a few
# seconds. Properties run a bounded number of cases here. The clang preset
# leaves out the CLI, mutation and answer_fingerprint tests, which the g++
# build runs on the same code (under the fuzzers' instrumentation they take
# five times as long);
# the sanitizer preset leaves out the mutants and the peers (not built there).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh --tests
for preset in default clang sanitize; do
  echo "== $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
echo "== clusterfuzzlite build.sh"
tests/clusterfuzzlite_build_test.sh
