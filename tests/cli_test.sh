#!/usr/bin/env bash
# The command line's contract: exit statuses and one-line reasons.
# usage: cli_test.sh MANIFUZZ SOURCE_DIR PLUGIN_DIR [PART]
# PART (statuses, faults, outputs; all three when absent) runs a third of
# the checks, so that ctest runs them side by side: under ASan the whole
# took four minutes on one core while the other stood idle, and the
# statuses alone, with the faulty plugins, still took 194 s.
set -u
manifuzz=$1 source_dir=$2 plugin_dir=$3 part=${4:-all}
in_part() { [ "$part" = all ] || [ "$part" = "$1" ]; }
case $part in all | statuses | faults | outputs) ;; *) echo "cli_test.sh: unknown part '$part'" >&2; exit 2 ;; esac
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

check_that() {  # check_that DESCRIPTION CONDITION...: the condition (a command) must succeed
  local what=$1
  shift
  checks=$((checks + 1))
  if ! "$@"; then
    failures=$((failures + 1))
    printf 'FAILED: %s\n' "$what"
  fi
}

# The mutants are built where the mutation test runs (not in the sanitizer build).
have_mutants=false
[ -f "$plugin_dir/libmfz_mutant_float_precision.so" ] && have_mutants=true

good=$source_dir/corpus/box_on_box.case
sed '5s/.*/v 1 2/' "$good" >"$scratch/short_line.case"
sed 's/^v 0.5 0.5 0.5$/v nan 0.5 0.5/' "$good" >"$scratch/nan.case"
printf 'manifuzz-case 1\nhull A\nv 0 0 0\nv 1 0 0\nv 0 1 0\npose A 0 0 0 1 0 0 0\nhull B\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\npose B 0 0 0 1 0 0 0\n' >"$scratch/three_points.case"
printf 'hello\n' >"$scratch/text.so"

if in_part statuses; then
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
# --jobs: the cases shared out over J streams; the first finding is the run's.
expect 0 'manifuzz check: 2 jobs, 60 cases' -- "$manifuzz" check --cases 60 --jobs 2 --seed 3 --out "$scratch/none"
expect 1 'VIOLATION crash ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_crashing.so" --jobs 2 --cases 200 --seed 3 --out "$scratch/crash" --quiet
expect_one_line_error '--jobs takes a whole number' -- "$manifuzz" check --jobs 0
expect 2 'not a manifuzz generator' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_missing_symbol.so" --cases 5
expect 2 '--cases takes' -- "$manifuzz" check --cases -3
expect 2 '--only takes an invariant or relation name' -- "$manifuzz" check --only on-surfce --cases 5
expect 1 'VIOLATION on-surface ' -- "$manifuzz" check --only on-surface --generator "$plugin_dir/libmanifuzz_tutorial.so" --cases 300 --seed 1 --out "$scratch/only" --quiet
# ---- profiles (docs/profiles.md) ----
expect_one_line_error 'profile: unknown key' -- "$manifuzz" replay --profile stiffness=3 "$good"
expect_one_line_error 'declares a profile the harness cannot read' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_test_bad_profile.so" "$good"
expect 2 'declares a profile the harness cannot read' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_bad_profile.so" --cases 5 --out "$scratch/bp"
if $have_mutants; then
  expect 0 'profile precision=float \(in force' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_mutant_float_precision.so" "$good"
  expect 0 '"profile":"precision=float"' -- "$manifuzz" replay --json --generator "$plugin_dir/libmfz_mutant_float_precision.so" "$good"
  expect 0 'profile max-contacts=4' -- "$manifuzz" check --generator "$plugin_dir/libmfz_mutant_reducing.so" --cases 20 --seed 3 --out "$scratch/none"
  expect 1 'VIOLATION ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_mutant_float_precision.so" --profile precision=double --cases 50 --seed 3 --out "$scratch/fd" --quiet
  # A finding made under a profile records it, and replays under it.
  float_out=$("$manifuzz" check --generator "$plugin_dir/libmfz_mutant_float_side_clip_skipped.so" --cases 300 --seed 3 \
              --out "$scratch/fl" --quiet 2>/dev/null)
  float_file=$(grep -oE '^VIOLATION [a-z-]+ .*' <<<"$float_out" | cut -d' ' -f3-)
  check_that_profile_recorded() { [ -n "$float_file" ] && grep -q '^profile precision=float$' "$float_file"; }
  checks=$((checks + 1))
  check_that_profile_recorded || { failures=$((failures + 1)); printf 'FAILED: a float finding records its profile\n'; }
  expect 1 'profile precision=float' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_mutant_side_clip_skipped.so" "$float_file"
