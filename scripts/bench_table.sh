#!/usr/bin/env bash
# The speed table: every generator at hand (the built-in, Bullet's two paths,
# ODE's collider and dBoxBox, libccd's EPA and MPR), family by family, in one
# run of bench/generator_bench on one pinned core, built at -O3 (the `bench`
# preset, build/bench); then the harness's own throughput (property cases
# and fuzz executions per second, bench/property_bench and
# bench/fuzz_target_bench) and a case's time stage by stage. Google
# Benchmark's reports go to OUT/; the tables, with the machine they ran on,
# to stdout. Time it on a quiet machine.
#
#   scripts/bench_table.sh [OUT]   (default: bench-results)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-bench-results}
mkdir -p "$out"
cmake --preset bench >/dev/null
cmake --build --preset bench --target generator_bench property_bench fuzz_target_bench >/dev/null
core=$(( $(nproc) - 1 ))
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; pinned to core $core; $(date -u +%Y-%m-%d); $(g++ --version | head -1)"
taskset -c "$core" build/bench/bench/generator_bench 2> "$out/generator_bench.log" | tee "$out/generator_bench.txt" | sed -n '/^| median/,$p'
echo
taskset -c "$core" build/bench/bench/property_bench --benchmark_min_time=2 > "$out/property_bench.txt" 2>&1
taskset -c "$core" build/bench/bench/fuzz_target_bench --benchmark_min_time=2 > "$out/fuzz_target_bench.txt" 2>&1
echo "| harness on one core | per second |"
echo "|---|---|"
grep -v '^BM_CaseStage' "$out/property_bench.txt" | cat - "$out/fuzz_target_bench.txt" |
  sed -n 's/^\(BM_[^ ]*\) .*items_per_second=\([0-9.]*[kM]*\)\/s.*/| \1 | \2 |/p'
echo
# A case's stages, microseconds each: BM_CaseStage/<stage>/<points>.
echo "| a case's stage (us) | 8-point hulls | 32-point hulls |"
echo "|---|---|---|"
awk '/^BM_CaseStage\// { split($1, name, "/"); us[name[2], name[3]] = $2; if (!(name[2] in seen)) { seen[name[2]] = 1; order[++n] = name[2] } }
     END { for (i = 1; i <= n; ++i) printf "| %s | %s | %s |\n", order[i], us[order[i], "8"], us[order[i], "32"] }' \
  "$out/property_bench.txt"
