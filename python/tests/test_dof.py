"""Tests of the Python package `dof`: the CPU backend and Vulkan (lavapipe in CI).

The Vulkan tests fail without a Vulkan driver, as the Rust suites do; DOF_SKIP_VULKAN=1 skips them
(reported as skipped, and CI refuses a run with skips).
"""

import os

import numpy as np
import pytest

import dof

BACKENDS = [
    "cpu",
    pytest.param(
        "vulkan",
        marks=pytest.mark.skipif(os.environ.get("DOF_SKIP_VULKAN") == "1", reason="DOF_SKIP_VULKAN=1"),
    ),
]


def few_rays(method):
    """Four rays a pixel for ray tracing (fast enough for a test); the other methods take no rays."""
    return {"spp": 4} if method == "raytrace" else {}


def scene(h=32, w=48):
    """A bright square in front of (z=1) a textured wall (z=4), a strip of sky (+inf) on top."""
    rng = np.random.default_rng(7)
    rgb = rng.random((h, w, 3), dtype=np.float32)
    depth = np.full((h, w), 4.0, np.float32)
    depth[h // 4 : 3 * h // 4, w // 4 : w // 2] = 1.0
    rgb[h // 4 : 3 * h // 4, w // 4 : w // 2] = [3.0, 2.0, 1.0]
    depth[:3] = np.inf
    return rgb, depth


@pytest.mark.parametrize("backend", BACKENDS)
def test_five_line_script_multilayer(backend):
    rgb, depth = scene()
    out = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method="multilayer", backend=backend)
    assert out.shape == rgb.shape and out.dtype == np.float32
    assert np.isfinite(out).all()
    # The near square is blurred: its edge spreads over the wall, the wall far from it stays sharp.
    assert np.abs(out - rgb).max() > 0.1
    np.testing.assert_allclose(out[20:, 40:], rgb[20:, 40:], atol=1e-5)


def test_cpu_and_vulkan_agree():
    if os.environ.get("DOF_SKIP_VULKAN") == "1":
        pytest.skip("DOF_SKIP_VULKAN=1")
    rgb, depth = scene()
    cpu = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, backend="cpu")
    vk = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, backend="vulkan")
    np.testing.assert_allclose(cpu, vk, atol=2e-3, rtol=2e-3)


@pytest.mark.parametrize("method", ["multilayer", "gather"])
def test_cpu_and_wgpu_agree(method):
    if os.environ.get("DOF_SKIP_WGPU") == "1":
        pytest.skip("DOF_SKIP_WGPU=1")
    rgb, depth = scene()
    cpu = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method=method, backend="cpu")
    gpu = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method=method, backend="wgpu")
    np.testing.assert_allclose(cpu, gpu, atol=1e-5, rtol=1e-5)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("aperture_radius", [0.0, 1e-4])
def test_in_focus_is_identity(backend, aperture_radius):
    rgb, depth = scene()
    out = dof.blur(rgb, depth, focus=4.0, aperture_radius=aperture_radius, backend=backend)
    np.testing.assert_allclose(out, rgb, rtol=1e-5, atol=1e-6)


@pytest.mark.parametrize("backend", BACKENDS)
def test_infinite_colours_follow_the_exr_policy(backend):
    """A +inf channel is 65504 (the largest half, as `read_exr` makes it), never black; NaN and
    -inf are 0: the readers' policy, the same for an RGB image and a multi-layer one."""
    rgb, depth = scene()
    rgb[10, 40] = [np.inf, np.nan, -np.inf]
    want = rgb.copy()
    want[10, 40] = [65504.0, 0.0, 0.0]
    out = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.0, backend=backend)
    np.testing.assert_allclose(out, want, rtol=1e-5, atol=1e-6)
    frags = np.zeros(rgb.shape[:2] + (1, 4), np.float32)
    frags[:, :, 0, :3], frags[:, :, 0, 3] = rgb, depth
    layered = dof.blur(frags, np.ones(depth.shape, np.int64), focus=4.0, aperture_radius=0.0, backend=backend)
    np.testing.assert_allclose(layered, want, rtol=1e-5, atol=1e-6)


