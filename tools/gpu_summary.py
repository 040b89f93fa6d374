#!/usr/bin/env python3
"""One table per size from the JSON that tools/gpu_measure.sh writes: python3 tools/gpu_summary.py OUT_DIR > OUT_DIR/summary.md
(standard library only)."""
import glob, json, math, os, sys
from figures import bench_runs, image_input_rows, ms_cell  # tools/figures.py, beside this script
out = sys.argv[1]
rows = {}
for r in bench_runs(out, "frame-"):
    rows.setdefault((r["width"], r["height"]), []).append(r)
def ms(v):
    return "-" if v is None else f"{v:.3f}"
for (w, h), rs in sorted(rows.items()):
    dev = rs[0]["device"]
    print(f"## {w}x{h} on {dev} ({rs[0]['backend']})\n")
    print("Frame time: median (p10-p90) of one span around the whole recording, over "
          f"{rs[0]['frame_ms_frames']} frames after {rs[0].get('warmup_frames_run', rs[0]['warmup_frames'])} warm-up; the columns of "
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

# The ratio the goals name, measured as they say (`dof bench frame`: one span around each frame's
# recording, no guard band), with the PSNRs of `dof bench ratios` where its report is there.
by = {}
for rs in rows.values():
    for r in rs:
        by[(r["width"], r["height"], r["scene"], r["method"], r["merge"])] = r
psnr = {}
for path in glob.glob(os.path.join(out, "ratios-*", "ratios.json")):
    with open(path) as f:
        report = json.load(f)
    for row in report if isinstance(report, list) else report.get("rows", []):
        size = os.path.basename(os.path.dirname(path))[len("ratios-"):]
        psnr[(size, row["scene"])] = row
for (w, h) in sorted(rows):
    scenes = sorted({s for (W, H, s, _, _) in by if (W, H) == (w, h)})
    lines = []
    for s in scenes:
        ml, rg = by.get((w, h, s, "multilayer", "4x4")), by.get((w, h, s, "ring-gather", "none"))
        if ml is None or rg is None:
            continue
        p = psnr.get((f"{w}x{h}", s))
        def db(key):
            return "-" if p is None else f"{p[key]['psnr_db']:.2f} / {p[key]['psnr_masked_db']:.2f}"
        lines.append(f"| {s} | {ml['frame_ms']:.3f} | {rg['frame_ms']:.3f} | {ml['frame_ms'] / rg['frame_ms']:.2f} "
                     f"| {db('multilayer')} | {db('ring_gather')} |")
    if lines:
        print(f"## Multi-layer (merged 4x4) over the ring gather, {w}x{h}\n")
        print("Frame times from the table above; PSNR (full frame / partial-occlusion region) from `dof bench ratios` "
              "at the same size where it ran (16-spp exact reference).\n")
        print("| scene | multilayer ms | ring gather ms | ratio | multilayer PSNR (dB) | ring gather PSNR (dB) |")
        print("|---|---|---|---|---|---|")
        print("\n".join(lines))
        print()

# What bringing a renderer's colour and depth images in costs (`dof bench frame --input images`
# and `--input copied-images`, per stage), beside the frame it feeds.
inputs = [f"| {inp} | {scene} | {size} | {method} | {ms_cell(copies)} | {convert:.3f} | {total:.3f} | "
          f"{100 * (convert + (0 if math.isnan(copies) else copies)) / total:.1f}% |"
          for inp, scene, size, method, copies, convert, total in image_input_rows(out)]
if inputs:
    print("## Colour and depth images brought in\n")
    print("RGBA16F colour and D32 depth read in place, or copied into the context's buffers first, and converted to "
          "one slot a pixel, each frame (per-stage means, each command's own timestamp pair).\n")
    print("| input | scene | size | method | copies ms | conversion ms | frame's commands ms | share |")
    print("|---|---|---|---|---|---|---|---|")
    print("\n".join(inputs))
    print()

# The subgroup variants: the same span-only frames with every kernel run without subgroup
# operations (DOF_SUBGROUPS=off), beside those with them.
spans = {}
for prefix in ("span-", "no-subgroups-span-"):
    for r in bench_runs(out, prefix):
        spans[(prefix, r["scene"], r["width"], r["height"], r["method"], r["merge"])] = r
pairs = []
for (prefix, scene, w, h, method, merge), off in sorted(spans.items()):
    on = spans.get(("span-", scene, w, h, method, merge))
    if prefix == "no-subgroups-span-" and on and on["frame_ms"] and off["frame_ms"]:
        pairs.append(f"| {scene} | {w}x{h} | {method} {merge} | {ms(on['frame_ms'])} | {ms(off['frame_ms'])} "
                     f"| {off['frame_ms'] / on['frame_ms']:.2f} |")
if pairs:
    print("## Subgroups\n")
    print("Span-only frame times (median ms) with the kernels' subgroup variants and without them (`DOF_SUBGROUPS=off`).\n")
    print("| scene | size | method | with subgroups | without | without / with |")
    print("|---|---|---|---|---|---|")
    print("\n".join(pairs))
    print()

