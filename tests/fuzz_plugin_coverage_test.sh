#!/usr/bin/env bash
# manifold_fuzzer sees a plugin's own branches: replaying the seed corpus
# through the built-in plugin (instrumented in the clang build), libFuzzer
# counts more edges than with the plugin's counters left in its worker
# (MANIFUZZ_PLUGIN_COVERAGE=off), and as many more as the plugin's call
# alone covers (over five hundred: its generator, not just its entry point;
# 1,165 when written).
# usage: fuzz_plugin_coverage_test.sh MANIFOLD_FUZZER PLUGIN CORPUS
set -u
fuzzer=$1 plugin=$2 corpus=$3
# libFuzzer's "INITED cov: N" once the corpus has run.
edges() {
  MANIFUZZ_PLUGIN_COVERAGE=$1 MANIFUZZ_GENERATOR=$plugin "$fuzzer" -runs=0 "$corpus" 2>&1 |
    sed -n 's/.*INITED cov: \([0-9]*\).*/\1/p'
}
shared=$(edges on) kept=$(edges off)
echo "edges: ${shared:-none} with the plugin's counters shared, ${kept:-none} without"
if [[ -z $shared || -z $kept ]]; then echo "FAILED: the fuzzer did not run the corpus"; exit 1; fi
if ((shared < kept + 500)); then echo "FAILED: the plugin's own edges did not reach the fuzzer"; exit 1; fi
echo "passed"
