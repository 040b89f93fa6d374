#!/usr/bin/env python3
"""One table per size from the JSON that tools/gpu_measure.sh writes: python3 tools/gpu_summary.py OUT_DIR > OUT_DIR/summary.md
(standard library only)."""
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
