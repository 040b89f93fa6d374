#!/usr/bin/env python3
"""Writes the hand-made seeds of the file-format fuzz targets (standard library only).

    python3 fuzz/make_seeds.py

- corpus/exr: tiny uncompressed EXRs of every layout the reader accepts (RGB, RGB+Z with alpha,
  Blender, Nuke in one part and as parts `rgba` and `depth`, multi-layer, multi-layer as parts),
  in half, float and uint samples;
- corpus/gltf: a triangle with a data URI, a textured quad (PNG data URI; sampler, camera,
  directional light, extras), the same quad as GLB with the image in the binary chunk, and the quad
  as a folder input (`scene.gltf`, `buffer.bin`, `image.png` joined by the target's separator);
- corpus/aperture_png: PNG masks in grey, grey+alpha, RGB, RGBA, palette with transparency, 16-bit,
  1-bit and interlaced, plus aperture texts (`blades:6:15:0.3`, `star:5`).

The other seeds come from `dof` itself (see fuzz/README.md): `simple.glb` from
`dof scenes --only simple --export DIR --width 16 --height 16`, and the ZIP-compressed
`dof-pinhole.exr` (RGB+Z) and `dof-layers.exr` (multi-layer) from
`dof render --method pinhole|layers --width 16 --height 16 --out FILE`. The corpora of the
structured targets (`lens`, `frame`) were grown by fuzzing and minimised with `cargo fuzz cmin`.
"""

import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SEP = b"#dof-fuzz-file#"


def out(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


# ---------------------------------------------------------------------------------------------- PNG


def png(width, height, color_type, bit_depth, rows, palette=None, trns=None, interlace=0):
    """`rows`: raw scanline bytes (without filter bytes) of the full image, or of each Adam7 pass
    when interlaced (already split)."""

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    raw = b"".join(b"\0" + r for r in rows)
    data = b"\x89PNG\r\n\x1a\n"
    data += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, interlace))
    if palette:
        data += chunk(b"PLTE", bytes(palette))
    if trns:
        data += chunk(b"tRNS", bytes(trns))
    data += chunk(b"IDAT", zlib.compress(raw))
    data += chunk(b"IEND", b"")
    return data


