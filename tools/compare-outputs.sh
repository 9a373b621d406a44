#!/usr/bin/env bash
# Compares what two builds of rockface write for the samples, byte for byte:
# the demo replay's table (stdout), the measurements of the sample picks
# (tools/samples/tunnel-face-demo.picks.json) on the demo's 3D image
# (MEASURES.json, stereonet PNG, Dips CSV, stdout), the field report of the
# visit (PDF, less its creation date) and the slope-wedge report JSON (less
# its timings). For a change that must not change behaviour (issue 26): build
# before and after, then
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
samples=$PWD/tools/samples

# The report and the measurements read one project, made once: a replay
# stores the time of its visit, which would differ between two replays.
"$before" replay "$samples/tunnel-face-demo.scene.json" --project "$work/common.rockface" >/dev/null 2>&1

run() {  # run SIDE BINARY: every output written under the same paths for both sides
  local side=$1 bin=$2 r="$work/run"
  rm -rf "$r"
  mkdir -p "$r"
  (
    cd "$r"
    "$bin" replay "$samples/tunnel-face-demo.scene.json" --project replay.rockface >replay.txt 2>replay.err
    rm -rf replay.rockface*
    cp "$work/common.rockface" demo.rockface
    "$bin" measure demo.rockface --traces "$samples/tunnel-face-demo.picks.json" \
      --out MEASURES.json --png stereonet.png --csv dips.csv >measure.txt
    "$bin" report demo.rockface --visit 1 --out report.pdf >report.txt
    # cairo dates the PDF: the only line allowed to differ.
    grep -av 'CreationDate' report.pdf >report.pdf.nodate || true
    "$bin" analyse "$samples/slope-wedge.scene.json" --out slope-wedge.report.json >analyse.txt
    sed -E -i '/"timings_ms"/,/}/ s/[0-9]+\.?[0-9]*(e-?[0-9]+)?/<ms>/g' slope-wedge.report.json
    rm -rf report.pdf replay.err demo.rockface*
  )
  mv "$r" "$work/$side"
}

run before "$before"
run after "$after"
status=0
for f in "$work/before"/*; do
  name=$(basename "$f")
  if cmp -s "$f" "$work/after/$name"; then
    echo "same      $name"
  else
    echo "DIFFERENT $name"
    status=1
  fi
done
exit $status
