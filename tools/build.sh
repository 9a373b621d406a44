#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release). In CI
# (CI=true) warnings are errors, and the release build leaves out what the
# tests do not run — the benchmarks (tools/bench/run.sh builds them) and
# debug information (same -O2 -DNDEBUG code) — to keep CI inside its time
# on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
extra=()
if [ "${CI:-}" = "true" ]; then
  extra+=(-DROCKFACE_WERROR=ON)
  if [ "$preset" = "release" ]; then
    extra+=(-DROCKFACE_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"
      "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG")
  fi
fi
cmake --preset "$preset" "${extra[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
echo "build.sh: $preset built in $SECONDS s"
