#!/usr/bin/env bash
# Builds the release preset with benchmarks and runs every benchmark (or the
# ones named: tools/bench/run.sh pyramids_bench). Results go to
# build/release/bench/results/NAME.txt; docs/accuracy-cost.md quotes them
# with the machine they ran on.
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup.sh
cmake --preset release -DROCKFACE_BUILD_BENCH=ON >/dev/null
cmake --build --preset release -j "$(nproc)"
mkdir -p build/release/bench/results
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for b in build/release/bench/*_bench; do names+=("$(basename "$b")"); done
fi
{ echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"; } \
  > build/release/bench/results/machine.txt
for n in "${names[@]}"; do
  echo "== $n"
  "build/release/bench/$n" --benchmark_counters_tabular=true | tee "build/release/bench/results/$n.txt"
done
