#!/usr/bin/env bash
# Installs the Debian 12 packages manifuzz needs, and only those missing.
# Run as root (or with sudo available). Nothing is fetched from anywhere but
# Debian's archive. `--tests` adds what only the tests need: Chromium, which
# opens the HTML reports and case views headless.
#
#   scripts/bootstrap.sh [--tests]
set -euo pipefail

packages=(
  cmake ninja-build g++ clang            # toolchains: g++ builds all, clang also the fuzzers
  pkgconf                                # finds Bullet and ODE, which ship no usable CMake config
  libclang-rt-14-dev libfuzzer-14-dev    # sanitizer and libFuzzer runtimes for clang
  libeigen3-dev libccd-dev libqhull-dev  # geometry, the libccd oracle, hulls (qhull_r)
  librapidcheck-dev libgtest-dev libbenchmark-dev
  libssl-dev zip                         # SHA-1 names of fuzz inputs; seed corpus archives
  libxxhash-dev                          # XXH3, the hash of a hull's loops (header only)
  libbullet-dev libode-dev               # peer generators
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(chromium)                   # the HTML pages' test (tests/html_pages_test.sh)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "bootstrap: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
