#!/usr/bin/env bash
# `manifuzz fuzz` and `manifuzz promote` as a user runs them (the clang
# build, where manifold_fuzzer sits beside manifuzz): a broken generator is
# found, minimised, promoted into a regression case that fails against it and
# passes against the built-in and in the regression test; a campaign resumes
# from its corpus, and one killed with SIGKILL leaves a corpus of whole inputs
# that the next campaign starts from; bad input is a one-line error; the
# run's report holds its coverage over time and its findings' pictures.
# usage: fuzz_cli_test.sh MANIFUZZ PLUGIN_DIR UNIT_TESTS
set -u
manifuzz=$1 plugins=$2 unit_tests=$3
scratch=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$scratch"' EXIT
failures=0 checks=0
fail() { failures=$((failures + 1)); printf 'FAILED: %s\n' "$*"; }
check() { checks=$((checks + 1)); "$@" || fail "$*"; }

# 1. A broken generator (normals the wrong way) is found and minimised.
out=$("$manifuzz" fuzz --generator "$plugins/libmfz_mutant_normal_sign.so" --seconds 12 --jobs 2 \
        --corpus "$scratch/corpus-sign" --out "$scratch/found" --minimise-seconds 3 --report "$scratch/fuzz-report" \
        2>"$scratch/fuzz.log")
status=$?
check test "$status" -eq 1
finding=$(sed -n 's/^VIOLATION [^ ]* //p' <<<"$out" | head -1)
check test -f "$finding"
check grep -q "^note found by: manifuzz fuzz --generator" "$finding"
check grep -q "distinct finding" "$scratch/fuzz.log"
"$manifuzz" replay --generator "$plugins/libmfz_mutant_normal_sign.so" "$finding" >/dev/null 2>&1
check test $? -eq 1
# --report: coverage over time, the corpus's statistics, each finding with
# its picture and the command that replays it.
report=$scratch/fuzz-report/report.html
check grep -q "Coverage over time" "$report"
check grep -q "corpus inputs replayed after the run" "$report"
check grep -q "manifuzz replay --generator $plugins/libmfz_mutant_normal_sign.so" "$report"
check grep -q 'class="case-data"' "$report"