def test_multilayer_input_and_counts():
    rgb, depth = scene()
    h, w, _ = rgb.shape
    frags = np.zeros((h, w, 2, 4), np.float32)
    frags[:, :, 0, :3], frags[:, :, 0, 3] = rgb, depth
    frags[:, :, 1, :3], frags[:, :, 1, 3] = 0.5, np.inf
    counts = np.where(np.isinf(depth), 1, 2)
    one = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.0)
    two = dof.blur(frags, counts, focus=4.0, aperture_radius=0.0)
    np.testing.assert_allclose(one, two, atol=1e-6)
    assert dof.blur(frags, counts, focus=4.0, aperture_radius=0.5).shape == (h, w, 3)
    with pytest.raises(ValueError, match=r"counts\[0, 0\] = 3"):
        dof.blur(frags, np.full((h, w), 3), focus=4.0, aperture_radius=0.5)


def two_layers(front, alpha, back=(0.1, 0.9, 0.1), h=8, w=12):
    """Every pixel: a fragment of colour `front` and coverage `alpha` at z=1 over an opaque `back`
    at z=2."""
    frags = np.zeros((h, w, 2, 5), np.float32)
    frags[:, :, 0] = [*front, 1.0, alpha]
    frags[:, :, 1] = [*back, 2.0, 1.0]
    return frags, np.full((h, w), 2)


@pytest.mark.parametrize("backend", BACKENDS)
def test_alpha_is_premultiplied(backend):
    """Fragments with alpha hold premultiplied colour (as OpenEXR and read_exr have it): in focus
    every method returns the front-to-back composite, front + (1 - alpha) * back; straight colour
    gives the same with straight_alpha=True."""
    premultiplied = two_layers((0.4, 0.2, 0.1), 0.5)
    straight = two_layers((0.8, 0.4, 0.2), 0.5)
    composite = np.array([0.45, 0.65, 0.15], np.float32)
    names = [m["name"] for m in dof.methods()] if backend == "cpu" else ["multilayer", "gather"]
    for method in names:
        out = dof.blur(*premultiplied, focus=1.0, aperture_radius=1e-7, method=method, backend=backend, **few_rays(method))
        np.testing.assert_allclose(out, np.broadcast_to(composite, out.shape), atol=1e-4, err_msg=method)
        out2 = dof.blur(*straight, focus=1.0, aperture_radius=1e-7, method=method, backend=backend, **few_rays(method), straight_alpha=True)
        np.testing.assert_allclose(out2, out, atol=1e-6, err_msg=method)


def test_alpha_zero_is_light_that_hides_nothing():
    """A premultiplied fragment of alpha 0 with a colour adds its light and hides nothing; as
    straight colour it is nothing at all."""
    frags, counts = two_layers((0.3, 0.3, 0.3), 0.0, back=(0.1, 0.1, 0.1))
    out = dof.blur(frags, counts, focus=1.0, aperture_radius=1e-7)
    np.testing.assert_allclose(out, np.full(out.shape, 0.4, np.float32), atol=1e-5)
    out = dof.blur(frags, counts, focus=1.0, aperture_radius=1e-7, straight_alpha=True)
    np.testing.assert_allclose(out, np.full(out.shape, 0.1, np.float32), atol=1e-5)


@pytest.mark.parametrize("backend", BACKENDS)
def test_footprints_move_the_light(backend):
    """An emitter covering the left column of its pixel's 2x2 sub-samples (alpha 1/2) in front of
    a black wall in focus: with its footprint the light's centre lies a quarter pixel left of the
    pixel's, without it on the pixel's centre; the energy is the same. Bad footprints raise
    ValueError."""
    h, w = 31, 31
    frags = np.zeros((h, w, 2, 5), np.float32)
    frags[..., 3] = 1.0
    frags[..., 4] = 1.0
    counts = np.ones((h, w), np.uint32)
    frags[15, 15, 0] = [500.0, 500.0, 500.0, 0.5, 0.5]
    frags[15, 15, 1] = [0.0, 0.0, 0.0, 1.0, 1.0]
    counts[15, 15] = 2
    footprints = np.zeros((h, w, 2), np.uint32)
    footprints[15, 15, 0] = 0b0101
    lens = dict(focus=1.0, aperture_radius=0.02, pixels_per_unit=4000.0, focal_length=50.0, backend=backend)
    with_fp = dof.blur(frags, counts, footprints=footprints, footprint_side=2, **lens)
    without = dof.blur(frags, counts, **lens)
    xs = np.arange(w) + 0.5

    def centre_x(img):
        light = img[..., 0].sum(axis=0)
        return float((light * xs).sum() / light.sum())

    assert abs(with_fp.sum() - without.sum()) < 1e-3 * without.sum()
    assert abs(centre_x(without) - 15.5) < 1e-3
    assert abs(centre_x(with_fp) - 15.25) < 0.02
    with pytest.raises(ValueError, match="footprints"):
        dof.blur(frags, counts, footprints=footprints[:, :, :1], footprint_side=2, **lens)
    with pytest.raises(ValueError, match="footprint_side"):
        dof.blur(frags, counts, footprints=footprints, footprint_side=5, **lens)


