#!/usr/bin/env bash
# Installs what the project needs on a fresh Debian machine and builds the WebAssembly.
# Idempotent: each step is skipped when its result is already there.
#   scripts/setup.sh            apt packages for the build, npm packages, the WebAssembly
#   scripts/setup.sh --native   also the native build tools (g++, GoogleTest, clang-format), Orocos KDL
#                               (the bench's kdl) and build/native (Release: the tools; npm test runs
#                               the GoogleTest suites in the sanitizer build, scripts/test-sanitize.sh)
#   scripts/setup.sh --browser  also Chromium for the browser tests
set -euo pipefail
cd "$(dirname "$0")/.."

want_native=0
want_browser=0
for arg in "$@"; do
  case "$arg" in
    --native) want_native=1 ;;
    --browser) want_browser=1 ;;
    *) echo "setup.sh: unknown option $arg" >&2; exit 2 ;;
  esac
done

packages=(emscripten node-acorn libeigen3-dev cmake ninja-build)
# liborocos-kdl-dev: Orocos KDL, the native bench's kdl method (optional for CMake: without it, no kdl).
# clang-format: scripts/test.sh checks the C++ under wasm/ against .clang-format. The sanitizer
# build of the tests (scripts/test-sanitize.sh) needs nothing more: g++ brings AddressSanitizer's
# and UndefinedBehaviorSanitizer's runtimes (libasan, libubsan).
[ "$want_native" = 1 ] && packages+=(g++ googletest libgtest-dev nlohmann-json3-dev liborocos-kdl-dev clang-format)
[ "$want_browser" = 1 ] && packages+=(chromium)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" != 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  # Wait (up to 10 minutes) for another apt or dpkg, e.g. `npm start` and `npm test` set up at once.
  apt=("${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600)
  "${apt[@]}" install -y --no-install-recommends "${missing[@]}" \
    || { "${apt[@]}" update && "${apt[@]}" install -y --no-install-recommends "${missing[@]}"; }
fi

# npm packages, pinned by package-lock.json; reinstall when the lockfile changed.
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: npm ci"
  # The lockfile lists every platform's optional packages (rollup's native builds), so `npm ci`
  # installs exactly the locked versions anywhere. rollup is pinned by an override in
  # package.json to a release whose builds for every platform are on the registry.
  npm ci --no-audit --no-fund
fi

# The WebAssembly core (web/src/ik/generated/).
export NODE_PATH=/usr/share/nodejs
if [ ! -f build/wasm/build.ninja ]; then
  emcmake cmake -S wasm -B build/wasm -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build/wasm

if [ "$want_native" = 1 ]; then
  # Release: the tools (the bench's native engine), every warning an error (IK_WERROR); a
  # build/native configured before that setting is configured again. The GoogleTest suites are
  # left out (IK_TESTS=OFF: npm test builds and runs them with the sanitizers); configure with
  # -DIK_TESTS=ON for a Release build of them (ctest --test-dir build/native).
  if [ ! -f build/native/build.ninja ] || ! grep -q '^IK_WERROR:BOOL=ON$' build/native/CMakeCache.txt; then
    cmake -S wasm -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release -DIK_TESTS=OFF -DIK_WERROR=ON >/dev/null
  fi
  cmake --build build/native
fi