# 2. Promoted in one command: fails against the broken generator, passes
# against the built-in and in the regression test, with no other edit.
"$manifuzz" promote "$finding" --dir "$scratch/regressions" --name wrong-sign --seconds 5 >"$scratch/promote.log" 2>&1
check test $? -eq 0
promoted=$scratch/regressions/wrong-sign.case
check grep -q "^expect pass" "$promoted"
check grep -q "^note check: " "$promoted"
check grep -q "^expect-tutorial " "$promoted"
"$manifuzz" replay --generator "$plugins/libmfz_mutant_normal_sign.so" "$promoted" >/dev/null 2>&1
check test $? -eq 1
"$manifuzz" replay "$promoted" >/dev/null 2>&1
check test $? -eq 0
MANIFUZZ_REGRESSIONS_DIR=$scratch/regressions "$unit_tests" --gtest_filter='Corpus/RegressionCase.*' >/dev/null 2>&1
check test $? -eq 0
# A raw artefact promotes too; a passing case has nothing to promote.
raw=$(ls "$scratch"/found/*.input | head -1)
"$manifuzz" promote "$raw" --generator "$plugins/libmfz_mutant_normal_sign.so" --dir "$scratch/regressions" \
  --name from-raw --seconds 2 >/dev/null 2>&1
check test -f "$scratch/regressions/from-raw.case"
"$manifuzz" promote "$promoted" --generator builtin --dir "$scratch/regressions" --name again 2>"$scratch/err"
check test $? -eq 2
check grep -q "nothing to promote" "$scratch/err"

# 3. A campaign grows its corpus, here on hulls of at most 8 points
# (--max-points: libFuzzer's -max_len); the next one resumes from it. Its
# status is not asked: on small hulls the built-in has open findings
# (corpus/open/). Step 1 ran small in stop 68, and in one of four CI runs a
# check of steps 1-2 got status 1 where it wanted 0; a case shrunk from the
# broken generator's finding may land where the built-in has one of them,
# so steps 1 and 2 keep the full size.
"$manifuzz" fuzz --seconds 6 --max-points 8 --corpus "$scratch/corpus" --out "$scratch/out" >/dev/null \
  2>"$scratch/first.log"
check grep -q "hulls of at most 8 points" "$scratch/first.log"
grown=$(ls "$scratch/corpus" | wc -l)
check test "$grown" -gt 17
"$manifuzz" fuzz --seconds 3 --corpus "$scratch/corpus" --out "$scratch/out" >/dev/null 2>"$scratch/second.log"
check grep -q "resuming from $grown inputs" "$scratch/second.log"
# A campaign that grows its hulls (--max-points A..B): phases on the one
# corpus at 5 points, then 10, then 16, each a share of --seconds.
"$manifuzz" fuzz --seconds 9 --max-points 5..16 --corpus "$scratch/corpus-grown" --out "$scratch/out" >/dev/null \
  2>"$scratch/grown.log"
check grep -q "hulls of at most 5 points, growing to 16 in 3 phases" "$scratch/grown.log"
check grep -q "phase 2 of 3: hulls of at most 10 points" "$scratch/grown.log"
check grep -q "phase 3 of 3: hulls of at most 16 points" "$scratch/grown.log"
check grep -q "^manifuzz fuzz: [0-9]* execs in" "$scratch/grown.log"

# 4. Killed with SIGKILL midway: every input in the corpus is whole (named
# by its SHA-1, or a seed), and the next campaign starts from it.
"$manifuzz" fuzz --seconds 60 --jobs 2 --corpus "$scratch/corpus" --out "$scratch/out" >/dev/null 2>&1 &
victim=$!
sleep 6
kill -9 "$victim"
wait "$victim" 2>/dev/null
sleep 1
for input in "$scratch"/corpus/*; do
  name=$(basename "$input")
  [[ $name =~ ^[0-9a-f]{40}$ ]] || continue
  [ "$(sha1sum <"$input" | cut -c1-40)" = "$name" ] || fail "corpus input $name is not whole after SIGKILL"
done
"$manifuzz" fuzz --seconds 3 --corpus "$scratch/corpus" --out "$scratch/out" >/dev/null 2>"$scratch/third.log"
status=$?
check test "$status" -le 1
check grep -q "resuming from" "$scratch/third.log"
# The engine's scratch folder of the killed run is gone too.
check test ! -e "/dev/shm/manifuzz-fuzz-$victim"

# 5. Ctrl-C: a clean stop, the summary so far, status 130, no fuzzer and
# no scratch files left.
# A finding made before the interrupt takes status 1, as in any run: the
# built-in may have findings not yet found or fixed (corpus/open/), and once
# in several CI runs these five seconds found one (stop 42, when O12 was
# open). Then the log must name it.
# libFuzzer's scratch files leave nothing in TMPDIR (they went to the
# campaign's own folder, removed at the end; libFuzzer left its folder
# in TMPDIR when stopped).
mkdir "$scratch/tmp-int"
TMPDIR="$scratch/tmp-int" "$manifuzz" fuzz --seconds 60 --corpus "$scratch/corpus-int" --out "$scratch/out-int" \
  >/dev/null 2>"$scratch/int.log" &
fuzzing=$!
sleep 5
kill -INT "$fuzzing"
wait "$fuzzing"
status=$?
check test "$status" -eq 130 -o \( "$status" -eq 1 -a -n "$(grep '^found ' "$scratch/int.log")" \)
check grep -q "interrupted; the summary so far" "$scratch/int.log"
sleep 1
check test -z "$(pgrep -f "corpus-int" || true)"
check test -z "$(ls -A "$scratch/tmp-int")"
check test ! -e "/dev/shm/manifuzz-fuzz-$fuzzing"
check test -z "$(ls -A "$scratch/out-int" | grep '^\.fuzz-' || true)"

# 6. Bad input: one line, exit 2.
for args in "--jobs 0" "--seconds 0" "--seconds x" "--corpus ''" "--frobnicate" "--max-points 3" "--max-points 65" \
  "--max-points 8..5" "--max-points 5..65" "--max-points 5.. --seconds 5" "--max-points 5..16"; do
  eval "\"$manifuzz\" fuzz $args" >/dev/null 2>"$scratch/err"
  status=$?
  check test "$status" -eq 2
  check test "$(wc -l <"$scratch/err")" -eq 1
done
"$manifuzz" fuzz --generator "$plugins/libmfz_test_missing_symbol.so" --seconds 2 --out "$scratch/out" 2>"$scratch/err" >/dev/null
check test $? -eq 2
MANIFUZZ_FUZZER=/nonexistent "$manifuzz" fuzz --seconds 2 --corpus "$scratch/c2" --out "$scratch/out" >/dev/null 2>"$scratch/err"
check test $? -eq 2
check grep -q "stopped before fuzzing" "$scratch/err"
printf 'not a case\n' >"$scratch/junk"
"$manifuzz" promote "$scratch/junk" 2>"$scratch/err"
check test $? -eq 2
check grep -q "neither a case file nor a fuzz input" "$scratch/err"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