def test_read_exr_layers_feed_blur_as_they_are():
    """An RGBA+Z file read as layers: its premultiplied colour goes into blur unchanged, so in
    focus the result is the file's own composite (read_exr without layers)."""
    path = os.path.join(os.path.dirname(__file__), "..", "..", "fuzz", "corpus", "exr", "rgbaz-float.exr")
    frags, counts = dof.read_exr(path, layers=True)
    assert frags.shape[3] == 5 and (frags[..., 4][counts > 0] < 1.0).any(), "the corpus file has alpha below 1"
    rgb, _ = dof.read_exr(path)
    out = dof.blur(frags, counts, focus=1.0, aperture_radius=1e-7)
    np.testing.assert_allclose(out, rgb, atol=1e-5)


DEEP = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "deep")


def test_deep_exr_reads_as_counts_and_flat_samples_that_make_layers_for_blur():
    """A deep file written by OpenEXR's own library: per-pixel counts and flat sample arrays, tidy
    (front to back); its layers for a lens feed blur, which in focus returns the flat layers'
    composite."""
    counts, samples = dof.read_deep_exr(os.path.join(DEEP, "scene-zips.exr"))
    assert counts.shape == (32, 48) and counts.dtype == np.uint32
    assert set(samples) == {"R", "G", "B", "A", "Z", "ZBack"}
    n = int(counts.sum())
    assert all(a.shape == (n,) for a in samples.values())
    starts = np.concatenate([[0], np.cumsum(counts.ravel(), dtype=np.int64)])
    z = samples["Z"]
    assert all((np.diff(z[starts[p] : starts[p + 1]]) >= 0).all() for p in range(counts.size)), "front to back"
    lens = dict(focus=4.0, aperture_radius=1e-7)
    frags, layer_counts = dof.deep_layers(counts, samples, max_layers=2, **lens)
    assert frags.shape == (32, 48, 2, 5) and layer_counts.max() <= 2
    flat, flat_counts = dof.read_exr(os.path.join(DEEP, "scene-flat.exr"), layers=True)
    want = dof.blur(flat, flat_counts, **lens)
    np.testing.assert_allclose(dof.blur(frags, layer_counts, **lens), want, atol=1e-5)
    # Several files merge; samples built by hand are made tidy as well.
    merged, _ = dof.read_deep_exr([os.path.join(DEEP, "scene-zips.exr"), os.path.join(DEEP, "scene-rle.exr")])
    assert merged.shape == counts.shape
    one = {k: np.array([0.5, 0.25], np.float32) for k in ("R", "G", "B")}
    one.update(A=np.array([0.5, 0.5], np.float32), Z=np.array([3.0, 1.0], np.float32))
    frags, c = dof.deep_layers(np.array([[2]]), one, yfov=1.0, **lens)
    assert c[0, 0] >= 1 and frags[0, 0, 0, 3] == 1.0, "the nearer sample comes first"


def test_bad_arrays_are_named_never_cast(tmp_path):
    rgb, depth = scene(8, 12)
    with pytest.raises(ValueError, match=r"depth must have shape \(H, W\)"):
        dof.write_exr(str(tmp_path / "x.exr"), rgb, depth[..., None])
    with pytest.raises(ValueError, match="needs a float depth array"):
        dof.blur(rgb, None, focus=2.0, f_number=2.0)
    frags = np.zeros((8, 12, 2, 5), np.float32)
    frags[..., 3] = 4.0
    frags[..., 4] = 1.0
    for bad, shown in [(np.nan, "NaN"), (1.7, "1.7"), (-1.0, "-1")]:
        counts = np.ones((8, 12))
        counts[2, 3] = bad
        with pytest.raises(ValueError, match=rf"counts\[2, 3\] is {shown}; it must be a whole number"):
            dof.blur(frags, counts, focus=2.0, f_number=2.0)
    footprints = np.full((8, 12, 2), 15, np.int64)
    footprints[0, 0, 0] = -1
    with pytest.raises(ValueError, match=r"footprints\[0, 0, 0\] is -1"):
        dof.blur(frags, np.ones((8, 12)), focus=2.0, f_number=2.0, footprints=footprints, footprint_side=2)