fi

expect_one_line_error 'line 5' -- "$manifuzz" replay "$scratch/short_line.case"
# Two boxes 1e4 across touching face to face, turned: SAT picks a face, the
# clip leaves nothing below it, and the supporting edges give the contact
# (F16). explain says so and shows the clip, not an edge-edge axis (stop 68).
{
  printf 'manifuzz-case 1\nhull A\n'
  printf 'v %s\n' '-5000 -5000 -5000' '-5000 -5000 5000' '-5000 5000 -5000' '-5000 5000 5000' '5000 -5000 -5000' \
    '5000 -5000 5000' '5000 5000 -5000.000000000002' '5000.00001 5000.00001 5000.00001'
  printf 'pose A 13419.364994794078 -4823.464598135858 3089.2698921083243 0.9004471023526769 0.11624942883566838 0.23249885767133677 0.3487482865070052\n'
  printf 'hull B\n'
  printf 'v %s\n' '-4999.999991400951 -4999.999992801637 -4999.999986800003' '-5000 -5000 5000' '-5000 5000 -5000' \
    '-5000 5000 5000' '5000 -5000 -5000.984375' '5000 -5000 5000' '5000 5000 -5000' '5000.00001 5000.00001 5000.00001'
  printf 'pose B 7679.334491527039 2473.7494687093867 6804.470678633839 0.9004471023526769 0.11624942883566838 0.23249885767133677 0.3487482865070052\n'
} >"$scratch/edges_beyond_the_face.case"
expect 0 'Clipping left no point below the reference face' -- "$manifuzz" explain "$scratch/edges_beyond_the_face.case"
expect 0 'Sutherland-Hodgman clipping' -- "$manifuzz" explain "$scratch/edges_beyond_the_face.case"
expect_one_line_error 'fewer than four' -- "$manifuzz" explain "$scratch/three_points.case"
expect_one_line_error 'cannot load generator' -- "$manifuzz" replay --generator "$scratch/text.so" "$good"
fi

if in_part faults; then
# ---- faults that once killed the harness or lost a finding (issue: verdicts that hold) ----
face_case=$good  # a box on a box: a face contact, which the misbehaving plugins act on
vertex_case=$source_dir/corpus/tetrahedron_tip_in_face.case  # one contact: the hanging plugin spins

# gone PID: the process ends (or is a zombie left to a PID 1 that does not reap) within 3 s.
gone() {
  for _ in $(seq 30); do
    [ -r "/proc/$1/stat" ] || return 0
    [ "$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null)" = Z ] && return 0
    sleep 0.1
  done
  return 1
}

# A plugin's own output never reaches the harness's stdout.
out=$("$manifuzz" check --generator "$plugin_dir/libmfz_test_printing.so" --cases 30 --seed 3 --out "$scratch/p" --quiet 2>/dev/null)
check_that "a printing plugin leaves check's stdout empty" test -z "$out"
out=$("$manifuzz" replay --json --generator "$plugin_dir/libmfz_test_printing.so" "$good" 2>/dev/null)
check_that "replay --json prints JSON alone, even for a printing plugin" python3 -c 'import json,sys; json.loads(sys.argv[1])' "$out"
out=$("$manifuzz" replay --json "$good" 2>/dev/null)
check_that "replay --json prints JSON alone" python3 -c 'import json,sys; json.loads(sys.argv[1])' "$out"

