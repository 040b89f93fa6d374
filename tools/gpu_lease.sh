#!/usr/bin/env bash
# What a lent GPU runs for issue 24, as one command that fits a 15-minute lease: the most wanted
# figures first, each step under its own time limit and none started past a deadline
# (GPU_LEASE_DEADLINE seconds, default 540), so that a lease cut short still brings back the rows
# that matter:
#
#   DOF=path/to/release/dof [BASE_DOF=path/to/earlier/dof] bash tools/gpu_lease.sh OUT_DIR
#
# With BASE_DOF, the run begins with that build against DOF, interleaved (tools/gpu_compare.sh:
# multi-layer 4x4 on every built-in scene at the first size, `railing`, `fence` and `simple` at the
# second; into OUT/compare/), so that a kernel change measured only on the CPU gets its GPU figure
# first.
#
# In order: the device (`dof info`, nvidia-smi; the run ends at once if no NVIDIA device answers);
# `dof bench frame` of multi-layer splatting merged 4x4 and of the ring gather on every built-in
# scene at 1920x1080 (the command line's 4 sub-samples, footprints on), `railing` again without
# footprints, then at 3840x2160; at 1920x1080 unmerged, 2x2, tiled, bokeh, layered and the
# ray tracer; the device peel of `fence` with the camera orbiting at both sizes; `dof bench ratios`
# at 1920x1080 (16-spp references); `dof stress` on the GPU (every method's oracles on a real
# driver); the exhaustive gather at 1920x1080 (5 frames: it is slow); the rest at 3840x2160;
# `dof bench ratios` at 3840x2160. Everything lands in one tarball, OUT_DIR/gpu.tgz, since the
# device tool brings back few files. Unpack it into docs/gpu/<device>/ and run
# `python3 tools/gpu_summary.py` there for the tables. Vulkan's loader travels as .deb files in
# .gl/ (see the device tool's notes); the NVIDIA ICD is named explicitly when it is present.
# GPU_LEASE_SIZE1 and GPU_LEASE_SIZE2 replace the two sizes (to try the script on lavapipe).
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:?output folder}
dof=${DOF:?DOF=path/to/release/dof}
m=/tmp/gpu
mkdir -p "$m" "$out"
if [ -d .gl ]; then for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig; fi
icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
[ -f "$icd" ] && export VK_DRIVER_FILES=$icd
export DOF=$dof
s1=${GPU_LEASE_SIZE1:-1920x1080}
s2=${GPU_LEASE_SIZE2:-3840x2160}
start=$(date +%s)
deadline=$((start + ${GPU_LEASE_DEADLINE:-540}))
log=$m/run.log
touch "$log"
step() { # time limit, then the command; skipped past the deadline
  local limit=$1; shift
  local left=$((deadline - $(date +%s)))
  if [ "$left" -lt 10 ]; then echo "skipped (deadline): $*" | tee -a "$log"; return; fi
  [ "$left" -lt "$limit" ] && limit=$left
  timeout "$limit" "$@"
}
measure() { # time limit, then gpu_measure.sh's options
  local limit=$1; shift
  step "$limit" bash tools/gpu_measure.sh "$m" --no-ratios "$@"
}
orbit() { # size
  local w=${1%x*} h=${1#*x}
  step 60 "$dof" bench frame --backend vulkan --scene fence --method multilayer --orbit 1 \
    --width "$w" --height "$h" --frames 10 --json > "$m/orbit-fence-$1.json" 2> "$m/orbit-fence-$1.err" \
    || echo "orbit $1 failed: $(tail -n 1 "$m/orbit-fence-$1.err")" | tee -a "$log"
}
no_footprints() { # size: multi-layer 4x4 on `railing` without footprints, beside the sweep's row with them
  local w=${1%x*} h=${1#*x}
  step 40 "$dof" bench frame --backend vulkan --scene railing --method multilayer --merge 4x4 --width "$w" --height "$h" \
    --frames 20 --no-footprints --json > "$m/no-footprints-railing-$1.json" 2> "$m/no-footprints-railing-$1.err" \
    || echo "no-footprints $1 failed: $(tail -n 1 "$m/no-footprints-railing-$1.err")" | tee -a "$log"
}
ratios() { # time limit, size
  local w=${2%x*} h=${2#*x}
  step "$1" "$dof" bench ratios --backend vulkan --width "$w" --height "$h" --spp 16 --runs 3 \
    --out "$m/ratios-$2" > "$m/ratios-$2.log" 2>&1 || echo "ratios $2 failed" | tee -a "$log"
}
finish() {
  echo "took $(( $(date +%s) - start )) s" | tee -a "$log"
  python3 tools/gpu_summary.py "$m" > "$m/summary.md" 2>/dev/null
  tar czf "$out/gpu.tgz" -C /tmp gpu
  tail -n 30 "$log"
}
nvidia-smi > "$m/nvidia-smi.txt" 2>&1
"$dof" info > "$m/device.txt" 2>&1
head -n 4 "$m/device.txt"
if [ -z "${GPU_LEASE_SIZE1:-}" ] && ! grep -q "vulkan device 0: NVIDIA" "$m/device.txt"; then
  echo "no NVIDIA Vulkan device: stopping" | tee -a "$log"
  ls /usr/share/vulkan/icd.d /etc/vulkan/icd.d /usr/local/nvidia/share/vulkan/icd.d >> "$log" 2>&1
  ldconfig -p | grep -i vulkan >> "$log"
  finish; exit 1
fi
if [ -n "${BASE_DOF:-}" ]; then
  step 130 bash tools/gpu_compare.sh "$m/compare" "$BASE_DOF" "$dof" --sizes "$s1" --methods multilayer:4x4 --deadline 110 >> "$log" 2>&1
  step 80 bash tools/gpu_compare.sh "$m/compare" "$BASE_DOF" "$dof" --sizes "$s2" --scenes railing,fence,simple --methods multilayer:4x4 --deadline 60 >> "$log" 2>&1
fi
measure 120 --sizes "$s1" --methods multilayer:4x4,ring-gather:none
no_footprints "$s1"
measure 150 --sizes "$s2" --methods multilayer:4x4,ring-gather:none
measure 150 --sizes "$s1" --methods multilayer:none,multilayer:2x2,tiled:4x4,bokeh:none,layered:none,raytrace:none
orbit "$s1"
orbit "$s2"
ratios 100 "$s1"
step 60 "$dof" stress --backend vulkan > "$m/stress-vulkan.log" 2>&1
echo "stress exit $?" | tee -a "$log"
measure 60 --sizes "$s1" --methods gather:none --frames 5 --warmup 1
measure 120 --sizes "$s2" --methods multilayer:none,tiled:4x4,layered:none,raytrace:none --frames 5 --warmup 1
ratios 150 "$s2"
finish