def test_readers_warn_about_what_they_repaired(tmp_path):
    rgb = np.full((4, 6, 3), 0.5, np.float32)
    rgb[1, 2, 0] = np.nan
    depth = np.full((4, 6), 2.0, np.float32)
    path = str(tmp_path / "nan.exr")
    dof.write_exr(path, rgb, depth)
    with pytest.warns(UserWarning, match="NaN colour values set to 0"):
        back, _ = dof.read_exr(path)
    assert back[1, 2, 0] == 0.0
    with pytest.warns(UserWarning, match="NaN, zero or negative Z dropped"):
        dof.read_deep_exr(os.path.join(DEEP, "nan-depth.exr"))


def test_bad_deep_input_raises_value_error(tmp_path):
    with pytest.raises(ValueError, match="not an OpenEXR file"):
        bad = tmp_path / "bad.exr"
        bad.write_bytes(b"not an exr")
        dof.read_deep_exr(str(bad))
    with pytest.raises(ValueError, match="no deep part"):
        dof.read_deep_exr(os.path.join(DEEP, "scene-flat.exr"))
    counts, samples = dof.read_deep_exr(os.path.join(DEEP, "volumes.exr"))
    with pytest.raises(ValueError, match="counts add up to"):
        dof.deep_layers(counts + 1, samples, focus=4.0, f_number=2.0)
    with pytest.raises(ValueError, match="max_layers"):
        dof.deep_layers(counts, samples, focus=4.0, f_number=2.0, max_layers=0)


@pytest.mark.parametrize(
    "lens, message",
    [
        (dict(focus=-1.0, aperture_radius=0.1), "focus distance must be positive"),
        (dict(focus=2.0, aperture_radius=-0.1), "aperture radius must be finite and not negative"),
        (dict(focus=2.0, f_number=0.0), "f-number must be positive"),
        (dict(focus=2.0, f_number=2.0, focal_length=5000.0), "must be shorter than the focus distance"),
        (dict(focus=2.0), "needs an aperture"),
        (dict(focus=2.0, f_number=2.0, aperture_radius=0.1), "not both"),
        (dict(focus=2.0, f_number=2.0, sensor_height=0.0), "sensor height must be positive"),
        (dict(focus=2.0, f_number=2.0, yfov=180.0), "yfov"),
    ],
)
def test_bad_lens_raises_value_error(lens, message):
    rgb, depth = scene()
    with pytest.raises(ValueError, match=message):
        dof.blur(rgb, depth, **lens)


def test_bad_input_raises_value_error():
    rgb, depth = scene()
    with pytest.raises(ValueError, match="depth must have shape"):
        dof.blur(rgb, depth[:-1], focus=2.0, f_number=2.0)
    bad = depth.copy()
    bad[5, 6] = -1.0
    with pytest.raises(ValueError, match=r"depth -1 at \(6, 5\) is not positive"):
        dof.blur(rgb, bad, focus=2.0, f_number=2.0)
    with pytest.raises(ValueError, match="unknown method 'nope'.*multilayer"):
        dof.blur(rgb, depth, focus=2.0, f_number=2.0, method="nope")
    with pytest.raises(ValueError, match="unknown option 'tiles': multilayer takes tile, merge, max_coc, aperture"):
        dof.blur(rgb, depth, focus=2.0, f_number=2.0, tiles=16)
    # A count is never rounded from a float, and bounds name their unit.
    with pytest.raises(ValueError, match="option rings of ring-gather is a whole number between 1 and 8"):
        dof.blur(rgb, depth, focus=2.0, f_number=2.0, method="ring-gather", rings=2.5)
    with pytest.raises(ValueError, match=r"option max_coc of gather must lie between 1 and 96 \(px, CoC diameter\), got 200"):
        dof.blur(rgb, depth, focus=2.0, f_number=2.0, method="gather", max_coc=200)
    with pytest.raises(ValueError, match="tile size 17"):
        dof.blur(rgb, depth, focus=2.0, aperture_radius=0.5, tile=17)
    with pytest.raises(ValueError, match="option merge of multilayer is one of none, 2x2, 4x4, got 3x3"):
        dof.blur(rgb, depth, focus=2.0, aperture_radius=0.5, merge="3x3")
    with pytest.raises(ValueError, match="unknown backend"):
        dof.blur(rgb, depth, focus=2.0, aperture_radius=0.5, backend="metal")


