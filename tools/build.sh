#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release). In CI
# (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
extra=()
if [ "${CI:-}" = "true" ]; then extra+=(-DROCKFACE_WERROR=ON); fi
cmake --preset "$preset" "${extra[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
