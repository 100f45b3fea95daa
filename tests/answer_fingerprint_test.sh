#!/usr/bin/env bash
# answer_fingerprint's verdicts and exit statuses: the same bytes (the
# built-in in process against its own plugin) exit 0; another generator's
# answers (OTHER, a plugin in PLUGINS_DIR: a broken mutant, or the
# tutorial's unfixed method) exit 1, name the first pair that differs and,
# given a folder, write the first 100 as cases; a missing file, a library
# that is no generator, or no argument exit 2 with a one-line error.
#
#   answer_fingerprint_test.sh FINGERPRINT PLUGINS_DIR OTHER
set -uo pipefail
fingerprint=$1 plugins=$2 other=$3
failures=0
expect() {  # expect STATUS PATTERN -- ARGS...
  local status=$1 pattern=$2
  shift 3
  local out
  out=$("$fingerprint" "$@" 2>&1)
  local got=$?
  if [ "$got" -ne "$status" ] || ! grep -qE "$pattern" <<<"$out"; then
    echo "FAIL: answer_fingerprint $* exited $got (want $status), output lacks /$pattern/:"
    tail -3 <<<"$out"
    failures=$((failures + 1))
  fi
}
expect 0 '^0 of 18432 calls differ$' -- builtin "$plugins/libmanifuzz_clipping.so"
# Another generator differs; with a folder, the first 100 differing calls
# are written there as case files.
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
expect 1 '^first difference: .*pair [0-9]+' -- "$plugins/libmanifuzz_clipping.so" "$plugins/$other" "$folder"
written=$(find "$folder" -name '*.case' | wc -l)
if [ "$written" -ne 100 ] || ! head -1 "$(find "$folder" -name '*.case' | head -1)" | grep -q '^manifuzz-case 1$'; then
  echo "FAIL: the folder holds $written case files (want 100, each a manifuzz case)"
  failures=$((failures + 1))
fi
expect 2 'cannot load generator' -- "$plugins/no-such-generator.so"
expect 2 'is not a manifuzz generator' -- "$plugins/libmfz_test_missing_symbol.so"
expect 2 '^usage: answer_fingerprint' --
[ "$failures" -eq 0 ] && echo "answer_fingerprint: all verdicts and statuses as expected"
exit $((failures > 0))