def test_exr_round_trip(tmp_path):
    rgb, depth = scene()
    path = tmp_path / "in.exr"
    dof.write_exr(path, rgb, depth)
    rgb2, depth2 = dof.read_exr(path)
    np.testing.assert_array_equal(rgb2, rgb)
    np.testing.assert_array_equal(depth2, depth)
    frags, counts = dof.read_exr(str(path), layers=True)
    assert frags.shape == rgb.shape[:2] + (1, 5) and counts.shape == depth.shape
    np.testing.assert_array_equal(frags[:, :, 0, 3], depth)
    out = dof.blur(frags, counts, focus=4.0, aperture_radius=0.5)
    np.testing.assert_array_equal(out, dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5))
    dof.write_exr(tmp_path / "rgb.exr", out)
    back, none = dof.read_exr(tmp_path / "rgb.exr")
    assert none is None
    np.testing.assert_array_equal(back, out)
    with pytest.raises(ValueError, match="does not exist"):
        dof.read_exr(tmp_path / "missing.exr")
    with pytest.raises(ValueError, match=r"rgb must have shape \(H, W, 3\)"):
        dof.write_exr(tmp_path / "x.exr", depth)


def test_methods_lists_the_registry():
    names = [m["name"] for m in dof.methods()]
    assert names[0] == "multilayer" and len(names) == len(set(names)) >= 7
    for m in dof.methods():
        assert m["title"] and m["paper"]
    # Each method's options with their kinds, bounds, units and defaults, as blur checks them.
    gather = next(m for m in dof.methods() if m["name"] == "gather")
    assert gather["options"] == [{"key": "max_coc", "kind": "count", "min": 1, "max": 96, "unit": "px, CoC diameter",
                                  "default": "the largest", "help": "largest CoC diameter the method honours"}]
    multilayer = next(m for m in dof.methods() if m["name"] == "multilayer")
    merge = next(o for o in multilayer["options"] if o["key"] == "merge")
    assert merge["kind"] == "choice" and merge["choices"] == ["none", "2x2", "4x4"] and merge["default"] == "none"


@pytest.mark.parametrize("method", [m["name"] for m in dof.methods()])
def test_every_method_runs(method):
    rgb, depth = scene(24, 32)
    out = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.3, method=method, **few_rays(method))
    assert out.shape == rgb.shape and np.isfinite(out).all()
    assert np.abs(out - rgb).max() > 0.01  # something was blurred
    sharp = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.0, method=method, **few_rays(method))
    np.testing.assert_allclose(sharp, rgb, rtol=1e-4, atol=1e-4)


@pytest.mark.parametrize("method", [m["name"] for m in dof.methods()])
def test_every_method_runs_on_vulkan(method):
    if os.environ.get("DOF_SKIP_VULKAN") == "1":
        pytest.skip("DOF_SKIP_VULKAN=1")
    rgb, depth = scene(24, 32)
    out = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.3, method=method, backend="vulkan", **few_rays(method))
    assert out.shape == rgb.shape and np.isfinite(out).all()


def test_options_reach_the_method():
    rgb, depth = scene()
    a = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method="ring-gather", rings=1)
    b = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method="ring-gather", rings=5)
    assert np.abs(a - b).max() > 1e-3
    merged = dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, merge="4x4", tile=32, aperture="blades:6")
    assert merged.shape == rgb.shape
    # An option of another method is refused, not ignored, as the CLI refuses its flag.
    for method, option in [("gather", {"merge": "4x4"}), ("tiled", {"no_cascade": True}), ("ring-gather", {"spp": 4}),
                           ("multilayer", {"rings": 2}), ("gather", {"aperture": "blades:6"})]:
        with pytest.raises(ValueError, match=f"option {next(iter(option))} applies to .* only; {method} does not take it"):
            dof.blur(rgb, depth, focus=4.0, aperture_radius=0.5, method=method, **option)


