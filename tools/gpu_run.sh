#!/usr/bin/env bash
# The prepared GPU run, as one command that fits a 10-minute limit: the most wanted figures first,
# each step under its own time limit and none started past a deadline (GPU_RUN_DEADLINE seconds,
# default 540), so that a run cut short still brings back the rows that matter:
#
#   DOF=path/to/release/dof [BASE_DOF=path/to/baseline/dof] [DOF_COMMIT=abc1234] bash tools/gpu_run.sh OUT_DIR
#
# In order:
# 1. the device (`dof info`, nvidia-smi; the run ends at once if no NVIDIA device answers) and the
#    kernels' static shape (`dof bench kernels --json`), the figures the GPU's own numbers explain,
#    and what the driver reports of each kernel's pipeline (`--device`: registers, spills);
# 2. warm frame times with one timestamp pair a frame and no command timed on its own
#    (`dof bench frame --span-only`, 30 frames after a warm-up of at least 500 ms): multi-layer 4x4
#    and the ring gather on every built-in scene at 1920x1080; multi-layer 4x4 on three of them
#    without subgroup operations (`DOF_SUBGROUPS=off`); then multi-layer 4x4 per stage
#    (`dof bench frame` per command) at that size;
# 3. with BASE_DOF, that build against DOF, interleaved (tools/gpu_compare.sh: multi-layer 4x4 on
#    every built-in scene at 1920x1080; into OUT/compare/);
# 4. `dof stress` on the GPU (every method's oracles on a real driver); multi-layer 4x4 span-only
#    at 3840x2160;
# 5. the moving-camera frame: the device peel of `fence` with the camera orbiting 1 degree a
#    frame, peel and depth of field, span-only and then per stage; the cost of a renderer's
#    colour and depth images brought in, read in place (`dof bench frame --input images`) and
#    copied first (`--input copied-images`: the two copies and the conversion), per stage, for
#    the ring gather and tiled 4x4 at 1920x1080;
# 6. per-stage tables: multi-layer 4x4 and the ring gather at 3840x2160, then the ring gather,
#    unmerged, 2x2, tiled, bokeh, layered and the ray tracer at 1920x1080; `dof bench ratios` at
#    1920x1080; the exhaustive gather; the rest at 3840x2160.
# Everything lands in one tarball, OUT_DIR/gpu.tgz. Unpack it into docs/gpu/<device>-<date>/ and
# run `python3 tools/gpu_summary.py` there for the tables. Vulkan's loader travels as .deb files in
# .gl/ where the machine lacks one; the NVIDIA ICD is named explicitly when it is present.
# GPU_RUN_SIZE1 and GPU_RUN_SIZE2 replace the two sizes (to try the script on lavapipe).
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
s1=${GPU_RUN_SIZE1:-1920x1080}
s2=${GPU_RUN_SIZE2:-3840x2160}
start=$(date +%s)
deadline=$((start + ${GPU_RUN_DEADLINE:-540}))
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
orbit() { # size [--span-only]
  local w=${1%x*} h=${1#*x} tag=${2:+-span-only}
  step 60 "$dof" bench frame --backend vulkan --scene fence --method multilayer --orbit 1 \
    --width "$w" --height "$h" --frames 20 ${2:-} --json > "$m/orbit-fence-$1$tag.json" 2> "$m/orbit-fence-$1$tag.err" \
    || echo "orbit $1$tag failed: $(tail -n 1 "$m/orbit-fence-$1$tag.err")" | tee -a "$log"
}
span_only() { # time limit, size, scene, method, merge [prefix]: warm frames, one timestamp pair each
  local w=${2%x*} h=${2#*x} name="${6:-}span-$3-$2-$4-$5"
  step "$1" "$dof" bench frame --backend vulkan --scene "$3" --method "$4" --merge "$5" --width "$w" --height "$h" \
    --frames 30 --span-only --json > "$m/$name.json" 2> "$m/$name.err" \
    || echo "$name failed: $(tail -n 1 "$m/$name.err")" | tee -a "$log"
}
no_footprints() { # size: multi-layer 4x4 on `railing` without footprints, beside the sweep's row with them
  local w=${1%x*} h=${1#*x}
  step 40 "$dof" bench frame --backend vulkan --scene railing --method multilayer --merge 4x4 --width "$w" --height "$h" \
    --frames 20 --no-footprints --json > "$m/no-footprints-railing-$1.json" 2> "$m/no-footprints-railing-$1.err" \
    || echo "no-footprints $1 failed: $(tail -n 1 "$m/no-footprints-railing-$1.err")" | tee -a "$log"
}
image_input() { # size, method, merge, input: per stage, fed a colour and a depth image each frame
  local w=${1%x*} h=${1#*x} name="$4-railing-$1-$2-$3"
  step 40 "$dof" bench frame --backend vulkan --scene railing --method "$2" --merge "$3" --width "$w" --height "$h" \
    --frames 20 --input "$4" --json > "$m/$name.json" 2> "$m/$name.err" \
    || echo "$name failed: $(tail -n 1 "$m/$name.err")" | tee -a "$log"
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
# The commit the binary was built from (DOF_COMMIT where the tree travels without git).
echo "${DOF_COMMIT:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)}" > "$m/commit.txt"
nvidia-smi > "$m/nvidia-smi.txt" 2>&1
"$dof" info > "$m/device.txt" 2>&1
head -n 4 "$m/device.txt"
if [ -z "${GPU_RUN_SIZE1:-}" ] && ! grep -q "vulkan device 0: NVIDIA" "$m/device.txt"; then
  echo "no NVIDIA Vulkan device: stopping" | tee -a "$log"
  ls /usr/share/vulkan/icd.d /etc/vulkan/icd.d /usr/local/nvidia/share/vulkan/icd.d >> "$log" 2>&1
  ldconfig -p | grep -i vulkan >> "$log"
  finish; exit 1
fi
"$dof" bench kernels --json > "$m/kernels.jsonl" 2> "$m/kernels.err" || echo "bench kernels failed" | tee -a "$log"
step 60 "$dof" bench kernels --device > "$m/kernels-device.jsonl" 2> "$m/kernels-device.err" \
  || echo "driver statistics failed: $(tail -n 1 "$m/kernels-device.err")" | tee -a "$log"
for scene in simple railing columns highlights fence edges; do
  span_only 20 "$s1" "$scene" multilayer 4x4
  span_only 20 "$s1" "$scene" ring-gather none
done
# The same frames with every kernel run without subgroup operations: what the subgroup variants save.
for scene in simple railing fence; do DOF_SUBGROUPS=off span_only 20 "$s1" "$scene" multilayer 4x4 no-subgroups-; done
measure 120 --sizes "$s1" --methods multilayer:4x4
if [ -n "${BASE_DOF:-}" ]; then
  step 130 bash tools/gpu_compare.sh "$m/compare" "$BASE_DOF" "$dof" --sizes "$s1" --methods multilayer:4x4 --deadline 110 >> "$log" 2>&1
fi
step 60 "$dof" stress --backend vulkan > "$m/stress-vulkan.log" 2>&1
echo "stress exit $?" | tee -a "$log"
for scene in simple railing fence; do span_only 30 "$s2" "$scene" multilayer 4x4; done
orbit "$s1" --span-only
orbit "$s1"
orbit "$s2" --span-only
for input in images copied-images; do
  image_input "$s1" ring-gather none "$input"
  image_input "$s1" tiled 4x4 "$input"
done
measure 150 --sizes "$s2" --methods multilayer:4x4,ring-gather:none
measure 150 --sizes "$s1" --methods ring-gather:none,multilayer:none,multilayer:2x2,tiled:4x4,bokeh:none,layered:none,raytrace:none
orbit "$s2"
no_footprints "$s1"
ratios 100 "$s1"
measure 60 --sizes "$s1" --methods gather:none --frames 5 --warmup 1
measure 120 --sizes "$s2" --methods multilayer:none,tiled:4x4,layered:none,raytrace:none --frames 5 --warmup 1
ratios 150 "$s2"
finish
