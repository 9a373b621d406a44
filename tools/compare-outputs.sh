#!/usr/bin/env bash
# Compares what two builds of rockface write for the samples, byte for byte:
# the demo replay's table (stdout), the field report of its visit (PDF, less
# its creation date), the measurements of the sample picks on its 3D image
# (MEASURES.json, stereonet PNG, Dips CSV) and the slope-wedge report JSON.
# For a change that must not change behaviour (issue 26): build main before
# and after, then
#
#   tools/compare-outputs.sh BEFORE/rockface AFTER/rockface
#
# Exit 0 when every output is identical, 1 naming the ones that differ.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 2 ]; then
  echo "usage: $0 BEFORE_ROCKFACE AFTER_ROCKFACE" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() {  # run SIDE BINARY
  local side=$1 bin=$2 d="$work/$1"
  mkdir -p "$d"
  "$bin" replay tools/samples/tunnel-face-demo.scene.json --project "$d/demo.rockface" \
    >"$d/replay.txt" 2>"$d/replay.err"
  "$bin" measure "$d/demo.rockface" --traces tools/samples/tunnel-face-demo.picks.json \
    --out "$d/MEASURES.json" --png "$d/stereonet.png" --csv "$d/dips.csv" \
    >"$d/measure.txt" 2>"$d/measure.err"
  "$bin" report "$d/demo.rockface" --visit 1 --out "$d/report.pdf" >"$d/report.txt" 2>&1
  # The PDF's creation date is the only field that may differ between two runs.
  grep -av '^/CreationDate\|CreationDate (' "$d/report.pdf" >"$d/report.pdf.nodate" || true
  rm "$d/report.pdf"
  "$bin" analyse tools/samples/slope-wedge.scene.json --out "$d/slope-wedge.report.json" \
    >"$d/analyse.txt" 2>&1
  # The replay prints timings of its steps: those are the only lines allowed to differ.
  sed -E -i 's/[0-9]+(\.[0-9]+)? ?(ms|s)\b/<time>/g' "$d/replay.txt" "$d/measure.txt"
}

run before "$before"
run after "$after"
status=0
for f in "$work/before"/*; do
  name=$(basename "$f")
  case "$name" in *.err) continue ;; esac
  if cmp -s "$f" "$work/after/$name"; then
    echo "same      $name"
  else
    echo "DIFFERENT $name"
    status=1
  fi
done
exit $status
