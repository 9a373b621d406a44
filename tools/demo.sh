#!/usr/bin/env bash
# README command 1: set up, build, and run the main job on built-in sample
# data: the field workflow, headless, on a synthetic tunnel face (a range pole
# and three joints) through the mock camera, into a project file; prints the
# table of blocks found with their verdicts.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release
mkdir -p out
build/release/rockface replay tools/samples/tunnel-face-demo.scene.json --project out/tunnel-face-demo.rockface
