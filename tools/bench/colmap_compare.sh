#!/usr/bin/env bash
# COLMAP's sparse two-view reconstruction (CPU) on the Middlebury temple
# pairs that tests/realdata uses, for the table in docs/accuracy-cost.md:
# wall time and rotation / base-direction error of the relative orientation
# against templeSR_par.txt. COLMAP is not a build or test dependency: without
# it this script says so and exits 0.
#   tools/bench/colmap_compare.sh [PAIR ...]     e.g. 1-2 9-10 (default: 1-2 3-4 7-8 9-10)
#   tools/bench/colmap_compare.sh synthetic      the synthetic tunnel face (24 Mpx, Brown
#                                                distortion) rendered by `rockface render`,
#                                                COLMAP and `rockface reconstruct` on the
#                                                same pair, errors against the render's poses
set -euo pipefail
cd "$(dirname "$0")/../.."
export BENCH_DIR="$(pwd)/tools/bench"  # pose_math.py for the Python parts
if ! command -v colmap >/dev/null; then
  echo "colmap not installed (apt-get install colmap); nothing to compare"
  exit 0
fi
data="${ROCKFACE_SHARED_DIR:-$(pwd)/../shared}/data/middlebury-temple"
pairs=("$@")
[ ${#pairs[@]} -eq 0 ] && pairs=(1-2 3-4 7-8 9-10)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# COLMAP's sparse two-view reconstruction of DIR/images with the camera
# fixed: run_colmap DIR MODEL PARAMS. Leaves DIR/sparse/0 when it registers
# the pair, and its log in DIR/log.
run_colmap() {
  local d="$1" model="$2" params="$3"
  colmap feature_extractor --database_path "$d/db" --image_path "$d/images" \
    --ImageReader.camera_model "$model" --ImageReader.single_camera 1 \
    --ImageReader.camera_params "$params" --SiftExtraction.use_gpu 0 >"$d/log" 2>&1
  colmap exhaustive_matcher --database_path "$d/db" --SiftMatching.use_gpu 0 >>"$d/log" 2>&1
  colmap mapper --database_path "$d/db" --image_path "$d/images" --output_path "$d/sparse" \
    --Mapper.init_min_num_inliers 30 --Mapper.ba_refine_focal_length 0 \
    --Mapper.ba_refine_principal_point 0 --Mapper.ba_refine_extra_params 0 >>"$d/log" 2>&1 || true
}

if [ "${pairs[0]}" = synthetic ]; then
  rockface=build/release/rockface
  d="$work/synthetic"; mkdir -p "$d/images" "$d/sparse"
  "$rockface" render tools/samples/tunnel-face.scene.json --out "$d/render" >/dev/null
  cp "$d/render/left.png" "$d/render/right.png" "$d/images/"
  # OpenCV's Brown model is COLMAP's OPENCV model: fx fy cx cy k1 k2 p1 p2 (k3 = 0).
  params=$(python3 -c "import json; c = json.load(open('$d/render/camera.json')); k = c['distortion']
print(','.join(str(v) for v in [c['fx'], c['fy'], c['cx'], c['cy'], k[0], k[1], k[2], k[3]]))")
  start=$(date +%s.%N)
  run_colmap "$d" OPENCV "$params"
  end=$(date +%s.%N)
  colmap_secs=$(echo "$end - $start" | bc)
  [ -d "$d/sparse/0" ] && colmap model_converter --input_path "$d/sparse/0" \
    --output_path "$d/sparse" --output_type TXT >>"$d/log" 2>&1
  line=$(python3 -c "import json; t = json.load(open('$d/render/truth.json'))['reference_line']
print(','.join(str(v) for p in t['left'] for v in p), t['azimuth_deg'])")
  start=$(date +%s.%N)
  "$rockface" reconstruct "$d/render/left.png" "$d/render/right.png" --camera "$d/render/camera.json" \
    --preset standard --range-pole 2.0 --reference-line "${line% *}" --azimuth "${line#* }" \
    --out "$d/model.ply" --report "$d/report.json" >>"$d/log" 2>&1
  end=$(date +%s.%N)
  rockface_secs=$(echo "$end - $start" | bc)
  python3 - "$d" "$colmap_secs" "$rockface_secs" <<'PY'
import sys, json, os
sys.path.insert(0, os.environ['BENCH_DIR'])
from pose_math import *
d, colmap_secs, rockface_secs = sys.argv[1:]
cams = {c['station']: c for c in json.load(open(d + '/render/truth.json'))['cameras']}
R1, R2 = cams['left']['rotation_world_to_camera'], cams['right']['rotation_world_to_camera']
C1, C2 = cams['left']['position'], cams['right']['position']
Rt = mul(R2, T(R1))                 # x_right = Rt x_left + tt
tt = mv(R2, sub(C1, C2))
def errors(R, t): return rot_angle(mul(T(R), Rt)), angle(t, tt)
print(f"{'who':10s} {'time_s':>8s} {'rotation_deg':>14s} {'base_dir_deg':>14s}")
try:
    est = colmap_poses(d + '/sparse/images.txt')
    (Ra, ta), (Rb, tb) = est['left.png'], est['right.png']
    R = mul(Rb, T(Ra))
    r, b = errors(R, sub(tb, mv(R, ta)))
    print(f"{'COLMAP':10s} {float(colmap_secs):8.2f} {r:14.4f} {b:14.4f}")
except (OSError, KeyError):
    print(f"{'COLMAP':10s} {float(colmap_secs):8.2f} {'failed':>14s} {'-':>14s}")
o = json.load(open(d + '/report.json'))['orientation']
r, b = errors(o['R'], o['t'])
print(f"{'rockface':10s} {float(rockface_secs):8.2f} {r:14.4f} {b:14.4f}   (whole reconstruction, standard preset)")
PY
  exit 0
fi
# The temple's intrinsics (all views share K).
read -r fx cx fy cy < <(awk 'NR==2 {print $2, $4, $6, $7}' "$data/templeSR_par.txt")
printf "%-6s %8s %14s %16s %8s\n" pair time_s rotation_deg base_dir_deg images
for p in "${pairs[@]}"; do
  a=$(printf "templeSR%04d.png" "${p%-*}"); b=$(printf "templeSR%04d.png" "${p#*-}")
  d="$work/$p"; mkdir -p "$d/images" "$d/sparse"
  cp "$data/$a" "$data/$b" "$d/images/"
  start=$(date +%s.%N)
  run_colmap "$d" PINHOLE "$fx,$fy,$cx,$cy"
  end=$(date +%s.%N)
  if [ ! -d "$d/sparse/0" ]; then
    printf "%-6s %8.2f %14s %16s %8s\n" "$p" "$(echo "$end - $start" | bc)" failed - 0
    continue
  fi
  colmap model_converter --input_path "$d/sparse/0" --output_path "$d/sparse" --output_type TXT >>"$d/log" 2>&1
  python3 - "$d/sparse/images.txt" "$data/templeSR_par.txt" "$a" "$b" "$(echo "$end - $start" | bc)" "$p" <<'PY'
import sys, os
sys.path.insert(0, os.environ['BENCH_DIR'])
from pose_math import *
images, par, a, b, secs, pair = sys.argv[1:]
est = colmap_poses(images)
truth = {}
for l in open(par).readlines()[1:]:
    f = l.split()
    v = list(map(float, f[1:]))
    truth[f[0]] = ([v[9:12], v[12:15], v[15:18]], v[18:21])
if a not in est or b not in est:
    print(f"{pair:6s} {float(secs):8.2f} {'not registered':>14s} {'-':>16s} {len(est):8d}")
    sys.exit(0)
Re, te = relative(est[a], est[b])
Rt, tt = relative(truth[a], truth[b])
print(f"{pair:6s} {float(secs):8.2f} {rot_angle(mul(T(Re), Rt)):14.4f} {angle(te, tt):16.4f} {len(est):8d}")
PY
done
