#!/usr/bin/env bash
# README command 2: set up, build, and run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release
# libgphoto2's virtual D750 for tests/camera/vcamera (built once per
# libgphoto2 version, then only looked up): docs/virtual-camera.md
tools/virtual-camera.sh > /dev/null
ctest --preset release -j "$(nproc)" --timeout 600
