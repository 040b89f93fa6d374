#!/usr/bin/env bash
# A kernel change against its baseline on one GPU, in one run: `dof bench frame` of two builds,
# interleaved scene by scene (baseline, change, baseline again), so that clock changes and other
# drift show as a spread between the two baseline runs instead of passing for a speed-up.
#
#   bash tools/gpu_compare.sh OUT_DIR BASE_DOF NEW_DOF [--sizes 1920x1080,3840x2160]
#        [--methods multilayer:4x4,multilayer:2x2] [--scenes simple,fence] [--frames 20]
#        [--warmup 30] [--deadline SECONDS]
#
# Writes OUT_DIR/<label>-<scene>-<W>x<H>-<method>-<merge>.json (labels base, new, base2) and
# compare.md: per row the three frame times (median over --frames after --warmup frames; GPUs
# raise their clocks over the first frames, so the warm-up is long) and new/base. No run starts
# past --deadline seconds (default 400), so a short run still brings back the rows done.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:?output folder}; base=${2:?baseline dof}; new=${3:?new dof}; shift 3
sizes="1920x1080 3840x2160"
methods="multilayer:4x4 multilayer:2x2"
scenes="simple railing columns highlights fence edges"
frames=20; warmup=30; deadline=400
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="${2//,/ }"; shift ;;
    --methods) methods="${2//,/ }"; shift ;;
    --scenes) scenes="${2//,/ }"; shift ;;
    --frames) frames="$2"; shift ;;
    --warmup) warmup="$2"; shift ;;
    --deadline) deadline="$2"; shift ;;
    *) echo "error: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"
end=$(( $(date +%s) + deadline ))
for size in $sizes; do
  w=${size%x*}; h=${size#*x}
  for scene in $scenes; do
    for m in $methods; do
      method=${m%:*}; merge=${m#*:}
      for run in base:$base new:$new base2:$base; do
        label=${run%%:*}; dof=${run#*:}
        [ "$(date +%s)" -lt "$end" ] || { echo "skipped (deadline): $label $scene $size $m"; continue; }
        name="$label-$scene-$size-$method-$merge"
        timeout 60 "$dof" bench frame --backend vulkan --scene "$scene" --width "$w" --height "$h" --method "$method" \
          --merge "$merge" --frames "$frames" --warmup "$warmup" --json > "$out/$name.json" 2> "$out/$name.err" \
          || { echo "failed: $name: $(tail -n 1 "$out/$name.err")"; rm -f "$out/$name.json"; }
        [ -s "$out/$name.err" ] || rm -f "$out/$name.err"
      done
    done
  done
done
python3 - "$out" > "$out/compare.md" <<'EOF'
import glob, json, os, sys
out = sys.argv[1]
runs = {}
for path in glob.glob(os.path.join(out, "*.json")):
    label, rest = os.path.basename(path)[:-5].split("-", 1)
    with open(path) as f:
        runs.setdefault(rest, {})[label] = json.load(f)
print("| scene | size | method | merge | base ms | new ms | base again ms | new / base | stages base → new (merge, splat, sort, apply) | MB base → new |")
print("|---|---|---|---|---|---|---|---|---|---|")
for key in sorted(runs):
    r = runs[key]
    any_run = next(iter(r.values()))
    def ms(label):
        return r[label]["frame_ms"] if label in r else None
    def f(v):
        return "-" if v is None else f"{v:.3f}"
    bases = [v for v in (ms("base"), ms("base2")) if v is not None]
    ratio = f"{ms('new') / min(bases):.2f}" if bases and ms("new") is not None else "-"
    def t1(label):
        if label not in r:
            return "-"
        t = r[label]["table1_ms"]
        return "/".join(f"{t[k]:.2f}" for k in ("merge", "splat", "sort", "apply"))
    def mb(label):
        return "-" if label not in r else f"{r[label]['device_bytes'] / 1e6:.1f}"
    print(f"| {any_run['scene']} | {any_run['width']}x{any_run['height']} | {any_run['method']} | {any_run['merge']} "
          f"| {f(ms('base'))} | {f(ms('new'))} | {f(ms('base2'))} | {ratio} | {t1('base')} → {t1('new')} | {mb('base')} → {mb('new')} |")
EOF
cat "$out/compare.md"
