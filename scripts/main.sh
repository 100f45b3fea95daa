#!/usr/bin/env bash
# The main job: set up, build, replay the hand-written and regression cases,
# then run the property suite on the built-in generator with its statistics
# (`manifuzz check` with its embedded default budget). Exits with check's
# status: 0 nothing found, 1 a violation (its minimised case is in failures/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
cmake --preset default >/dev/null
cmake --build --preset default
manifuzz=build/default/src/manifuzz
"$manifuzz" replay --strict corpus/*.case corpus/regressions/*.case | grep -E '^(case|verdict|VIOLATION)'
exec "$manifuzz" check --generator builtin --strict "$@"
