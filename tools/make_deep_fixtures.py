#!/usr/bin/env python3
"""Writes the deep OpenEXR test files of tests/data/deep/ with OpenEXR's own library (the Python
`OpenEXR` module, 3.3 or later), so that the deep reader is checked against files it did not write.

    python3 -m venv /tmp/exr && /tmp/exr/bin/pip install OpenEXR numpy
    /tmp/exr/bin/python tools/make_deep_fixtures.py tests/data/deep

The scene, 48x32 pixels: a far opaque wall at Z 10 (a colour gradient), an opaque disc at Z 4 with
an antialiased rim (partial coverage), a translucent pane at Z 1.5 (alpha 0.4) over the left part.
Each pixel stores its samples in a shuffled order, so the reader must sort them.

- scene-flat.exr: the same fragments as a flat multi-layer EXR (layer0..layer2 R, G, B, A, Z);
- scene-{none,rle,zips}.exr: deep scan lines in each compression OpenEXR allows for deep data;
- scene-tiled.exr: deep tiles of 20x12 (clipped at the right and bottom edges), ZIPS;
- scene-parts.exr: two deep parts, `front` (the pane and the disc) and `back` (the wall), that
  merge into the scene;
- scene-half.exr: colour and alpha as half floats, Z as float;
- volumes.exr: 4x1 pixels of volume samples (ZBack) overlapping point samples, and AR, AG, AB;
- nan-depth.exr: the scene with the wall's Z NaN in its first row.
"""
import sys
from pathlib import Path

import numpy as np
import OpenEXR

W, H = 48, 32


def scene_samples():
    """Per pixel, a list of (r, g, b, a, z), premultiplied."""
    rng = np.random.default_rng(7)
    pixels = []
    for y in range(H):
        row = []
        for x in range(W):
            s = [(0.2 + 0.6 * x / W, 0.3, 0.2 + 0.6 * y / H, 1.0, 10.0)]
            # The disc's coverage by 4x4 sub-samples, for an antialiased rim.
            cover = np.mean([(x + (i + 0.5) / 4 - 30) ** 2 + (y + (j + 0.5) / 4 - 16) ** 2 < 81 for i in range(4) for j in range(4)])
            if cover > 0:
                s.append((0.9 * cover, 0.5 * cover, 0.1 * cover, float(cover), 4.0))
            if x < 20 and 6 <= y < 26:
                s.append((0.4 * 0.2, 0.4 * 0.6, 0.4 * 0.9, 0.4, 1.5))
            order = rng.permutation(len(s))
            row.append([s[k] for k in order])
        pixels.append(row)
    return pixels


def deep_channels(pixels, names=("R", "G", "B", "A", "Z"), dtypes=None, keep=lambda s: True):
    dtypes = dtypes or {}
    out = {}
    for c, name in enumerate(names):
        a = np.empty((H, W), dtype=object)
        for y in range(H):
            for x in range(W):
                a[y, x] = np.array([s[c] for s in pixels[y][x] if keep(s)], dtype=dtypes.get(name, np.float32))
        out[name] = a
    return out


def write_deep(path, channels, kind=OpenEXR.deepscanline, compression=OpenEXR.ZIPS_COMPRESSION, tiles=None):
    header = {"type": kind, "compression": compression}
    if tiles:
        td = OpenEXR.TileDescription()
        td.xSize, td.ySize, td.mode = tiles[0], tiles[1], OpenEXR.ONE_LEVEL
        header["tiles"] = td
    OpenEXR.File(header, channels).write(str(path))


def main(out):
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    pixels = scene_samples()

    # The flat multi-layer file: each pixel's fragments front to back in layer0, layer1, layer2.
    flat = {}
    for k in range(3):
        planes = {c: np.zeros((H, W), np.float32) for c in "RGBAZ"}
        planes["Z"][:] = np.inf
        for y in range(H):
            for x in range(W):
                s = sorted(pixels[y][x], key=lambda s: s[4])
                if k < len(s):
                    for c, v in zip("RGBAZ", s[k]):
                        planes[c][y, x] = v
        for c in "RGBAZ":
            flat[f"layer{k}.{c}"] = planes[c]
    OpenEXR.File({"compression": OpenEXR.ZIP_COMPRESSION}, flat).write(str(out / "scene-flat.exr"))

    channels = deep_channels(pixels)
    for name, compression in [("none", OpenEXR.NO_COMPRESSION), ("rle", OpenEXR.RLE_COMPRESSION), ("zips", OpenEXR.ZIPS_COMPRESSION)]:
        write_deep(out / f"scene-{name}.exr", channels, compression=compression)
    write_deep(out / "scene-tiled.exr", channels, kind=OpenEXR.deeptile, tiles=(20, 12))
    write_deep(out / "scene-half.exr", deep_channels(pixels, dtypes={c: np.float16 for c in "RGBA"}))

    front = deep_channels(pixels, keep=lambda s: s[4] < 10)
    back = deep_channels(pixels, keep=lambda s: s[4] >= 10)
    parts = [
        OpenEXR.Part({"type": OpenEXR.deepscanline, "compression": OpenEXR.ZIPS_COMPRESSION}, front, name="front"),
        OpenEXR.Part({"type": OpenEXR.deepscanline, "compression": OpenEXR.RLE_COMPRESSION}, back, name="back"),
    ]
    OpenEXR.File(parts).write(str(out / "scene-parts.exr"))

    nan_pixels = [[[(r, g, b, a, np.nan if (y == 0 and z == 10.0) else z) for (r, g, b, a, z) in px] for px in row] for y, row in enumerate(pixels)]
    write_deep(out / "nan-depth.exr", deep_channels(nan_pixels))

    # Volumes: (R, G, B, AR, AG, AB, Z, ZBack) per sample, 4x1 pixels.
    vol = [
        [(0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 1.0, 3.0), (1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0)],
        [(0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 1.0, 2.0), (0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 1.0, 2.0)],
        [(0.2, 0.2, 0.2, 0.2, 0.4, 0.6, 5.0, 5.0)],
        [],
    ]
    names = ("R", "G", "B", "AR", "AG", "AB", "Z", "ZBack")
    vchan = {}
    for c, name in enumerate(names):
        a = np.empty((1, 4), dtype=object)
        for x in range(4):
            a[0, x] = np.array([s[c] for s in vol[x]], dtype=np.float32)
        vchan[name] = a
    OpenEXR.File({"type": OpenEXR.deepscanline, "compression": OpenEXR.NO_COMPRESSION}, vchan).write(str(out / "volumes.exr"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/deep")
