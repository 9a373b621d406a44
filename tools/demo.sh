#!/usr/bin/env bash
# README command 1: set up, build, and run the main job on built-in sample
# data: the field workflow, headless, on a synthetic tunnel face (a range pole
# and three joints) through the mock camera, into a project file. The joint
# traces are tapped in the photographs (the scene's `picks`), measured on the
# reconstructed 3D image, and the blocks come from the measured traces and
# joint planes; it prints each joint's measured orientation beside the
# scene's and the table of blocks with their verdicts.
#
# It builds only what it runs: the rockface program, optimised, without the
# tests, the benchmarks or debug information, each library as a unity build
# (CMake preset "demo", build/demo).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh --demo
cmake --preset demo >/dev/null
cmake --build --preset demo -j "$(nproc)"
echo "demo.sh: rockface built in $SECONDS s"
mkdir -p out
build/demo/rockface replay tools/samples/tunnel-face-demo.scene.json --project out/tunnel-face-demo.rockface
echo "demo.sh: done in $SECONDS s"
