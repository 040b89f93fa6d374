#!/usr/bin/env python3
"""Independent check: the project's exact reference and every method against Mitsuba 3 (Jakob et
al. 2022) on built-in scenes that export exactly (emissive-only surfaces, the same thin lens, a box
pixel filter; translucent surfaces as a `mask` BSDF of opacity alpha over an emitter of alpha times
the radiance, which is glTF's "over"; see host/src/scene/mitsuba_export.rs).

    python3 tools/independent_check.py [--scenes fence,edges] [--width 320 --height 240]
        [--spp 4096] [--reference-spp 1024] [--backend cpu] [--out out/independent] [--mitsuba-cache DIR]

Per scene: Mitsuba renders two independent halves (different seeds), whose PSNR against each other
gives the noise of their pooled mean (+6.02 dB for equal halves, as host/src/scene/reference.rs);
`dof render` renders the reference and each method; `dof compare` measures each against the pooled
Mitsuba image, full frame and inside the partial-occlusion region (the `mask` plane of the
reference render). Writes OUT/table.md and OUT/table.json and prints the table.
"""

import argparse
import json
import math
import re
import sys
import time
from pathlib import Path

from dof_tools import compare, dof_binary, export_scenes, psnr, render_mitsuba, require_mitsuba, run, write_exr

SCENES = ["simple", "railing", "columns", "highlights", "fence", "edges", "panes", "foliage", "glass"]

# (row name, `dof render` arguments after the scene and size)
METHODS = [
    ("pinhole", ["--method", "pinhole"]),
    ("gather", ["--method", "gather"]),
    ("ring-gather", ["--method", "ring-gather"]),
    ("bokeh", ["--method", "bokeh"]),
    ("tiled", ["--method", "tiled"]),
    ("multilayer", ["--method", "multilayer"]),
    ("multilayer --merge 4x4", ["--method", "multilayer", "--merge", "4x4"]),
    ("layered", ["--method", "layered"]),
    ("raytrace --spp 16", ["--method", "raytrace", "--spp", "16"]),
]
REFERENCE_ROW = "project reference vs Mitsuba"

# Reference noise must lie this far above a measured PSNR to bias it by at most 0.5 dB
# (10·log10(1/(10^0.05 − 1)), host/src/scene/reference.rs).
MARGIN_DB = 9.14


def parse():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default=",".join(SCENES), help="built-in scenes (comma-separated); those that do not export exactly are listed as skipped")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=240)
    p.add_argument("--spp", type=int, default=4096, help="Mitsuba samples per pixel, in two halves (default 4096: noise above 49 dB on the emissive scenes)")
    p.add_argument("--reference-spp", type=int, default=1024,
                   help="samples of the project's reference (default 1024; 0: its automatic count, which aims at 49 dB of noise)")
    p.add_argument("--backend", default="cpu", choices=["cpu", "vulkan"], help="backend of the project's methods")
    p.add_argument("--variant", default="auto", help="Mitsuba variant (default: llvm_ad_rgb if it runs, else scalar_rgb)")
    p.add_argument("--out", default="out/independent", type=Path)
    p.add_argument("--mitsuba-cache", type=Path,
                   help="reuse Mitsuba's halves from DIR/SCENE-WxH-SPPspp-VARIANT when there (they depend on the scene, size, spp and variant only), else render and store them there; without it they are always rendered")
    p.add_argument("--dof", help="a built dof binary (default: build the dev profile, as `cargo run --bin dof` does)")
    return p.parse_args()


