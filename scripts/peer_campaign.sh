#!/usr/bin/env bash
# Looks for every kind of violation a generator makes, not just the first:
# one `manifuzz check --only NAME` per invariant and relation, each for
# SECONDS, all on one seed; a table of what each found (the minimised case,
# and with --confirm-with G2, the double build of a float peer, how many
# findings were rounding only, passed over because G2 does not make them)
# is printed at the end and kept in OUT/summary.txt.
#
#   scripts/peer_campaign.sh MANIFUZZ GENERATOR SECONDS OUT [--family F] [--confirm-with G2] [--seed S]
set -uo pipefail
manifuzz=$1 generator=$2 seconds=$3 out=$4
shift 4
family=() confirm=() seed=1
while [ $# -gt 0 ]; do
  case $1 in
    --family) family=(--family "$2"); shift 2 ;;
    --confirm-with) confirm=(--confirm-with "$2"); shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    *) echo "peer_campaign: unknown option $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
names=$("$manifuzz" --help 2>&1 | sed -n 's/^  checks: //p')
[ -n "$names" ] || { echo "peer_campaign: manifuzz --help lists no checks" >&2; exit 2; }
summary="$out/summary.txt"
printf '%-26s %8s  %-24s %s\n' check cases finding "rounding only" > "$summary"
for name in $names; do
  log="$out/$name.log"
  "$manifuzz" check --generator "$generator" --only "$name" --seconds "$seconds" --seed "$seed" --quiet \
    --out "$out/$name" "${family[@]}" "${confirm[@]}" > "$log.out" 2> "$log"
  cases=$(sed -n 's/^manifuzz check: \([0-9][0-9]*\) cases in.*/\1/p' "$log" | tail -1)
  finding=$(sed -n 's/^VIOLATION \([^ ]*\) .*/\1/p' "$log.out")
  file=$(sed -n 's/^VIOLATION [^ ]* //p' "$log.out")
  rounding=$(sed -n 's/.*, \([0-9][0-9]*\) findings of rounding only passed over.*/\1/p' "$log" | tail -1)
  printf '%-26s %8s  %-24s %6s  %s\n' "$name" "${cases:-?}" "${finding:-none}" "${rounding:--}" "$file" >> "$summary"
done
cat "$summary"
