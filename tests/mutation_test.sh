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
# A float profile must separate rounding from logic: the broken float
# variant's finding is one the same logic in double makes too.
float_case=$(grep -oE '^VIOLATION [a-z-]+ .*' <<<"$("$manifuzz" check --generator "$plugins/libmfz_mutant_float_side_clip_skipped.so" \
             --cases "$budget" --seed "$seed" --out "$scratch/float" --quiet 2>&1)" | head -1)
float_name=$(cut -d' ' -f2 <<<"$float_case") float_file=$(cut -d' ' -f3- <<<"$float_case")
in_double=$("$manifuzz" replay --generator "$plugins/libmfz_mutant_side_clip_skipped.so" --profile none "$float_file" 2>&1)
if [ -n "$float_name" ] && grep -q "^VIOLATION $float_name " <<<"$in_double"; then
  printf '  float   %s reproduces in double (%s)\n' "$float_name" "side_clip_skipped"
else
  failures=$((failures + 1))
  printf '  FLOAT FINDING NOT IN DOUBLE: %s\n' "${float_case:-none found}"
fi
# The profile is what lets the correct float variant pass: held to double, it fails.
if "$manifuzz" check --generator "$plugins/libmfz_mutant_float_precision.so" --profile precision=double \
     --cases "$correct_budget" --seed "$seed" --out "$scratch/double" --quiet >/dev/null 2>&1; then
  failures=$((failures + 1))
  printf '  PASSES IN DOUBLE: the float variant passed without its profile\n'
else
  printf '  flagged float_precision under --profile precision=double, as it must be\n'
fi
# The correct variants' own regression cases, each named after its variant
# (float-*: float_precision, face-bias-*: face_bias, reversed-order-*:
# reversed_order, reducing-*: reducing): each was a false alarm
# once, or a fault of the built-in's that only the variant reached.
variant_cases=0
for case in "$(dirname "$0")"/../corpus/variants/*.case; do
  case "$(basename "$case")" in
    float-*) variant=float_precision ;;
    face-bias-*) variant=face_bias ;;
    reversed-order-*) variant=reversed_order ;;
    reducing-*) variant=reducing ;;
    *) failures=$((failures + 1)); printf '  NO VARIANT named by %s\n' "$case"; continue ;;
  esac
  variant_cases=$((variant_cases + 1))
  if "$manifuzz" replay --generator "$plugins/libmfz_mutant_$variant.so" "$case" >/dev/null 2>&1; then
    printf '  passes  %s on %s\n' "$variant" "$(basename "$case")"
  else
    failures=$((failures + 1))
    printf '  FLAGGED %s (a correct generator) on %s\n' "$variant" "$case"
  fi
done
# Correct generators: the variants that choose differently in ties at the
# contract level (each under the profile it declares), the built-in and its
# plugin at the strict level.
for g in reducing last_incident_face b_reference_on_face_ties reversed_order float_precision face_bias stale_separating_normal \
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
echo "$((total + 10 + variant_cases - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
