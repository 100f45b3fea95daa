#!/usr/bin/env bash
# Builds and runs every test: g++ (the default preset), clang++, and g++ with
# ASan + UBSan. Properties run a bounded number of cases here.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
for preset in default clang sanitize; do
  echo "== $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
