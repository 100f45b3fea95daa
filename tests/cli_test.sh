#!/usr/bin/env bash
# The command line's contract: exit statuses and one-line reasons.
# usage: cli_test.sh MANIFUZZ SOURCE_DIR PLUGIN_DIR
set -u
manifuzz=$1 source_dir=$2 plugin_dir=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0 checks=0

# expect STATUS PATTERN -- command...: the status, and PATTERN in stdout+stderr.
expect() {
  local want=$1 pattern=$2
  shift 3
  local out status
  out=$("$@" 2>&1)
  status=$?
  checks=$((checks + 1))
  if [ "$status" -ne "$want" ] || ! grep -qE -- "$pattern" <<<"$out"; then
    failures=$((failures + 1))
    printf 'FAILED: %s\n  wanted status %s and /%s/, got %s:\n%s\n' "$*" "$want" "$pattern" "$status" "$out"
  fi
}

# A one-line reason: exactly one line on stderr, nothing on stdout.
expect_one_line_error() {
  local pattern=$1
  shift 2
  local err lines
  err=$("$@" 2>&1 >/dev/null)
  lines=$(printf '%s\n' "$err" | wc -l)
  checks=$((checks + 1))
  if [ "$lines" -ne 1 ] || ! grep -qE -- "$pattern" <<<"$err"; then
    failures=$((failures + 1))
    printf 'FAILED: %s\n  wanted one line matching /%s/, got:\n%s\n' "$*" "$pattern" "$err"
  fi
}

good=$source_dir/corpus/box_on_box.case
sed '5s/.*/v 1 2/' "$good" >"$scratch/short_line.case"
sed 's/^v 0.5 0.5 0.5$/v nan 0.5 0.5/' "$good" >"$scratch/nan.case"
printf 'manifuzz-case 1\nhull A\nv 0 0 0\nv 1 0 0\nv 0 1 0\npose A 0 0 0 1 0 0 0\nhull B\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\npose B 0 0 0 1 0 0 0\n' >"$scratch/three_points.case"
printf 'hello\n' >"$scratch/text.so"

expect 0 'verdict pass' -- "$manifuzz" replay "$good"
expect 0 '"verdict":"pass"' -- "$manifuzz" replay --json "$good"
expect 0 'Verdict: every invariant holds' -- "$manifuzz" explain "$good"
expect 2 'line 5: expected 3 numbers' -- "$manifuzz" replay "$scratch/short_line.case"
expect 2 'not finite' -- "$manifuzz" replay "$scratch/nan.case"
expect 2 'hull A: fewer than four points' -- "$manifuzz" replay "$scratch/three_points.case"
expect 2 'cannot load generator' -- "$manifuzz" replay --generator "$scratch/text.so" "$good"
expect 2 'cannot open' -- "$manifuzz" replay "$scratch/missing.case"
expect 2 'unknown option' -- "$manifuzz" replay --bogus "$good"
expect 2 'unknown command' -- "$manifuzz" frobnicate
expect 2 'usage' -- "$manifuzz"
expect 1 'VIOLATION finite ' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_test_forgetful.so" "$good"
expect 0 'verdict pass' -- "$manifuzz" replay --generator "$plugin_dir/libmanifuzz_clipping.so" "$good"
expect 1 'VIOLATION crash ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_crashing.so" --cases 200 --seed 3 --out "$scratch/crash" --quiet
expect 1 'VIOLATION hang ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_hanging.so" --cases 200 --seed 3 --out "$scratch/hang" --call-timeout 0.2 --quiet
expect 0 'manifuzz check: 50 cases' -- "$manifuzz" check --cases 50 --seed 3 --out "$scratch/none"
expect 2 'not a manifuzz generator' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_missing_symbol.so" --cases 5
expect 2 '--cases takes' -- "$manifuzz" check --cases -3
expect 2 '--only takes an invariant or relation name' -- "$manifuzz" check --only on-surfce --cases 5
expect 1 'VIOLATION on-surface ' -- "$manifuzz" check --only on-surface --generator "$plugin_dir/libmanifuzz_tutorial.so" --cases 300 --seed 1 --out "$scratch/only" --quiet
expect_one_line_error 'line 5' -- "$manifuzz" replay "$scratch/short_line.case"
expect_one_line_error 'fewer than four' -- "$manifuzz" explain "$scratch/three_points.case"
expect_one_line_error 'cannot load generator' -- "$manifuzz" replay --generator "$scratch/text.so" "$good"

echo "$((checks - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
