#!/usr/bin/env bash
# Runs `manifuzz check` on every deliberately broken generator (each must be
# caught within a bounded number of cases) and on the correct ones (which must
# pass), then prints the mutation score and the median cases to detection.
# usage: mutation_test.sh MANIFUZZ PLUGIN_DIR "MUTANT..."
set -u
manifuzz=$1 plugins=$2 mutants=${3//;/ }
seed=${MUTATION_SEED:-20261121}
budget=${MUTATION_CASES:-3000}
correct_budget=${CORRECT_CASES:-1000}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
caught=0 total=0 failures=0 detections=()
for m in $mutants; do
  total=$((total + 1))
  out=$("$manifuzz" check --generator "$plugins/libmfz_mutant_$m.so" --cases "$budget" --seed "$seed" \
        --out "$scratch/$m" --quiet 2>&1)
  status=$?
  at=$(grep -oE 'found [a-z-]+ at case [0-9]+' <<<"$out" | head -1)
  if [ "$status" -eq 1 ]; then
    caught=$((caught + 1))
    n=${at##* }
    detections+=("$((n + 1))")
    printf '  caught  %-22s %s -> %s\n' "$m" "${at:-?}" "$(grep -oE '^VIOLATION [a-z-]+' <<<"$out")"
    # A finding that does not replay is worthless: its case file must fail
    # again, with the same check, against the same generator.
    file=$(grep -oE '^VIOLATION [a-z-]+ .*' <<<"$out" | head -1 | cut -d' ' -f3-)
    name=$(grep -oE '^VIOLATION [a-z-]+' <<<"$out" | head -1 | cut -d' ' -f2)
    again=$("$manifuzz" replay --generator "$plugins/libmfz_mutant_$m.so" "$file" 2>&1)
    if [ $? -ne 1 ] || ! grep -q "^VIOLATION $name " <<<"$again"; then
      failures=$((failures + 1))
      printf '  NO REPLAY %s: %s did not fail %s again\n' "$m" "$file" "$name"
    fi
  else
    failures=$((failures + 1))
    printf '  MISSED  %-22s (status %s in %s cases)\n' "$m" "$status" "$budget"
  fi
done
# Correct generators: the variants that choose differently in ties at the
# contract level, the built-in and its plugin at the strict level.
for g in reducing last_incident_face b_reference_on_face_ties reversed_order \
         "$plugins/libmanifuzz_clipping.so --strict" "builtin --strict"; do
  case "$g" in *.so*|builtin*) ;; *) g="$plugins/libmfz_mutant_$g.so" ;; esac
  out=$("$manifuzz" check --generator $g --cases "$correct_budget" --seed "$seed" --out "$scratch/ok" --quiet 2>&1)
  status=$?
  if [ "$status" -eq 0 ]; then
    printf '  passes  %s\n' "$g"
  else
    failures=$((failures + 1))
    printf '  FLAGGED %s (a correct generator): %s\n' "$g" "$(grep -E '^VIOLATION|found' <<<"$out" | head -2)"
  fi
done
median=$(printf '%s\n' "${detections[@]}" | sort -n | awk '{a[NR]=$1} END {print (NR ? a[int((NR+1)/2)] : "-")}')
echo "mutation score: $caught/$total caught; median cases to detection: $median (seed $seed)"
echo "$((total + 3 - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
