#!/usr/bin/env bash
# Five images against two (issue 28), one command: builds face_merge_ratio_bench
# (in build/bench, configured once with CI's optimisation and the benchmarks on;
# the compiler cache serves what the release build made) and runs the 2, 5 and
# 10-image merges interleaved, 9 rounds at the default tie-point
# SIFT width. Prints one line per round and the table docs/accuracy-cost.md
# quotes ("Five images against two (the merge)"). About 3 minutes on two idle
# cores: ~1.5 min to reconstruct the ten stations' pairs, ~7 s per round.
#   tools/bench/face_merge_ratio.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=build/bench
if [ ! -f "$dir/CMakeCache.txt" ]; then
  cmake -S . -B "$dir" -G Ninja -DROCKFACE_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=Release \
    "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" >/dev/null
fi
cmake --build "$dir" --target face_merge_ratio_bench -j "$(nproc)" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs);" \
  "load average now: $(cut -d' ' -f1-3 /proc/loadavg)"
"$dir/bench/face_merge_ratio_bench" --benchmark_filter='BM_MergeInterleaved/rounds:9/width:600' \
  --benchmark_counters_tabular=true 2>&1 | grep --line-buffered -v '^\*\*\*WARNING'
