#!/usr/bin/env bash
# ClusterFuzzLite's build, without Docker: .clusterfuzzlite/build.sh with the
# variables its build image sets, pointing at the local clang, ASan + UBSan
# and a temporary $OUT; then each target shipped in $OUT runs for a few
# seconds on its unzipped seed corpus with its dictionary and options, as
# the runner would. A target may stop on a check's VIOLATION (a finding, with
# its case file); a sanitizer report, a missing library or a bad option fails.
set -euo pipefail
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export CC=clang CXX=clang++ SRC="$source_dir" WORK="$scratch/work" OUT="$scratch/out"
flags="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address,undefined -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
export CFLAGS="$flags" CXXFLAGS="$flags" LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
mkdir -p "$WORK" "$OUT"
bash "$source_dir/.clusterfuzzlite/build.sh" > "$scratch/build.log" 2>&1 || { tail -30 "$scratch/build.log"; exit 1; }

status=0
for target in manifold_fuzzer case_file_fuzzer; do
  for shipped in "$target" "${target}_seed_corpus.zip" "$target.dict" "$target.options"; do
    [ -f "$OUT/$shipped" ] || { echo "FAIL: \$OUT/$shipped missing"; status=1; }
  done
  corpus="$scratch/corpus-$target"
  mkdir -p "$corpus" && unzip -q "$OUT/${target}_seed_corpus.zip" -d "$corpus"
  max_len=$(sed -n 's/^max_len = //p' "$OUT/$target.options")
  log="$scratch/$target.log"
  if (cd "$scratch" && "$OUT/$target" -seed=1 -max_total_time=4 -max_len="$max_len" -dict="$OUT/$target.dict" \
        -artifact_prefix="$scratch/" "$corpus" > "$log" 2>&1); then
    echo "ok: $target ran 4 s ($(ls "$corpus" | wc -l) inputs in its corpus)"
  elif grep -q '^VIOLATION ' "$log" && ! grep -q 'Sanitizer' "$log"; then
    echo "ok: $target ran and stopped on a finding: $(grep '^VIOLATION ' "$log" | head -1)"
  else
    echo "FAIL: $target"; tail -30 "$log"; status=1
  fi
done
# The libraries a runner image lacks are shipped and found through the rpath.
if ldd "$OUT/manifold_fuzzer" | grep -E 'libqhull|libccd' | grep -qv "$OUT/lib"; then
  echo "FAIL: manifold_fuzzer does not find its shipped libraries in \$OUT/lib"; ldd "$OUT/manifold_fuzzer"; status=1
fi
exit $status
