#!/usr/bin/env bash
# The main job: set up, build, and run manifuzz on the built-in generator.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
cmake --preset default >/dev/null
cmake --build --preset default
build/default/src/manifuzz replay corpus/*.case
