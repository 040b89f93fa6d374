#!/usr/bin/env bash
# One command for the GPU figures of issue 24 (the per-stage table in the shape of Franke et al.
# 2018, Table 1, at 1920x1080 and 3840x2160, and the ratios against the ring gather):
#
#   bash tools/gpu_measure.sh OUT_DIR [--quick] [--backend vulkan|cpu] [--frames N] [--spp N]
#                                     [--scenes simple,fence]
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
# --scenes narrows the built-in scenes (default: all six). DOF=path/to/dof skips the build.
set -uo pipefail
cd "$(dirname "$0")/.."

out=""
backend=vulkan
quick=0
frames=20
warmup=2
spp=64
scenes="simple railing columns highlights fence edges"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --backend) backend="$2"; shift ;;
    --frames) frames="$2"; shift ;;
    --spp) spp="$2"; shift ;;
    --scenes) scenes="${2//,/ }"; shift ;;
    -h|--help) sed -n 2,20p "$0"; exit 0 ;;
    -*) echo "error: unknown option $1" >&2; exit 2 ;;
    *) [ -z "$out" ] || { echo "error: one output folder, got $out and $1" >&2; exit 2; }; out="$1" ;;
  esac
  shift
done
[ -n "$out" ] || { echo "usage: bash tools/gpu_measure.sh OUT_DIR [--quick] [--backend vulkan|cpu] [--frames N] [--spp N]" >&2; exit 2; }
case "$backend" in vulkan|cpu) ;; *) echo "error: --backend is vulkan or cpu, got $backend" >&2; exit 2 ;; esac
if [ "$quick" = 1 ]; then
  sizes="320x180 160x90"; frames=3; warmup=1; spp=4
else
  sizes="1920x1080 3840x2160"
fi
# method and merge setting; the merge flag is ignored by the methods that do not splat.
methods="multilayer:4x4 multilayer:none tiled:4x4 ring-gather:none gather:none bokeh:none layered:none raytrace:none"

mkdir -p "$out" || exit 1
log="$out/run.log"
: > "$log"
# DOF=path/to/dof uses a binary built before (the device machine may have no toolchain).
dof=${DOF:-}
if [ -z "$dof" ]; then
  echo "== building the release binary (the profile a user builds)" | tee -a "$log"
  cargo build --release -p dof-cli --no-default-features 2>&1 | tail -n 3 | tee -a "$log"
  dof=target/release/dof
fi
[ -x "$dof" ] || { echo "error: $dof was not built" | tee -a "$log" >&2; exit 1; }
"$dof" info > "$out/device.txt" 2>&1 || true
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
  echo "ratios-$size" | tee -a "$log"
  if ! "$dof" bench ratios --backend "$backend" --scenes "${scenes// /,}" --width "$w" --height "$h" --spp "$spp" --runs 3 \
      --out "$out/ratios-$size" > "$out/ratios-$size.log" 2>&1; then
    echo "  failed: $(tail -n 1 "$out/ratios-$size.log")" | tee -a "$log"
    failed=$((failed + 1))
  fi
done

# One table per size from the JSON (python3, standard library only).
python3 - "$out" > "$out/summary.md" <<'EOF'
import glob, json, os, sys
out = sys.argv[1]
rows = {}
for path in sorted(glob.glob(os.path.join(out, "frame-*.json"))):
    with open(path) as f:
        r = json.load(f)
    rows.setdefault((r["width"], r["height"]), []).append(r)
def ms(v):
    return "-" if v is None else f"{v:.3f}"
for (w, h), rs in sorted(rows.items()):
    dev = rs[0]["device"]
    print(f"## {w}x{h} on {dev} ({rs[0]['backend']})\n")
    print("Frame time: median (p10-p90) of one span around the whole recording, over "
          f"{rs[0]['frame_ms_frames']} frames after {rs[0]['warmup_frames']} warm-up; the columns of "
          "Franke et al. 2018, Table 1: per-stage means, each command's own timestamp pair.\n")
    print("| scene | method | merge | frame ms (p10-p90) | merge | splat | sort | apply | dispatches | barriers | MB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rs, key=lambda r: (r["scene"], r["method"], r["merge"])):
        t = r["table1_ms"]
        merge = r["merge"] if r["method"] in ("multilayer", "tiled") else "-"
        print(f"| {r['scene']} | {r['method']} | {merge} | {ms(r['frame_ms'])} ({ms(r['frame_ms_p10'])}-{ms(r['frame_ms_p90'])}) "
              f"| {ms(t['merge'])} | {ms(t['splat'])} | {ms(t['sort'])} | {ms(t['apply'])} "
              f"| {r['dispatches_per_frame']:.0f} | {r['barriers_per_frame']:.0f} | {r['device_bytes'] / 1e6:.1f} |")
    print()
EOF
echo "wrote $out/summary.md; $failed run(s) failed (see $log)" | tee -a "$log"
