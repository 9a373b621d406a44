#!/usr/bin/env bash
# README command 1: set up, build, and run the main job on built-in sample data.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh release
build/release/rockface analyse tools/samples/slope-wedge.scene.json --summary
