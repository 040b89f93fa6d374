#!/usr/bin/env python3
"""Texture check: the rasteriser's filtered textures against Mitsuba 3 (Jakob et al. 2022) on a
textured glTF scene built here as real assets are (a closed box whose material is double-sided,
a floor running to the horizon and a wall, 1024x1024 sRGB textures of fine detail, everything
emissive through KHR_materials_unlit).

    python3 tools/texture_check.py [--width 160 --height 120] [--spp 4096] [--subsamples 1,4,16]
        [--defocus-spp 8192] [--out out/texture-check] [--dof PATH/TO/dof]

Mitsuba sees the same triangles (OBJ) with the same images as area emitters' radiance (bilinear,
sRGB decoded), through a pinhole with a box pixel filter: at SPP samples a pixel it is the
pixel's area average of the bilinear texture. The project renders the pinhole image (`dof render
--method pinhole`, the rasterised front layer at each sub-sample count) and `dof compare`
measures it against Mitsuba's. Two Mitsuba halves (different seeds) give the reference's own noise
(their PSNR + 6.02 dB for the pooled mean).

Then defocused (`--defocus-spp` > 0): Mitsuba's `thinlens` with the same aperture radius and
planar focus distance against every blurring method, full frame and in the partial-occlusion
region (the `mask` plane of `dof render --method pinhole` with that lens), on the scene as built
(the box's material double-sided) and with every material single-sided: a closed object's inner
faces must not show through its blurred silhouette. Writes OUT/table.md and OUT/table.json.
"""

import argparse
import json
import math
import struct
import zlib
from pathlib import Path

import numpy as np

from dof_tools import compare, dof_binary, psnr, require_mitsuba, run, write_exr

TEXTURE = 1024


def parse():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--spp", type=int, default=4096, help="Mitsuba samples a pixel, in two halves (4096: its noise 51 dB)")
    p.add_argument("--subsamples", default="1,4,16", help="the project's sub-sample counts to measure (4 is the default)")
    p.add_argument("--defocus-spp", type=int, default=8192, help="Mitsuba samples a pixel of the defocused check (0: skip it)")
    p.add_argument("--aperture-radius", type=float, default=0.15, help="aperture radius of the defocused check, scene units")
    p.add_argument("--focus", type=float, default=5.5, help="planar focus distance of the defocused check (the box)")
    p.add_argument("--methods", default="multilayer,tiled,gather,ring-gather,layered,scatter-gather",
                   help="methods of the defocused check")
    p.add_argument("--variant", default="auto")
    p.add_argument("--out", type=Path, default=Path("out/texture-check"))
    p.add_argument("--dof", help="the dof binary (default: build it)")
    return p.parse_args()