def disc(w, h, x, y):
    u, v = (x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1
    return u * u + v * v <= 0.8


def grey_png(w, h):
    return png(w, h, 0, 8, [bytes(255 if disc(w, h, x, y) else 0 for x in range(w)) for y in range(h)])


def aperture_seeds():
    out("aperture_png", "grey-8x8.png", grey_png(8, 8))
    out("aperture_png", "grey-alpha-6x4.png",
        png(6, 4, 4, 8, [bytes(b for x in range(6) for b in (200, 255 if disc(6, 4, x, y) else 0)) for y in range(4)]))
    out("aperture_png", "rgb-5x5.png",
        png(5, 5, 2, 8, [bytes(b for x in range(5) for b in ((250, 120, 10) if disc(5, 5, x, y) else (0, 0, 0))) for y in range(5)]))
    out("aperture_png", "rgba-4x7.png",
        png(4, 7, 6, 8, [bytes(b for x in range(4) for b in (255, 255, 255, 255 if disc(4, 7, x, y) else 0)) for y in range(7)]))
    out("aperture_png", "palette-trns-6x6.png",
        png(6, 6, 3, 8, [bytes(1 if disc(6, 6, x, y) else 0 for x in range(6)) for y in range(6)],
            palette=[0, 0, 0, 255, 255, 255], trns=[0, 255]))
    out("aperture_png", "grey16-4x4.png",
        png(4, 4, 0, 16, [b"".join(struct.pack(">H", 65535 if disc(4, 4, x, y) else 0) for x in range(4)) for y in range(4)]))
    # 1 bit, 8 wide: one byte a row.
    out("aperture_png", "grey1-8x8.png",
        png(8, 8, 0, 1, [bytes([sum((1 if disc(8, 8, x, y) else 0) << (7 - x) for x in range(8))]) for y in range(8)]))
    # Adam7, 2x2 grey: pass 1 holds (0,0), pass 6 holds (1,0), pass 7 holds row 1.
    out("aperture_png", "interlaced-2x2.png", png(2, 2, 0, 8, [bytes([255]), bytes([128]), bytes([64, 32])], interlace=1))
    out("aperture_png", "blades.txt", b"blades:6:15:0.3")
    out("aperture_png", "star.txt", b"star:5:0:0.4")


# ---------------------------------------------------------------------------------------------- EXR

HALF, FLOAT, UINT = 1, 2, 0


def attr(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def chlist(channels):
    body = b""
    for name, pixel_type in sorted(channels):
        body += name.encode() + b"\0" + struct.pack("<iB3xii", pixel_type, 0, 1, 1)
    return body + b"\0"


def header(channels, w, h, part=None):
    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    attrs = [
        attr("channels", "chlist", chlist(channels)),
        attr("compression", "compression", b"\0"),
        attr("dataWindow", "box2i", box),
        attr("displayWindow", "box2i", box),
        attr("lineOrder", "lineOrder", b"\0"),
        attr("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
        attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)),
        attr("screenWindowWidth", "float", struct.pack("<f", 1.0)),
    ]
    if part is not None:
        attrs += [
            attr("name", "string", part.encode()),
            attr("type", "string", b"scanlineimage"),
            attr("chunkCount", "int", struct.pack("<i", h)),
        ]
    return b"".join(attrs) + b"\0"


def sample(pixel_type, v):
    if pixel_type == HALF:
        return struct.pack("<e", v)
    if pixel_type == FLOAT:
        return struct.pack("<f", v)
    return struct.pack("<I", max(0, int(v)))


def value(name, x, y):
    """A plausible sample for a channel: depth grows to the right and the last column is the sky,
    alpha is 1 but for one transparent pixel, colour varies."""
    leaf = name.split(".")[-1]
    if leaf in ("Z", "depth"):
        layer = 1 if name.startswith("layer1") else 0
        return 1e30 if x == 3 else 1.0 + x + 2 * layer
    if leaf == "A":
        return 0.0 if (x, y) == (1, 1) else 1.0
    return 0.25 * (x + 1) * ("RGB".index(leaf) + 1) if leaf in "RGB" else 0.5


def lines(channels, w, h, y):
    body = b""
    for name, t in sorted(channels):
        body += b"".join(sample(t, value(name, x, y)) for x in range(w))
    return body


def exr(channels, w=4, h=3):
    """A single-part scanline EXR, uncompressed, one line a chunk."""
    head = b"\x76\x2f\x31\x01" + struct.pack("<I", 2) + header(channels, w, h)
    chunks = [struct.pack("<ii", y, len(lines(channels, w, h, y))) + lines(channels, w, h, y) for y in range(h)]
    offset = len(head) + 8 * h
    table = b""
    for c in chunks:
        table += struct.pack("<Q", offset)
        offset += len(c)
    return head + table + b"".join(chunks)


def exr_parts(parts, w=4, h=3):
    """A multi-part scanline EXR: `parts` is [(name, channels)]."""
    head = b"\x76\x2f\x31\x01" + struct.pack("<I", 2 | 0x1000)
    head += b"".join(header(ch, w, h, part=name) for name, ch in parts) + b"\0"
    chunks = []
    for p, (_, ch) in enumerate(parts):
        chunks.append([struct.pack("<iii", p, y, len(lines(ch, w, h, y))) + lines(ch, w, h, y) for y in range(h)])
    offset = len(head) + 8 * h * len(parts)
    table = b""
    for part in chunks:
        for c in part:
            table += struct.pack("<Q", offset)
            offset += len(c)
    return head + table + b"".join(c for part in chunks for c in part)


def exr_seeds():
    out("exr", "rgb-half.exr", exr([("R", HALF), ("G", HALF), ("B", HALF)]))
    out("exr", "rgbaz-float.exr", exr([("R", FLOAT), ("G", FLOAT), ("B", FLOAT), ("A", HALF), ("Z", FLOAT)]))
    out("exr", "rgb-depth-uint.exr", exr([("R", UINT), ("G", UINT), ("B", UINT), ("depth", FLOAT)]))
    out("exr", "blender.exr", exr([(f"ViewLayer.Combined.{c}", HALF) for c in "RGBA"] + [("ViewLayer.Depth.Z", FLOAT)]))
    out("exr", "nuke.exr", exr([(f"rgba.{c}", HALF) for c in "RGBA"] + [("depth.Z", FLOAT)]))
    out("exr", "nuke-parts.exr", exr_parts([("rgba", [(c, HALF) for c in "RGBA"]), ("depth", [("depth.Z", FLOAT)])]))
    multi = [(f"layer{i}.{c}", HALF if c != "Z" else FLOAT) for i in range(2) for c in "RGBAZ"]
    out("exr", "multilayer.exr", exr(multi))
    out("exr", "multilayer-parts.exr",
        exr_parts([(f"layer{i}", [(f"layer{i}.{c}", FLOAT) for c in "RGBZ"]) for i in range(2)]))


# --------------------------------------------------------------------------------------------- glTF


def f32s(values):
    return struct.pack(f"<{len(values)}f", *values)


def data_uri(data, mime="application/octet-stream"):
    return f"data:{mime};base64," + base64.b64encode(data).decode()


def triangle():
    pos = f32s([0, 0, -2, 1, 0, -2, 0, 1, -2])
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "buffers": [{"byteLength": len(pos), "uri": data_uri(pos)}],
        "bufferViews": [{"buffer": 0, "byteLength": len(pos)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, -2], "max": [1, 1, -2]}],
    }


