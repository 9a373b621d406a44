#!/usr/bin/env bash
# Line and branch coverage of the parsers under the fuzz harness
# (docs/fuzzing.md): builds tests/storage/fuzz with gcc's --coverage in its own
# build directory (build/coverage), runs it (ROCKFACE_FUZZ_ITERATIONS and
# ROCKFACE_FUZZ_SEED as set in the environment: a factor on the CI counts
# and the mutator's seed), and prints gcov's summary
# for each parser's source file. Needs only gcc's gcov.
#   tools/fuzz_coverage.sh            # the CI-sized run
#   ROCKFACE_FUZZ_ITERATIONS=10 tools/fuzz_coverage.sh   # ten times the inputs
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/coverage
jobs=${JOBS:-2}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="--coverage -O1" -DCMAKE_EXE_LINKER_FLAGS="--coverage" \
  -DROCKFACE_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target fuzz_tests -j "$jobs"
find "$build" -name '*.gcda' -delete
"$build/tests/storage/fuzz/fuzz_tests" --gtest_brief=1
# The parsers: a file per input kind (the project file: the store's sources).
parsers=(
  storage/scene/scene_json.cpp storage/scene/camera_json.cpp core/photogrammetry/estimators/registration.cpp
  core/photogrammetry/targets/reference_line.cpp storage/exchange/ply_reader.cpp camera/exif.cpp
  storage/project/project_store.cpp storage/project/project_store_captures.cpp storage/project/project_store_survey.cpp
  storage/project/project_store_cameras.cpp storage/project/project_sqlite.cpp storage/project/project_schema.cpp
  storage/project/project_blobs.cpp
)
root=$PWD
for src in "${parsers[@]}"; do
  dir=$(dirname "$src")
  while [ ! -d "$root/$build/$dir" ] && [ "$dir" != . ]; do dir=$(dirname "$dir"); done
  obj=$(find "$root/$build/$dir" -name "$(basename "$src").o" | head -1)
  [ -n "$obj" ] || { echo "$src: no object file"; continue; }
  gcov -b -n -o "$obj" "$root/$src" 2>/dev/null |
    awk -v f="$src" '
      /^File/ { keep = index($0, f) > 0 }
      keep && /^(Lines|Branches|Taken)/ { printf "%s: %s\n", f, $0 }'
done