def test_readme_example(tmp_path, monkeypatch):
    """The README's Python lines, on a file written here."""
    monkeypatch.chdir(tmp_path)
    dof.write_exr("in.exr", *scene())
    rgb, depth = dof.read_exr("in.exr")
    out = dof.blur(rgb, depth, focus=2.0, f_number=2.8)
    dof.write_exr("out.exr", out, depth)
    assert "multilayer" in [m["name"] for m in dof.methods()]
    np.testing.assert_array_equal(dof.read_exr("out.exr")[0], out)


def test_multilayer_exr_file():
    """A multi-layer EXR from the repository's corpus: read as layers and blurred."""
    path = os.path.join(os.path.dirname(__file__), "..", "..", "fuzz", "corpus", "exr", "dof-layers.exr")
    with pytest.raises(ValueError, match="multi-layer EXR.*layers=True"):
        dof.read_exr(path)
    frags, counts = dof.read_exr(path, layers=True)
    assert frags.shape == (16, 16, 4, 5) and counts.dtype == np.uint32 and counts.max() == 2
    out = dof.blur(frags, counts, focus=2.0, f_number=2.0)
    assert out.shape == (16, 16, 3) and np.isfinite(out).all()


@pytest.mark.cli
@pytest.mark.parametrize(
    "method, flags, lens",
    [
        ("multilayer", ["--aperture-radius", "0.5", "--merge", "2x2"], dict(aperture_radius=0.5, merge="2x2")),
        ("gather", ["--f-number", "1.4", "--yfov", "10"], dict(f_number=1.4, yfov=10.0)),
        ("layered", ["--f-number", "2", "--focal-length", "80"], dict(f_number=2.0, focal_length=80.0)),
    ],
)
def test_same_as_the_cli(tmp_path, method, flags, lens):
    """blur gives exactly what `dof render --scene FILE.exr` gives (DOF_CLI: the `dof` binary)."""
    import subprocess

    cli = os.environ.get("DOF_CLI")
    if not cli:
        pytest.skip("DOF_CLI (the dof binary) is not set")
    rgb, depth = scene()
    dof.write_exr(tmp_path / "in.exr", rgb, depth)
    out = tmp_path / "out.exr"
    args = [cli, "render", "--scene", str(tmp_path / "in.exr"), "--method", method, "--focus", "4", *flags, "--out", str(out)]
    subprocess.run(args, check=True, capture_output=True)
    expected, _ = dof.read_exr(out)
    got = dof.blur(rgb, depth, focus=4.0, method=method, **lens)
    assert np.abs(got - rgb).max() > 0.05  # the comparison is of a real blur
    np.testing.assert_array_equal(got, expected)


def run_limited(code, limit_bytes):
    """Runs `code` in a fresh interpreter whose address space is limited to `limit_bytes`
    (`ulimit -v`): returns (exit code, stdout + stderr). A negative code is the signal that ended it."""
    import subprocess
    import sys

    prelude = f"import resource\nresource.setrlimit(resource.RLIMIT_AS, ({limit_bytes}, {limit_bytes}))\n"
    r = subprocess.run([sys.executable, "-c", prelude + code], capture_output=True, text=True, timeout=600)
    return r.returncode, r.stdout + r.stderr


MEMORY_ERROR = """
import numpy as np, dof
try:
    {call}
    print("finished")
except MemoryError as e:
    print("MemoryError:", e)
"""


@pytest.mark.parametrize(
    "call,limit_gib",
    [
        # An 8192x8192 gather, the image and depth broadcast (no memory of their own): its layers,
        # their padded copy and the context fit in 8 GiB of address space, the words up and back
        # (3 GB more) do not, and the frame is refused before its upload, not part way.
        (
            "dof.blur(np.broadcast_to(np.float32(0.5), (8192, 8192, 3)), np.broadcast_to(np.float32(2.0), (8192, 8192)),"
            " focus=4.0, f_number=2.0, method='gather')",
            8,
        ),
        # A 65536x65536 image to write: 48 GiB to copy.
        ("dof.write_exr('/nonexistent-dir/x.exr', np.broadcast_to(np.float32(0.5), (65536, 65536, 3)))", 4),
    ],
)
def test_sizes_beyond_the_memory_raise_memory_error(call, limit_gib):
    """Work larger than the memory it may use raises MemoryError; the interpreter lives on."""
    code, out = run_limited(MEMORY_ERROR.format(call=call), limit_gib << 30)
    assert code == 0 and "MemoryError: out of host memory" in out, f"exit {code}: {out[-2000:]}"