def quad(buffer_uri, image):
    """A textured quad, its camera and a directional light; `image` is the glTF image object.
    Returns the document and its binary buffer."""
    pos = f32s([-1, -1, -3, 1, -1, -3, 1, 1, -3, -1, 1, -3])
    nrm = f32s([0, 0, 1] * 4)
    uv = f32s([0, 1, 1, 1, 1, 0, 0, 0])
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0\0"
    binary = pos + nrm + uv + idx
    views = []
    offset = 0
    for part in (pos, nrm, uv, idx):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part)
    views[3]["byteLength"] = 12
    doc = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "color": [1, 1, 1], "intensity": 2}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2], "extras": {"dof_ambient": [0.1, 0.1, 0.1], "dof_background": [0.2, 0.3, 0.5]}}],
        "nodes": [
            {"mesh": 0, "rotation": [0, 0, 0, 1], "scale": [1, 1, 1], "translation": [0, 0, 0]},
            {"camera": 0, "translation": [0, 0, 1]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "aspectRatio": 1.5}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0, "mode": 4}]}],
        "materials": [{
            "pbrMetallicRoughness": {"baseColorFactor": [1, 0.8, 0.6, 1], "baseColorTexture": {"index": 0}},
            "emissiveFactor": [0.1, 0, 0],
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2}},
            "alphaMode": "MASK",
            "alphaCutoff": 0.3,
            "doubleSided": True,
        }],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "wrapS": 33071, "wrapT": 33648}],
        "images": [image],
        "buffers": [{"byteLength": len(binary)} | ({"uri": buffer_uri} if buffer_uri else {})],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, -3], "max": [1, 1, -3]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    return doc, binary


def glb(doc, binary):
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def gltf_seeds():
    texture = grey_png(4, 4)
    out("gltf", "triangle.gltf", json.dumps(triangle()).encode())

    doc, binary = quad(None, {"uri": data_uri(texture, "image/png"), "mimeType": "image/png"})
    doc["buffers"][0]["uri"] = data_uri(binary)
    out("gltf", "quad-embedded.gltf", json.dumps(doc).encode())

    doc, binary = quad(None, {"bufferView": 4, "mimeType": "image/png"})
    doc["bufferViews"].append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(texture)})
    binary += texture
    doc["buffers"][0]["byteLength"] = len(binary)
    out("gltf", "quad.glb", glb(doc, binary))

    doc, binary = quad("buffer.bin", {"uri": "image.png"})
    out("gltf", "quad-folder.input", json.dumps(doc).encode() + SEP + binary + SEP + texture)


if __name__ == "__main__":
    aperture_seeds()
    exr_seeds()
    gltf_seeds()
