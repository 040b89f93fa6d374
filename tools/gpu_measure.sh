#!/usr/bin/env bash
# One command for the GPU figures (the per-stage table in the shape of Franke et al.
# 2018, Table 1, at 1920x1080 and 3840x2160, and the ratios against the ring gather):
#
#   bash tools/gpu_measure.sh OUT_DIR [--quick] [--backend vulkan|cpu] [--frames N] [--warmup N]
#        [--spp N] [--scenes simple,fence] [--sizes 1920x1080,3840x2160]
#        [--methods multilayer:4x4,ring-gather:none] [--no-ratios]
#
# For every built-in scene, size and method it runs `dof bench frame --json` (frame time: the
# median of one span, a GPU timestamp pair on Vulkan, around the whole recording, over --frames
# frames after 2 warm-up frames; per-stage times; dispatches and barriers per frame; device bytes),
# then `dof bench ratios` at each size. It writes into OUT_DIR:
#   frame-<scene>-<W>x<H>-<method>.json (and .err, the command's stderr), ratios-<W>x<H>/ (the
#   ratio bench's report.{md,json}), device.txt (`dof info`), summary.md (one table per size:
#   frame time median/p10/p90, the Table 1 columns, dispatches, barriers, MB) and run.log.
# A failing run is logged and skipped, so one refused size (a device limit) does not end the
# sweep. Copy OUT_DIR into docs/gpu/ with the device's name. --quick runs 320x180 and 160x90,
# 3 frames after 1 warm-up, a 4-spp reference: what lavapipe can finish, to test the script itself.
# --scenes, --sizes and --methods narrow the sweep (method:merge, as in the list below), and
# --no-ratios leaves out the ratio bench, so a short run can do the sweep in parts into one
# OUT_DIR (the log is appended to; summary.md is made from every JSON there). DOF=path/to/dof
# skips the build.
set -uo pipefail
cd "$(dirname "$0")/.."

out=""
backend=vulkan
quick=0
frames=20
warmup=2
spp=64
scenes="simple railing columns highlights fence edges"
sizes=""
methods=""
ratios=1
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --backend) backend="$2"; shift ;;
    --frames) frames="$2"; shift ;;
    --spp) spp="$2"; shift ;;
    --scenes) scenes="${2//,/ }"; shift ;;
    --sizes) sizes="${2//,/ }"; shift ;;
    --methods) methods="${2//,/ }"; shift ;;
    --warmup) warmup="$2"; shift ;;
    --no-ratios) ratios=0 ;;
    -h|--help) sed -n 2,20p "$0"; exit 0 ;;
    -*) echo "error: unknown option $1" >&2; exit 2 ;;
    *) [ -z "$out" ] || { echo "error: one output folder, got $out and $1" >&2; exit 2; }; out="$1" ;;
  esac
  shift
done
[ -n "$out" ] || { echo "usage: bash tools/gpu_measure.sh OUT_DIR [--quick] [--backend vulkan|cpu] [--frames N] [--spp N]" >&2; exit 2; }
case "$backend" in vulkan|cpu) ;; *) echo "error: --backend is vulkan or cpu, got $backend" >&2; exit 2 ;; esac
if [ "$quick" = 1 ]; then
  sizes=${sizes:-320x180 160x90}; frames=3; warmup=1; spp=4
else
  sizes=${sizes:-1920x1080 3840x2160}
fi
# method and merge setting; the merge flag is ignored by the methods that do not splat.
methods=${methods:-multilayer:4x4 multilayer:none tiled:4x4 ring-gather:none gather:none bokeh:none layered:none raytrace:none}

mkdir -p "$out" || exit 1
log="$out/run.log"
touch "$log"
# DOF=path/to/dof uses a binary built before (the device machine may have no toolchain).
dof=${DOF:-}
if [ -z "$dof" ]; then
  echo "== building the release binary (the profile a user builds)" | tee -a "$log"
  cargo build --release -p dof-cli --no-default-features 2>&1 | tail -n 3 | tee -a "$log"
  dof=target/release/dof
fi
[ -x "$dof" ] || { echo "error: $dof was not built" | tee -a "$log" >&2; exit 1; }
[ -s "$out/device.txt" ] || "$dof" info > "$out/device.txt" 2>&1 || true
failed=0
for size in $sizes; do
  w=${size%x*}; h=${size#*x}
  for scene in $scenes; do
    for m in $methods; do
      method=${m%:*}; merge=${m#*:}
      name="frame-$scene-$size-$method"; [ "$method" = multilayer ] && name="$name-$merge"
      echo "$name" | tee -a "$log"
      if ! "$dof" bench frame --backend "$backend" --scene "$scene" --width "$w" --height "$h" \
          --method "$method" --merge "$merge" --frames "$frames" --warmup "$warmup" --json > "$out/$name.json" 2> "$out/$name.err"; then
        echo "  failed: $(tail -n 1 "$out/$name.err")" | tee -a "$log"
        rm -f "$out/$name.json"
        failed=$((failed + 1))
      fi
    done
  done
  [ "$ratios" = 1 ] || continue
  echo "ratios-$size" | tee -a "$log"
  if ! "$dof" bench ratios --backend "$backend" --scenes "${scenes// /,}" --width "$w" --height "$h" --spp "$spp" --runs 3 \
      --out "$out/ratios-$size" > "$out/ratios-$size.log" 2>&1; then
    echo "  failed: $(tail -n 1 "$out/ratios-$size.log")" | tee -a "$log"
    failed=$((failed + 1))
  fi
done

# One table per size from the JSON.
python3 tools/gpu_summary.py "$out" > "$out/summary.md"
echo "wrote $out/summary.md; $failed run(s) failed (see $log)" | tee -a "$log"