def mitsuba_halves(mi, xml, spp, folder, reuse):
    """Two independent halves and their pooled mean, as EXRs in `folder`; with `reuse` (a
    `--mitsuba-cache` folder, named for the scene, size, samples and variant) those already there
    are taken as they are. Returns (paths, samples, seconds)."""
    start = time.perf_counter()
    n = [spp - spp // 2, spp // 2]
    paths = [folder / "mitsuba-a.exr", folder / "mitsuba-b.exr", folder / "mitsuba.exr"]
    if reuse and all(path.exists() for path in paths):
        return paths, n, 0.0
    halves = [render_mitsuba(mi, xml, k, seed) for k, seed in zip(n, (1, 2))]
    pooled = (halves[0] * n[0] + halves[1] * n[1]) / (n[0] + n[1])
    folder.mkdir(parents=True, exist_ok=True)
    for image, path in zip(halves + [pooled], paths):
        write_exr(mi, image, path)
    return paths, n, time.perf_counter() - start


def noise(dof, halves, n, mask_from):
    """PSNR of the pooled mean against the converged image, full frame and in the region:
    PSNR(a, b) + 10·log10((1/n_a + 1/n_b)(n_a + n_b))."""
    c = compare(dof, halves[0], halves[1], mask_from)
    if c is None:
        return None, None
    gain = 10 * math.log10((1 / n[0] + 1 / n[1]) * (n[0] + n[1]))
    region = psnr(c["psnr_masked_db"]) + gain if c["masked_pixels"] else None
    return psnr(c["psnr_db"]) + gain, region


def fmt(v, digits=2):
    if v is None:
        return "-"
    return "inf" if v == float("inf") else f"{v:.{digits}f}"


def check_scene(dof, mi, args, name, meta, xml):
    folder = args.out / name
    folder.mkdir(parents=True, exist_ok=True)
    size = ["--width", args.width, "--height", args.height]
    print(f"{name}: Mitsuba, {args.spp} spp in two halves...", file=sys.stderr)
    cache = args.mitsuba_cache / f"{name}-{args.width}x{args.height}-{args.spp}spp-{mi.variant()}" if args.mitsuba_cache else folder
    (half_a, half_b, mitsuba), n, mitsuba_s = mitsuba_halves(mi, xml, args.spp, cache, reuse=args.mitsuba_cache is not None)
    result = {"scene": name, "width": args.width, "height": args.height, "mitsuba_spp": args.spp,
              "mitsuba_seconds": round(mitsuba_s, 1), "notes": meta["notes"], "rows": []}
    print(f"{name}: project reference...", file=sys.stderr)
    reference = folder / "reference.exr"
    ref_cmd = [dof, "render", "--scene", name, *size, "--method", "reference", "--out", reference]
    if args.reference_spp > 0:
        ref_cmd += ["--samples", args.reference_spp]
    ok, out, seconds = run(ref_cmd)
    if not ok:
        result["error"] = f"the project reference failed: {out.strip().splitlines()[-1:]}"
        return result
    m = re.search(r"reference: (\d+) samples per pixel, estimated noise PSNR ([0-9.]+) dB", out)
    result["reference_spp"], result["reference_noise_db"] = (int(m.group(1)), float(m.group(2))) if m else (None, None)
    result["reference_seconds"] = round(seconds, 1)
    full, region = noise(dof, [half_a, half_b], n, reference)
    result["mitsuba_noise_db"], result["mitsuba_noise_region_db"] = full, region
    # Two unbiased images differ by their noise alone: the PSNR that agreement would give.
    if full is not None and result["reference_noise_db"] is not None:
        result["noise_alone_db"] = -10 * math.log10(10 ** (-full / 10) + 10 ** (-result["reference_noise_db"] / 10))
    rows = [(REFERENCE_ROW, reference, seconds)]
    for row, method_args in METHODS:
        print(f"{name}: {row}...", file=sys.stderr)
        path = folder / (row.replace(" --", "-").replace(" ", "-") + ".exr")
        ok, out, seconds = run([dof, "render", "--scene", name, *size, *method_args, "--backend", args.backend, "--out", path])
        rows.append((row, path if ok else None, seconds if ok else None))
    for row, path, seconds in rows:
        c = compare(dof, mitsuba, path, reference) if path else None
        entry = {"method": row, "seconds": None if seconds is None else round(seconds, 2)}
        if c is None:
            entry["error"] = "render or compare failed"
        else:
            entry.update(psnr_db=psnr(c["psnr_db"]), psnr_region_db=psnr(c["psnr_masked_db"]) if c["masked_pixels"] else None,
                         flip=c["flip"], flip_region=c["flip_masked"], ssim=c["ssim"], region_pixels=c["masked_pixels"])
        result["rows"].append(entry)
    return result


def markdown(results, skipped, variant, mitsuba_version):
    lines = [f"Against Mitsuba {mitsuba_version} ({variant}, thinlens, box filter, emissive-only surfaces); "
             f"PSNR in dB and FLIP on the project's display transform (`dof compare`); region: the partial-occlusion "
             f"region of the project's reference. A PSNR is measured within 0.5 dB while it stays {MARGIN_DB} dB below "
             f"the noise of the Mitsuba image.", ""]
    for r in results:
        heading = f"### {r['scene']} ({r['width']}x{r['height']})"
        if "error" in r:
            lines += [heading, "", f"failed: {r['error']}", ""]
            continue
        lines += [heading, "",
                  f"Mitsuba: {r['mitsuba_spp']} spp in {r['mitsuba_seconds']} s; its noise (from two independent halves): "
                  f"PSNR {fmt(r['mitsuba_noise_db'])} dB full frame, {fmt(r['mitsuba_noise_region_db'])} dB in the region. "
                  f"Project reference: {r['reference_spp']} spp, its own noise {fmt(r['reference_noise_db'])} dB full frame; "
                  f"the two noises alone would give {fmt(r.get('noise_alone_db'))} dB between them.", "",
                  "| method | PSNR full (dB) | PSNR region (dB) | FLIP full | FLIP region |", "|---|---|---|---|---|"]
        for row in r["rows"]:
            if "error" in row:
                lines.append(f"| {row['method']} | {row['error']} | | | |")
            else:
                lines.append(f"| {row['method']} | {fmt(row['psnr_db'])} | {fmt(row['psnr_region_db'])} | "
                             f"{fmt(row['flip'], 4)} | {fmt(row['flip_region'], 4)} |")
        lines.append("")
    for name, why in skipped.items():
        lines.append(f"- `{name}` not exported: {why}")
    return "\n".join(lines).rstrip() + "\n"


def finite(value):
    """The summary as strict JSON: an infinite PSNR (identical images) becomes the string "inf"."""
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    if isinstance(value, dict):
        return {k: finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [finite(v) for v in value]
    return value


def main():
    args = parse()
    mi, variant = require_mitsuba(args.variant)
    names = [s for s in args.scenes.split(",") if s]
    start = time.perf_counter()
    dof = dof_binary(args.dof)
    args.out.mkdir(parents=True, exist_ok=True)
    metas = export_scenes(dof, names, args.width, args.height, args.out / "mitsuba")
    skipped = {n: m["reason"] for n, m in metas.items() if not m["exported"]}
    results = []
    for name in names:
        if name in skipped:
            print(f"{name}: skipped, {skipped[name]}", file=sys.stderr)
            continue
        results.append(check_scene(dof, mi, args, name, metas[name], args.out / "mitsuba" / f"{name}.xml"))
    table = markdown(results, skipped, variant, mi.__version__)
    (args.out / "table.md").write_text(table)
    summary = {"mitsuba": mi.__version__, "variant": variant, "seconds": round(time.perf_counter() - start, 1),
               "scenes": results, "skipped": skipped}
    (args.out / "table.json").write_text(json.dumps(finite(summary), indent=2) + "\n")
    print(table)
    print(f"wrote {args.out / 'table.md'} and {args.out / 'table.json'} in {summary['seconds']} s", file=sys.stderr)


if __name__ == "__main__":
    main()