# A plugin that crashes, overflows its stack, hangs or exits is a finding in every command.
for cmd in replay explain; do
  expect 1 'crash|gave no answer' -- "$manifuzz" $cmd --generator "$plugin_dir/libmfz_test_crashing.so" "$face_case"
  expect 1 'crash|gave no answer' -- "$manifuzz" $cmd --generator "$plugin_dir/libmfz_test_overflowing.so" "$face_case"
  expect 1 'exit status 0' -- "$manifuzz" $cmd --generator "$plugin_dir/libmfz_test_exiting.so" "$face_case"
  expect 1 'hang|no answer within' -- "$manifuzz" $cmd --call-timeout 0.3 --generator "$plugin_dir/libmfz_test_hanging.so" "$vertex_case"
done
expect 1 'VIOLATION crash ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_exiting.so" --cases 200 --seed 3 --out "$scratch/exit" --quiet

# The worker dies with the harness, SIGKILL included, and takes the plugin's children with it.
"$manifuzz" check --generator "$plugin_dir/libmfz_test_hanging.so" --cases 200 --seed 3 --call-timeout 60 \
  --out "$scratch/kill" --quiet >/dev/null 2>&1 &
harness=$!
sleep 1.5
workers=$(pgrep -P "$harness")
kill -KILL "$harness"; wait "$harness" 2>/dev/null
alive=""
for w in $workers; do gone "$w" || alive="$alive $w"; done
check_that "a SIGKILLed harness leaves no worker behind (workers:$workers; alive:$alive)" test -z "$alive"
MFZ_TEST_CHILD_PID_FILE=$scratch/child.pid "$manifuzz" check --generator "$plugin_dir/libmfz_test_forking.so" \
  --cases 20 --seed 3 --out "$scratch/fork" --quiet >/dev/null 2>&1
child=$(cat "$scratch/child.pid" 2>/dev/null)
check_that "a plugin's child process ends with the run (pid ${child:-none})" test -n "$child"
[ -n "$child" ] && check_that "the plugin's child $child is gone" gone "$child"

# Ctrl-C prints the summary so far.
"$manifuzz" check --cases 1000000 --seed 3 --out "$scratch/int" >"$scratch/int.out" 2>&1 &
harness=$!
sleep 1.5
kill -INT "$harness"; wait "$harness"; status=$?
check_that "Ctrl-C ends check with status 130" test "$status" -eq 130
check_that "Ctrl-C prints the summary so far" grep -q 'interrupted; the summary so far' "$scratch/int.out"
"$manifuzz" check --generator "$plugin_dir/libmfz_test_hanging.so" --call-timeout 60 --cases 1000000 --seed 3 \
  --out "$scratch/term" >"$scratch/term.out" 2>&1 &
harness=$!
sleep 1.5
workers=$(pgrep -P "$harness")
kill -TERM "$harness"; wait "$harness"; status=$?
check_that "SIGTERM during a hanging plugin call ends check with status 130" test "$status" -eq 130
check_that "SIGTERM prints the summary so far" grep -q 'interrupted; the summary so far' "$scratch/term.out"
alive=""
for w in $workers; do gone "$w" || alive="$alive $w"; done
check_that "SIGTERM leaves no worker behind (workers:$workers; alive:$alive)" test -z "$alive"