def write_png(path, rgb8):
    """An 8-bit RGB PNG (sRGB-encoded values, as glTF's colour textures are)."""
    h, w, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].tobytes() for y in range(h))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                     + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def textures(rng):
    """Three textures of detail finer than the pixels that see them: a checker of 4-texel cells
    under coloured stripes, thin grid lines on noise, and an asymmetric marker pattern (so a flip
    of either texture axis between the renderers shows)."""
    y, x = np.mgrid[0:TEXTURE, 0:TEXTURE]
    checker = ((x // 4 + y // 4) % 2).astype(np.float32)
    stripes = 0.5 + 0.5 * np.sin(2 * math.pi * (x + 2 * y) / 23.0)
    a = np.stack([0.15 + 0.8 * checker, 0.2 + 0.6 * stripes, 0.9 - 0.7 * checker * stripes], -1)
    noise = rng.random((TEXTURE // 8, TEXTURE // 8, 3)).repeat(8, 0).repeat(8, 1)
    grid = ((x % 16 < 2) | (y % 16 < 2)).astype(np.float32)[..., None]
    b = 0.2 + 0.5 * noise * (1 - grid) + 0.9 * grid
    quadrant = ((x < TEXTURE // 2) * 1 + (y < TEXTURE // 3) * 2).astype(np.float32)
    rings = 0.5 + 0.5 * np.cos(((x - 300) ** 2 + (y - 200) ** 2) ** 0.5 / 3.0)
    c = np.stack([0.25 * quadrant, rings, 1.0 - 0.2 * quadrant], -1)
    return [np.clip(t * 255 + 0.5, 0, 255).astype(np.uint8) for t in (a, b, c)]


def box(centre, half, turn):
    """A closed box's 6 faces as quads (corners counter-clockwise seen from outside), turned by
    `turn` radians about y."""
    c, s = math.cos(turn), math.sin(turn)
    rot = lambda p: (c * p[0] + s * p[2] + centre[0], p[1] + centre[1], -s * p[0] + c * p[2] + centre[2])
    hx, hy, hz = half
    faces = [
        [(-hx, -hy, hz), (hx, -hy, hz), (hx, hy, hz), (-hx, hy, hz)],
        [(hx, -hy, -hz), (-hx, -hy, -hz), (-hx, hy, -hz), (hx, hy, -hz)],
        [(hx, -hy, hz), (hx, -hy, -hz), (hx, hy, -hz), (hx, hy, hz)],
        [(-hx, -hy, -hz), (-hx, -hy, hz), (-hx, hy, hz), (-hx, hy, -hz)],
        [(-hx, hy, hz), (hx, hy, hz), (hx, hy, -hz), (-hx, hy, -hz)],
        [(-hx, -hy, -hz), (hx, -hy, -hz), (hx, -hy, hz), (-hx, -hy, hz)],
    ]
    return [[rot(p) for p in f] for f in faces]


def scene():
    """(name, quads, uv repeat, texture index) of every object."""
    floor = [[(-40, 0, 4.5), (40, 0, 4.5), (40, 0, -60), (-40, 0, -60)]]
    wall = [[(-40, 0, -60), (40, 0, -60), (40, 30, -60), (-40, 30, -60)]]
    return [
        ("floor", floor, (6.0, 12.0), 0),
        ("wall", wall, (4.0, 2.0), 1),
        ("box", box((0.3, 0.8, -1.5), (0.7, 0.8, 0.7), 0.6), (1.0, 1.0), 2),
    ]


def triangles(quads, repeat):
    """Positions, UVs (glTF's: origin at the image's top left) and indices of quads split in two."""
    pos, uv, idx = [], [], []
    for q in quads:
        base = len(pos)
        pos += q
        uv += [(0, repeat[1]), (repeat[0], repeat[1]), (repeat[0], 0), (0, 0)]
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return np.array(pos, np.float32), np.array(uv, np.float32), np.array(idx, np.uint32)


def write_gltf(folder, objects, camera, file="scene.gltf", double_sided=True):
    eye, yfov, aspect = camera
    binary, views, accessors, meshes, nodes, materials = bytearray(), [], [], [], [], []

    def view(data, target):
        while len(binary) % 4:
            binary.append(0)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        return len(views) - 1

    for t in range(3):
        materials.append({"pbrMetallicRoughness": {"baseColorTexture": {"index": t}, "metallicFactor": 0.0},
                          "doubleSided": double_sided, "extensions": {"KHR_materials_unlit": {}}})
    for name, quads, repeat, tex in objects:
        pos, uv, idx = triangles(quads, repeat)
        a = len(accessors)
        accessors += [
            {"bufferView": view(pos.tobytes(), 34962), "componentType": 5126, "count": len(pos), "type": "VEC3",
             "min": pos.min(0).tolist(), "max": pos.max(0).tolist()},
            {"bufferView": view(uv.tobytes(), 34962), "componentType": 5126, "count": len(uv), "type": "VEC2"},
            {"bufferView": view(idx.tobytes(), 34963), "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ]
        meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": a, "TEXCOORD_0": a + 1}, "indices": a + 2, "material": tex}]})
        nodes.append({"mesh": len(meshes) - 1})
    nodes.append({"camera": 0, "translation": list(eye)})
    (folder / "scene.bin").write_bytes(bytes(binary))
    doc = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_unlit"],
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "textures": [{"source": t, "sampler": 0} for t in range(3)],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": f"texture{t}.png"} for t in range(3)],
        "cameras": [{"type": "perspective", "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": 0.05}}],
        "buffers": [{"uri": "scene.bin", "byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    (folder / file).write_text(json.dumps(doc, indent=1))


def write_obj(path, quads, repeat):
    """The same triangles as OBJ; OBJ's texture origin is the image's bottom left, so v flips."""
    pos, uv, idx = triangles(quads, repeat)
    lines = [f"v {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}" for p in pos]
    lines += [f"vt {t[0]:.9g} {1.0 - t[1]:.9g}" for t in uv]
    lines += [f"f {a + 1}/{a + 1} {b + 1}/{b + 1} {c + 1}/{c + 1}" for a, b, c in idx.reshape(-1, 3)]
    path.write_text("\n".join(lines) + "\n")


def mitsuba_scene(mi, folder, objects, camera, width, height, lens=None):
    """The scene in Mitsuba: a pinhole, or with `lens` = (aperture radius, focus distance) a thin lens."""
    eye, yfov, _ = camera
    sensor = {"type": "perspective"} if lens is None else {"type": "thinlens", "aperture_radius": lens[0], "focus_distance": lens[1]}
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 2},
        "sensor": {
            **sensor, "fov": math.degrees(yfov), "fov_axis": "y", "near_clip": 0.01, "far_clip": 1000.0,
            "to_world": mi.ScalarTransform4f().look_at(origin=list(eye), target=[eye[0], eye[1], eye[2] - 1.0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb",
                     "component_format": "float32", "rfilter": {"type": "box"}},
            "sampler": {"type": "independent"},
        },
    }
    for name, quads, repeat, tex in objects:
        write_obj(folder / f"{name}.obj", quads, repeat)
        d[name] = {
            "type": "obj", "filename": str(folder / f"{name}.obj"), "face_normals": True,
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}},
            "emitter": {"type": "area", "radiance": {"type": "bitmap", "filename": str(folder / f"texture{tex}.png"),
                                                       "filter_type": "bilinear", "wrap_mode": "repeat", "raw": False}},
        }
    return mi.load_dict(d)


def mitsuba_halves(mi, scene, spp, out, stem):
    """Two renders of `spp / 2` samples (seeds 1 and 2), written to OUT/STEM-half0.exr and
    -half1.exr, and their mean to OUT/STEM.exr (the halves' PSNR against each other + 6.02 dB is
    the mean's noise)."""
    halves = [np.array(mi.render(scene, seed=seed, spp=spp // 2)) for seed in (1, 2)]
    for k, h in enumerate(halves):
        write_exr(mi, h, out / f"{stem}-half{k}.exr")
    write_exr(mi, 0.5 * (halves[0] + halves[1]), out / f"{stem}.exr")


def defocused(mi, dof, args, out, objects, camera):
    """Every method, with the scene double- and single-sided, against Mitsuba's thin lens."""
    lens = (args.aperture_radius, args.focus)
    write_gltf(out, objects, camera, "scene-single-sided.gltf", double_sided=False)
    ms = mitsuba_scene(mi, out, objects, camera, args.width, args.height, lens)
    mitsuba_halves(mi, ms, args.defocus_spp, out, "mitsuba-lens")
    size = ["--width", args.width, "--height", args.height, "--aperture-radius", args.aperture_radius, "--focus", args.focus]
    ok, _, _ = run([dof, "render", "--scene", out / "scene.gltf", "--method", "pinhole", *size, "--out", out / "mask.exr"])
    if not ok:
        return None
    noise = compare(dof, out / "mitsuba-lens-half0.exr", out / "mitsuba-lens-half1.exr", out / "mask.exr")
    rows = []
    for method in args.methods.split(","):
        row = {"method": method}
        for variant, scene in (("double", "scene.gltf"), ("single", "scene-single-sided.gltf")):
            image = out / f"{method}-{variant}.exr"
            ok, _, seconds = run([dof, "render", "--scene", out / scene, "--method", method, *size, "--out", image])
            c = compare(dof, out / "mitsuba-lens.exr", image, out / "mask.exr") if ok else None
            row[variant] = None if c is None else {"psnr_db": psnr(c["psnr_db"]), "region_db": psnr(c["psnr_masked_db"]), "seconds": seconds}
        rows.append(row)
    return {"rows": rows, "spp": args.defocus_spp, "aperture_radius": args.aperture_radius, "focus": args.focus,
            "noise_db": None if noise is None else psnr(noise["psnr_db"]) + 6.02,
            "noise_region_db": None if noise is None else psnr(noise["psnr_masked_db"]) + 6.02}


def fmt(v):
    return "-" if v is None else f"{v:.2f}"


def main():
    args = parse()
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    mi, variant = require_mitsuba(args.variant)
    dof = dof_binary(args.dof)
    rng = np.random.default_rng(7)
    for t, image in enumerate(textures(rng)):
        write_png(out / f"texture{t}.png", image)
    objects = scene()
    camera = ((0.0, 1.0, 4.0), math.radians(40.0), args.width / args.height)
    write_gltf(out, objects, camera)

    ms = mitsuba_scene(mi, out, objects, camera, args.width, args.height)
    mitsuba_halves(mi, ms, args.spp, out, "mitsuba")
    noise = compare(dof, out / "mitsuba-half0.exr", out / "mitsuba-half1.exr")
    noise_db = psnr(noise["psnr_db"]) + 6.02 if noise else float("nan")

    rows = []
    for n in [int(s) for s in args.subsamples.split(",")]:
        image = out / f"pinhole-{n}.exr"
        ok, _, seconds = run([dof, "render", "--scene", out / "scene.gltf", "--method", "pinhole", "--width", args.width,
                              "--height", args.height, "--subsamples", n, "--out", image])
        result = compare(dof, out / "mitsuba.exr", image) if ok else None
        rows.append({"subsamples": n, "psnr_db": psnr(result["psnr_db"]) if result else None, "seconds": seconds})
    table = ["Pinhole (`dof render --method pinhole`):", "", "| sub-samples | PSNR against Mitsuba (dB) | seconds |", "|---:|---:|---:|"]
    table += [f"| {r['subsamples']} | {fmt(r['psnr_db'])} | {r['seconds']:.2f} |" for r in rows]
    table += ["", f"Mitsuba {mi.__version__} ({variant}), {args.spp} spp at {args.width}x{args.height}; its own noise: {noise_db:.2f} dB"]
    lens = defocused(mi, dof, args, out, objects, camera) if args.defocus_spp > 0 else None
    if lens:
        table += ["", f"Defocused (aperture radius {args.aperture_radius}, focus {args.focus}), PSNR full / region (dB) against Mitsuba's "
                  f"thin lens at {args.defocus_spp} spp (its own noise {fmt(lens['noise_db'])} / {fmt(lens['noise_region_db'])} dB):", "",
                  "| method | double-sided | single-sided |", "|---|---:|---:|"]
        for r in lens["rows"]:
            cell = lambda c: "failed" if c is None else f"{fmt(c['psnr_db'])} / {fmt(c['region_db'])}"
            table.append(f"| {r['method']} | {cell(r['double'])} | {cell(r['single'])} |")
    text = "\n".join(table) + "\n"
    (out / "table.md").write_text(text)
    (out / "table.json").write_text(json.dumps({"pinhole": rows, "mitsuba_noise_db": noise_db, "spp": args.spp, "defocused": lens,
                                                "width": args.width, "height": args.height, "variant": variant}, indent=1))
    print(text, end="")


if __name__ == "__main__":
    main()
