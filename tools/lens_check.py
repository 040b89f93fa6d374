#!/usr/bin/env python3
"""Checks that an exported Mitsuba 3 sensor is the project's thin lens.

    python3 tools/lens_check.py [--scenes fence,edges] [--width 320 --height 240] [--spp 1024]

1. Pinhole: the exported scene with the aperture radius set to 0 against the project's reference
   with `--aperture-radius 0` (`dof compare`): the same camera, not mirrored or shifted.
2. Circle of confusion: the exported sensor looking at one emissive half-plane (its edge through
   the image centre) at depth z; the edge's blur width gives the CoC diameter, to compare with the
   project's model coc_px(z) = K·|1 − z_f/z| (`ThinLens::coc_px`). For a uniform disc of diameter D
   the edge's line spread has variance D²/16; the box pixel filter and the difference of adjacent
   pixels add 1/6 px², so D = 4·sqrt(var − 1/6). Also with the aperture 8 times larger, where the
   CoC behind the focus plane is wide enough to measure.

Needs Mitsuba 3 and numpy (pip install mitsuba numpy).
"""

import argparse
import math
import xml.etree.ElementTree as ET
from pathlib import Path

from dof_tools import compare, dof_binary, export_scenes, fail, psnr, render_mitsuba, require_mitsuba, run, write_exr


def parse():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scenes", default="fence,edges")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=240)
    p.add_argument("--spp", type=int, default=1024)
    p.add_argument("--variant", default="auto")
    p.add_argument("--out", default="out/lens-check", type=Path)
    p.add_argument("--dof")
    p.add_argument("--pinhole-only", action="store_true", help="skip the circle-of-confusion measurement")
    return p.parse_args()


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def set_float(root, name, value):
    node = root.find(f".//sensor/float[@name='{name}']")
    node.set("value", repr(value))


def edge_scene(xml, meta, z, radius):
    """The exported file's sensor (aperture `radius`) looking at an emissive half-plane: image
    x < centre at planar depth z, radiance 1, black elsewhere."""
    root = ET.parse(xml).getroot()
    for node in list(root):
        if node.tag in ("shape", "emitter"):
            root.remove(node)
    set_float(root, "aperture_radius", radius)
    set_float(root, "far_clip", 10.0 * z)
    eye, target, up = meta["eye"], meta["target"], meta["up"]
    f = unit(sub(target, eye))
    r = unit(cross(f, up))
    u = cross(r, f)
    t = math.tan(math.radians(meta["yfov_degrees"]) / 2)
    s = 4 * z * t * meta["width"] / meta["height"] + 4 * radius * (1 + z / meta["lens"]["focus_distance"])
    center = [e + z * fi - s * ri for e, fi, ri in zip(eye, f, r)]
    cols = [[s * x for x in r], [s * x for x in u], [-x for x in f], center]
    matrix = " ".join(repr(cols[c][row]) for row in range(3) for c in range(4)) + " 0 0 0 1"
    shape = ET.SubElement(root, "shape", type="rectangle")
    ET.SubElement(ET.SubElement(shape, "transform", name="to_world"), "matrix", value=matrix)
    ET.SubElement(shape, "ref", id="black")
    ET.SubElement(ET.SubElement(shape, "emitter", type="area"), "rgb", name="radiance", value="1, 1, 1")
    return ET.tostring(root, encoding="unicode")


def blur_diameter(np, image):
    """CoC diameter (px) from the blur of a vertical edge, bright on the left (module docs)."""
    h = image.shape[0]
    profile = image[h // 4: 3 * h // 4, :, :].mean(axis=(0, 2))
    spread = profile[:-1] - profile[1:]
    x = np.arange(spread.size)
    mean = (spread * x).sum() / spread.sum()
    var = (spread * (x - mean) ** 2).sum() / spread.sum()
    return 4 * math.sqrt(max(var - 1 / 6, 0.0))


def main():
    args = parse()
    mi, variant = require_mitsuba(args.variant)
    try:
        import numpy as np
    except ImportError:
        fail("the lens check needs numpy: pip install numpy")
    dof = dof_binary(args.dof)
    names = args.scenes.split(",")
    metas = export_scenes(dof, names, args.width, args.height, args.out / "mitsuba")
    for name in names:
        meta = metas[name]
        if not meta["exported"]:
            print(f"{name}: not exported ({meta['reason']})")
            continue
        xml = args.out / "mitsuba" / f"{name}.xml"
        lens = meta["lens"]
        folder = args.out / name
        folder.mkdir(parents=True, exist_ok=True)
        # 1. Pinhole.
        root = ET.parse(xml).getroot()
        set_float(root, "aperture_radius", 0.0)
        pinhole_xml = folder / "pinhole.xml"
        ET.ElementTree(root).write(pinhole_xml)
        write_exr(mi, render_mitsuba(mi, pinhole_xml, args.spp, 1), folder / "mitsuba-pinhole.exr")
        ok, out, _ = run([dof, "render", "--scene", name, "--width", args.width, "--height", args.height,
                          "--method", "reference", "--aperture-radius", 0, "--samples", args.spp, "--out", folder / "pinhole.exr"])
        c = compare(dof, folder / "pinhole.exr", folder / "mitsuba-pinhole.exr") if ok else None
        print(f"{name} ({variant}, {args.spp} spp): pinhole, Mitsuba against the project: "
              f"PSNR {psnr(c['psnr_db']):.2f} dB, FLIP {c['flip']:.4f}" if c else f"{name}: pinhole render failed")
        if args.pinhole_only:
            continue
        # 2. CoC from edge blur.
        print(f"  CoC diameter (px), model K·|1 − z_f/z| with K = {lens['far_limit_px']:.3f} px, z_f = {lens['focus_distance']}:")
        print("  | aperture | z | model | Mitsuba edge | difference |")
        print("  |---|---|---|---|---|")
        zf = lens["focus_distance"]
        for scale, depths in [(1, [1.0, 1.5, 3.0, 6.0]), (8, [2.0 * zf, 10.0 * zf, 1000.0 * zf])]:
            radius = lens["aperture_radius"] * scale
            for z in depths:
                text = edge_scene(xml, meta, z, radius)
                scene = mi.load_string(text, spp=args.spp)
                image = np.array(mi.render(scene, seed=3, spp=args.spp))
                measured = blur_diameter(np, image)
                model = scale * lens["far_limit_px"] * abs(1 - zf / z)
                print(f"  | {scale}R | {z:g} | {model:.3f} | {measured:.3f} | {measured - model:+.3f} |")


if __name__ == "__main__":
    main()
