#!/usr/bin/env bash
# The fuzz build leaves every loop in vector lanes out of libFuzzer's
# coverage (fuzz/coverage_ignorelist.txt): a lane loop that is instrumented
# bumps a counter and traces a compare in each step, and clang leaves it out
# of the lanes. Each loop built for the lanes (geometry/vector_lanes.h) has
# an AVX2 clone, named `<function>.avx2.0` by clang; this reads each clone's
# machine code and fails where one touches the coverage counters (the
# __sancov_cntrs section), calls a coverage hook, or calls any function at
# all (a helper the loop calls is run a step at a time). Six lane loops
# written after the list was, and margins_in_lanes's helper, ran
# instrumented or called out, the brute-force SAT's ways_of_row among them.
#
# usage: fuzz_lane_loops_test.sh BINARY...  (the fuzz target, and the
# plugin built from the same instrumented library)
set -euo pipefail

# Fails the test where a clone of `binary` is instrumented or calls out.
check_binary() {
  local binary=$1 counters_start counters_size
  read -r counters_start counters_size < <(readelf -SW "$binary" |
    awk '$2 == "__sancov_cntrs" { print $4, $6 } $3 == "__sancov_cntrs" { print $5, $7 }')
  if [[ -z "${counters_start:-}" ]]; then
    echo "no __sancov_cntrs section in $binary: not a coverage build" >&2
    exit 1
  fi
  local counters_begin=$((16#$counters_start))
  local counters_end=$((counters_begin + 16#$counters_size))

  local clones=0 failures=0 address size name begin end code readable named at callees
  while read -r address size name; do
    clones=$((clones + 1))
    begin=$((16#$address))
    end=$((begin + 16#$size))
    code=$(objdump -d --no-show-raw-insn "$binary" --start-address=$begin --stop-address=$end | tail -n +7)
    readable=$(c++filt <<<"$name")
    # Every address an instruction names in objdump's comment: `# 24e40c <...>`.
    while read -r named; do
      at=$((16#$named))
      if ((at >= counters_begin && at < counters_end)); then
        echo "instrumented lane loop: $readable bumps a coverage counter" >&2
        failures=$((failures + 1))
        break
      fi
    done < <(grep -oE '# [0-9a-f]+ <' <<<"$code" | awk '{ print $2 }')
    callees=$(grep -E $'\tcall' <<<"$code" | grep -oE '<[^>+]+' | tr -d '<' | sort -u | c++filt | paste -sd ';' - || true)
    if [[ -n "$callees" ]]; then
      echo "lane loop $readable calls out: $callees" >&2
      failures=$((failures + 1))
    fi
  done < <(nm -S "$binary" | awk '$4 ~ /\.avx2\.0$/ { print $1, $2, $4 }')

  if ((clones == 0)); then
    echo "no AVX2 lane clones in $binary: the lanes' build changed, and this test reads nothing" >&2
    exit 1
  fi
  if ((failures > 0)); then
    echo "$binary: $failures of $clones lane loops instrumented or calling out (fuzz/coverage_ignorelist.txt)" >&2
    exit 1
  fi
  echo "$binary: $clones lane loops, none instrumented"
}

for binary in "$@"; do
  check_binary "$binary"
done
