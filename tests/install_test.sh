#!/usr/bin/env bash
# The installed package, as a user meets it: `cmake --install` of this build
# into a clean prefix; then examples/my_generator, copied out of the source
# tree, configured against that prefix alone (find_package(manifuzz)), built,
# and its regression cases replayed by its own ctest; and the installed
# manifuzz finds its bundled generators by name.
# usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$1 source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
prefix=$scratch/prefix
cmake --install "$build_dir" --prefix "$prefix" >"$scratch/install.log"
for f in bin/manifuzz include/manifuzz/abi.h lib/cmake/manifuzz/manifuzzConfig.cmake \
         lib/cmake/manifuzz/ManifuzzTesting.cmake lib/manifuzz/libmanifuzz_tutorial.so; do
  [ -e "$prefix/$f" ] || [ -e "$prefix/${f/lib\//lib/x86_64-linux-gnu/}" ] || { echo "FAIL: $f not installed"; exit 1; }
done
cp -r "$source_dir/examples/my_generator" "$scratch/example"
cmake -S "$scratch/example" -B "$scratch/example-build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >"$scratch/configure.log" ||
  { cat "$scratch/configure.log"; exit 1; }
cmake --build "$scratch/example-build" >"$scratch/build.log" || { cat "$scratch/build.log"; exit 1; }
ctest --test-dir "$scratch/example-build" --output-on-failure | tail -3
manifuzz=$(ls "$prefix"/bin/manifuzz)
"$manifuzz" replay --generator tutorial "$source_dir/corpus/box_on_box.case" >/dev/null
"$manifuzz" check --generator "$scratch/example-build/libmy_generator.so" --cases 50 --seed 3 --only finite \
  --out "$scratch/findings" --quiet
echo "ok: the example builds and tests against the installed package"