# Findings are never lost or emptied.
expect 2 'cannot (create|write)' -- "$manifuzz" check --cases 5 --out /proc/manifuzz-cannot-write
expect 2 '--out needs a folder name' -- "$manifuzz" check --cases 5 --out ""
"$manifuzz" check --generator "$plugin_dir/libmfz_test_crashing.so" --cases 200 --seed 3 --out "$scratch/keep" --quiet >/dev/null 2>&1
kept=$(ls "$scratch"/keep/*.case 2>/dev/null | head -1)
before=$(cat "$kept" 2>/dev/null)
expect 2 'cannot write into --out' -- bash -c "ulimit -f 0; exec '$manifuzz' check --generator '$plugin_dir/libmfz_test_crashing.so' --cases 200 --seed 3 --out '$scratch/keep' --quiet"
check_that "a full disk leaves the earlier case as it was" test -n "$before" -a "$before" = "$(cat "$kept")"
check_that "a full disk leaves no empty case file" test -z "$(find "$scratch/keep" -name '*.case' -empty)"

fi

if in_part outputs; then
# --seconds covers shrinking: without it the two shrinking stages may take
# 180 s. The slack covers the case under way at the deadline in the slowest
# build (ASan, a loaded machine: 12 s once).
start=$(date +%s)
"$manifuzz" check --generator "$plugin_dir/libmanifuzz_tutorial.so" --seconds 2 --seed 1 --out "$scratch/sec" --quiet >/dev/null 2>&1
check_that "check --seconds 2 ends within 30 s, shrinking included ($(( $(date +%s) - start )) s)" test $(( $(date +%s) - start )) -le 30

# A relation finding replays as a finding.
if $have_mutants; then
  "$manifuzz" check --generator "$plugin_dir/libmfz_mutant_swapped_pair.so" --cases 300 --seed 3 --out "$scratch/rel" --quiet >/dev/null 2>&1
  relation_case=$(ls "$scratch"/rel/*.case 2>/dev/null | head -1)
  expect 1 'VIOLATION swap-symmetry ' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_mutant_swapped_pair.so" "$relation_case"
  expect 0 'verdict pass' -- "$manifuzz" replay "$relation_case"
fi

# Bad input: one line, status 2.
awk '/^pose B/ {print "pose B  0 0 0.9  1e154 1e154 0 0"; next} {print}' "$good" >"$scratch/huge_quat.case"
awk '/^pose B/ {print "pose B  0 0 0.9  1e-160 1e-160 0 0"; next} {print}' "$good" >"$scratch/tiny_quat.case"
awk '/^pose B/ {print "pose B  0 0 0.9  1 1 0 0"; next} {print}' "$good" >"$scratch/plain_quat.case"
plain=$("$manifuzz" replay --json "$scratch/plain_quat.case" | sed 's/"file":"[^"]*"//')
check_that "a quaternion near 1e154 is the same rotation" test "$plain" = "$("$manifuzz" replay --json "$scratch/huge_quat.case" | sed 's/"file":"[^"]*"//')"
check_that "a quaternion near 1e-160 is the same rotation" test "$plain" = "$("$manifuzz" replay --json "$scratch/tiny_quat.case" | sed 's/"file":"[^"]*"//')"
awk '/^pose B/ {print "pose B  1e16 0 0.9  1 0 0 0"; next} /^pose A/ {print "pose A  1e16 0 0  1 0 0 0"; next} {print}' "$good" >"$scratch/far.case"
expect_one_line_error 'from the origin' -- "$manifuzz" replay "$scratch/far.case"
# A hull the world frame cannot resolve: 5e-4 across beside a hull of 8e25
# (manifuzz fuzz on the built-in found it 1e56 out beside one of 8e70,
# which the coordinate limit now refuses first).
{ echo "manifuzz-case 1"; echo "hull A"; echo "v 0 0 0"; echo "v 8e25 8e25 0"; echo "v 0 0 8e25"; echo "v 0 8e25 0"
  echo "pose A  0 0 0  1 0 0 0"; echo "hull B"; echo "v -5e-4 0 0"; echo "v -5e-4 0 -5e-4"; echo "v -5e-4 5e-4 0"; echo "v 0 0 0"
  echo "pose B  0 3e10 1e11  -0.5 0.5 -0.5 0.5"; } >"$scratch/unresolved.case"
expect_one_line_error 'hull B .* not resolved' -- "$manifuzz" replay "$scratch/unresolved.case"
# Past the coordinate limit (O20: a tetrahedron 3e78 long answered with the
# normal (0, 0, 0)), in a hull and in a position.
{ echo "manifuzz-case 1"; echo "hull A"; echo "v 2e72 0 0"; echo "v 0 0 0"; echo "v 0 0 3e78"; echo "v 0 1e70 0"
  echo "pose A  0 0 0  1 0 0 0"; echo "hull B"; echo "v 2e72 0 0"; echo "v 0 0 0"; echo "v 0 0 3e78"; echo "v 0 1e70 0"
  echo "pose B  0 0 0  1 0 -0.1 0"; } >"$scratch/huge.case"
expect_one_line_error 'hull A: .*coordinate of 3e\+78 is past the limit of 1e\+30' -- "$manifuzz" replay "$scratch/huge.case"
# Below the diameter limit (h25: hulls 1e-107 across, whose edges' cross
# products underflow, lost the exact oracle its edge axes).
{ echo "manifuzz-case 1"; echo "hull A"; echo "v 0 0 0"; echo "v 2e-107 0 0"; echo "v 0 2e-107 0"; echo "v 0 0 2e-107"
  echo "pose A  0 0 0  1 0 0 0"; echo "hull B"; echo "v 0 0 0"; echo "v 2e-107 0 0"; echo "v 0 2e-107 0"; echo "v 0 0 2e-107"
  echo "pose B  0 0 0  1 0 -0.1 0"; } >"$scratch/minute.case"
expect_one_line_error 'hull A has a diameter of 2.83e-107, below the limit of 1e-30' -- "$manifuzz" replay "$scratch/minute.case"
awk '/^pose B/ {print "pose B  0 2e30 0.9  1 0 0 0"; next} {print}' "$good" >"$scratch/far_position.case"
expect_one_line_error 'position has a coordinate of 2e\+30, past the limit' -- "$manifuzz" replay "$scratch/far_position.case"
{ echo "manifuzz-case 1"; echo "hull A"; for i in $(seq 1 1100); do echo "v $i $((i * i % 97)) $((i % 13))"; done
  echo "pose A 0 0 0 1 0 0 0"; echo "hull B"; echo "v 0 0 0"; echo "v 1 0 0"; echo "v 0 1 0"; echo "v 0 0 1"; echo "pose B 0 0 0 1 0 0 0"; } >"$scratch/many.case"
expect_one_line_error 'more than 1024 points' -- "$manifuzz" replay "$scratch/many.case"
expect_one_line_error 'larger than' -- timeout 10 "$manifuzz" replay /dev/zero
printf 'manifuzz-case 1\nhull A\nv 0 0 0\nv 1\0009 0 0\n' >"$scratch/nul.case"
expect_one_line_error 'line 4:.*not a number' -- "$manifuzz" replay "$scratch/nul.case"
printf 'manifuzz-case 1\n\033[31mred\n' >"$scratch/escape.case"
err=$("$manifuzz" replay "$scratch/escape.case" 2>&1 >/dev/null)
check_that "control bytes of the input are escaped in messages" sh -c "printf '%s' '$err' | grep -q 'x1b' && ! printf '%s' '$err' | grep -q \"\$(printf '\\033')\""
expect_one_line_error 'call-timeout takes' -- "$manifuzz" check --call-timeout 0.0005 --cases 5
manifuzz_path=$(cd "$(dirname "$manifuzz")" && pwd)/$(basename "$manifuzz")
expect 0 'verdict pass' -- sh -c "cd '$plugin_dir' && '$manifuzz_path' replay --generator libmanifuzz_clipping.so '$good'"

# Generators by name (the tutorial always; the peers where their libraries were found).
expect 1 'VIOLATION ' -- "$manifuzz" replay --generator tutorial "$source_dir/corpus/regressions/f1-frustum-side-planes-slope-inwards.case"
expect_one_line_error "unknown generator 'bulet'" -- "$manifuzz" replay --generator bulet "$good"
expect_one_line_error "unknown family 'spheres'" -- "$manifuzz" check --family spheres --cases 5
expect 0 'families cube box slab needle anisotropic-box' -- "$manifuzz" check --family boxes --cases 20 --seed 3 --out "$scratch/none"
# A family drawn only where named: faces of 65 to 520 corners (F61).
expect 0 'families wide-face cube tetrahedron' -- "$manifuzz" check --strict --family wide-face,cube,tetrahedron --cases 6 --seed 5 --out "$scratch/none"
if [ -f "$plugin_dir/libmanifuzz_peer_ode_box.so" ]; then
  expect 0 'manifuzz check: 100 cases' -- "$manifuzz" check --generator ode-box --family boxes --only finite --cases 100 --seed 3 --out "$scratch/none"
  expect 1 'VIOLATION refused ' -- "$manifuzz" replay --generator ode-box "$source_dir/corpus/tetrahedron_tip_in_face.case"
fi

# --confirm-with: a float variant's rounding (flagged under a double
# profile) is passed over when the same logic in double does not make it;
# a broken float variant's finding, which the broken double one makes too, stops the run.
if $have_mutants; then
  expect 0 '[1-9][0-9]* findings of rounding only passed over' -- "$manifuzz" check --generator "$plugin_dir/libmfz_mutant_float_precision.so" \
    --profile precision=double --confirm-with builtin --cases 400 --seed 3 --out "$scratch/confirm" --only on-surface
  expect 1 'VIOLATION ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_mutant_float_side_clip_skipped.so" \
    --confirm-with "$plugin_dir/libmfz_mutant_side_clip_skipped.so" --cases 2000 --seed 3 --out "$scratch/confirm" --quiet
fi

# diff: a generator against itself agrees; against the tutorial, disagreements
# with their minimised cases; case files compared one by one.
expect 0 '100 agree; 0 differ where the oracles confirm both' -- "$manifuzz" diff --generator builtin --against "$plugin_dir/libmanifuzz_clipping.so" --cases 100 --seed 3 --out "$scratch/diff" --quiet
expect 1 'disagreement +cases +oracles side with: +first +second' -- "$manifuzz" diff --generator builtin --against tutorial --cases 300 --seed 3 --out "$scratch/diff" --quiet
expect 0 'agree .*box_on_box.case' -- "$manifuzz" diff --generator builtin --against tutorial "$good"
expect_one_line_error 'give both --generator and --against' -- "$manifuzz" diff --generator builtin --cases 5
tutorial_case=$(ls "$scratch"/diff/diff-*.case | head -1)
expect 1 'DISAGREE ' -- "$manifuzz" diff --generator builtin --against tutorial "$tutorial_case"

# --junit: XML a CI system reads, the finding as a failure; an unwritable
# file is refused before the run.
expect 1 'VIOLATION finite ' -- "$manifuzz" replay --generator "$plugin_dir/libmfz_test_forgetful.so" --junit "$scratch/junit/replay.xml" "$good"
check_that "replay --junit writes a failure for the finding" grep -q '<failure message="finite' "$scratch/junit/replay.xml"
expect 1 'VIOLATION crash ' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_crashing.so" --cases 200 --seed 3 --out "$scratch/crash" --quiet --junit "$scratch/junit/check.xml"
check_that "check --junit has a test case per check and the crash as a failure" sh -c "grep -c '<testcase' '$scratch/junit/check.xml' | grep -qx 23 && grep -q 'name=\"crash\"' '$scratch/junit/check.xml'"
expect 1 'disagreement' -- "$manifuzz" diff --generator builtin --against tutorial --cases 300 --seed 3 --out "$scratch/diff" --quiet --junit "$scratch/junit/diff.xml"
check_that "diff --junit names each kind" sh -c "grep -q 'name=\"contact-region\"' '$scratch/junit/diff.xml' && grep -q '<failure' '$scratch/junit/diff.xml'"
expect_one_line_error 'cannot write --junit file' -- "$manifuzz" check --cases 5 --junit /proc/version/x.xml

# render: a picture of one case; a failing case is drawn and exits 1 (a
# crashing plugin too); bad input is a one-line error and status 2.
expect 0 '' -- "$manifuzz" render "$good" -o "$scratch/render/box.svg"
expect 0 '' -- "$manifuzz" render "$good" -o "$scratch/render/box_again.svg"
check_that "render gives the same bytes twice" cmp -s "$scratch/render/box.svg" "$scratch/render/box_again.svg"
expect 0 '' -- "$manifuzz" render "$good" --output "$scratch/render/box.html"
check_that "render -o .html writes a page with its picture" grep -q '<svg' "$scratch/render/box.html"
expect 1 '' -- "$manifuzz" render --generator tutorial "$source_dir/corpus/regressions/f1-frustum-side-planes-slope-inwards.case" -o "$scratch/render/f1.svg"
check_that "render circles the failing contact" grep -q 'on-surface (contact 1)' "$scratch/render/f1.svg"
expect 1 '' -- "$manifuzz" render --generator "$plugin_dir/libmfz_test_crashing.so" "$good" -o "$scratch/render/crash.svg"
check_that "render draws the crashing plugin's case and names the crash" grep -q 'no answer: crash' "$scratch/render/crash.svg"
expect_one_line_error 'no output file' -- "$manifuzz" render "$good"
expect_one_line_error 'must end in .svg or .html' -- "$manifuzz" render "$good" -o "$scratch/render/box.png"
expect_one_line_error 'line 5: expected 3 numbers' -- "$manifuzz" render "$scratch/short_line.case" -o "$scratch/render/x.svg"
expect_one_line_error 'not finite' -- "$manifuzz" render "$scratch/nan.case" -o "$scratch/render/x.svg"
expect_one_line_error 'fewer than four points' -- "$manifuzz" render "$scratch/three_points.case" -o "$scratch/render/x.svg"
expect_one_line_error 'cannot load generator' -- "$manifuzz" render --generator "$scratch/text.so" "$good" -o "$scratch/render/x.svg"
expect_one_line_error 'cannot write' -- "$manifuzz" render "$good" -o /proc/version/x.svg
# --render DIR beside explain's and replay's text.
expect 0 'Verdict: every invariant holds' -- "$manifuzz" explain --render "$scratch/explained" "$good"
check_that "explain --render writes the SVG and the page" test -s "$scratch/explained/box_on_box.svg" -a -s "$scratch/explained/box_on_box.html"
expect 1 'VIOLATION on-surface' -- "$manifuzz" replay --generator tutorial --render "$scratch/replayed" "$good" "$source_dir/corpus/regressions/f1-frustum-side-planes-slope-inwards.case"
check_that "replay --render draws every case" test -s "$scratch/replayed/box_on_box.svg" -a -s "$scratch/replayed/f1-frustum-side-planes-slope-inwards.svg"
# --report DIR: the run's report; tried before the run.
expect 0 'report in' -- "$manifuzz" check --cases 60 --jobs 2 --seed 3 --out "$scratch/none" --report "$scratch/report-jobs" --quiet
check_that "check --jobs --report counts every job's cases" grep -q '<th>cases</th><td>60</td>' "$scratch/report-jobs/report.html"
check_that "check --jobs --report merges every job's margins" grep -q '<td>finite</td><td>60</td>' "$scratch/report-jobs/report.html"
expect 1 'report in' -- "$manifuzz" check --generator "$plugin_dir/libmfz_test_crashing.so" --cases 50 --seed 3 --out "$scratch/crash" --quiet --report "$scratch/report-crash"
check_that "check --report shows the finding with its replay command" sh -c "grep -q 'manifuzz replay --generator $plugin_dir/libmfz_test_crashing.so' '$scratch/report-crash/report.html'"
expect_one_line_error 'cannot write the report' -- "$manifuzz" check --cases 5 --report /proc/version/r
expect 1 'report in' -- "$manifuzz" diff --generator builtin --against tutorial --cases 100 --seed 3 --out "$scratch/diff-report-cases" --quiet --report "$scratch/report-diff"
check_that "diff --report counts contact kinds and both answers' margins" sh -c "grep -q '<h3>contact kind</h3>' '$scratch/report-diff/report.html' && grep -q '<td>first: depth-exact</td>' '$scratch/report-diff/report.html' && grep -q '<td>second: depth-exact</td>' '$scratch/report-diff/report.html'"

fi

echo "$((checks - failures)) passed, $failures failed"
[ "$failures" -eq 0 ] && [ "$checks" -gt 0 ]
