#!/usr/bin/env bash
# Two builds of a generator timed against each other: both plugins in one
# run of bench/generator_bench on one pinned core, the order swapped from
# run to run, ROUNDS times each way; per family, the new build's time over
# the base's in every run and the median of those ratios. On a shared
# machine one run's ratio moves a lot: a build against a copy of itself
# gave single runs from 0.84 to 1.12 and medians of six from 0.991 to 1.007
# (stop 39, three rounds), so a change smaller than the spread of its
# ratios is not measured here.
#
#   scripts/bench_ab.sh BASE.so NEW.so [ROUNDS] [FAMILIES]
#
# ROUNDS: 1 to 20 (default 3; each is two runs). FAMILIES: a regular
# expression for the start of the family names (default every family), e.g.
# 'boxes|8-point'.
# To see the machine's noise, time a build against a copy of itself: the
# same file twice is one library, loaded once.
set -euo pipefail
usage() {
  echo "usage: scripts/bench_ab.sh BASE.so NEW.so [ROUNDS 1-20] [FAMILIES regex]" >&2
  exit 2
}
[ $# -ge 2 ] && [ $# -le 4 ] || usage
base=$(realpath -e -- "$1" 2>/dev/null) || { echo "bench_ab: no such plugin: $1" >&2; exit 2; }
new=$(realpath -e -- "$2" 2>/dev/null) || { echo "bench_ab: no such plugin: $2" >&2; exit 2; }
rounds=${3:-3}
if ! [[ "$rounds" =~ ^[0-9]+$ ]] || (( rounds < 1 || rounds > 20 )); then
  echo "bench_ab: ROUNDS is a count from 1 to 20, not '$rounds'" >&2
  exit 2
fi
families=${4:-.*}
cd "$(dirname "$0")/.."
cmake --preset bench >/dev/null
cmake --build --preset bench --target generator_bench >/dev/null
core=$(( $(nproc) - 1 ))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One run: "family generator ns" per line for the two plugins, from Google
# Benchmark's CSV (names have no commas; the median of the three repeats).
run_once() {
  MANIFUZZ_BENCH_PLUGINS="$1" taskset -c "$core" build/bench/bench/generator_bench \
    --benchmark_filter="^($families)[^/]*/(base|new)/" --benchmark_out="$work/run.csv" \
    --benchmark_out_format=csv >/dev/null 2>"$work/run.log"
  awk -F, '$1 ~ /_median"$/ { name = $1; gsub(/"/, "", name); sub(/\/min_time.*/, "", name);
                               n = split(name, part, "/"); print part[1] "\t" part[2] "\t" $4 }' "$work/run.csv"
}

echo "base: $base"
echo "new:  $new"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), pinned to core $core; $(date -u +%Y-%m-%d)"
for ((r = 1; r <= rounds; ++r)); do
  for order in "base=$base;new=$new" "new=$new;base=$base"; do
    run_once "$order" > "$work/one.tsv"
    for who in base new; do
      if ! cut -f2 "$work/one.tsv" | grep -qx "$who"; then
        echo "bench_ab: the $who plugin gave no times: $(grep -m1 "generator_bench: $who" "$work/run.log" || echo "no family matches '$families'")" >&2
        exit 2
      fi
    done
    cat "$work/one.tsv" >> "$work/all.tsv"
    echo "--" >> "$work/all.tsv"
  done
done

# Per run, new over base per family; then each family's ratios and median.
awk -F'\t' '
  $0 == "--" { for (f in t_new) if (f in t_base) ratio[f, ++count[f]] = t_new[f] / t_base[f]
               delete t_new; delete t_base; next }
  !($1 in seen) { seen[$1] = 1; order[++families] = $1 }
  $2 == "new" { t_new[$1] = $3 } $2 == "base" { t_base[$1] = $3 }
  END {
    print "| family | new / base, each run | median |"
    print "|---|---|---|"
    for (i = 1; i <= families; ++i) {
      f = order[i]; n = count[f]; line = ""
      for (k = 1; k <= n; ++k) { v[k] = ratio[f, k]; line = line sprintf("%s%.3f", k > 1 ? " " : "", v[k]) }
      for (a = 1; a <= n; ++a) for (b = a + 1; b <= n; ++b) if (v[b] < v[a]) { x = v[a]; v[a] = v[b]; v[b] = x }
      median = n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
      printf "| %s | %s | %.3f |\n", f, line, median
    }
  }' "$work/all.tsv"
