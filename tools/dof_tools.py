"""Shared helpers of the independent-check tools: the `dof` binary, Mitsuba 3 (Jakob et al. 2022)
and its variant, rendering an exported scene, and `dof compare` results."""

import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent

# A tiny render that makes the JIT compile a kernel: the LLVM variant fails only then (and aborts
# the process, so it is tried in a child).
_PROBE = (
    "import mitsuba as mi; mi.set_variant('{v}'); "
    "mi.render(mi.load_dict({{'type': 'scene', 'integrator': {{'type': 'path'}}, 'sensor': {{'type': 'perspective', "
    "'film': {{'type': 'hdrfilm', 'width': 4, 'height': 4}}}}, "
    "'e': {{'type': 'constant'}}}}), spp=1)"
)


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(1)


def require_mitsuba(variant):
    """Imports Mitsuba 3 and selects `variant` ('auto': llvm_ad_rgb if its JIT works here, else
    scalar_rgb). Installs nothing: a missing package is an error naming the command."""
    try:
        import mitsuba as mi
    except ImportError:
        fail("this tool needs Mitsuba 3 (CPU variants included): pip install mitsuba")
    if variant == "auto":
        probe = subprocess.run([sys.executable, "-c", _PROBE.format(v="llvm_ad_rgb")], capture_output=True, text=True)
        if probe.returncode == 0:
            variant = "llvm_ad_rgb"
        else:
            print("note: Mitsuba's llvm_ad_rgb variant does not run here (it needs libLLVM, e.g. "
                  "`apt-get install libllvm19`; Dr.Jit finds it, or set DRJIT_LIBLLVM_PATH); using scalar_rgb",
                  file=sys.stderr)
            variant = "scalar_rgb"
    try:
        mi.set_variant(variant)
    except (ImportError, AttributeError) as e:
        fail(f"Mitsuba variant {variant} is not available: {e}")
    return mi, variant


def dof_binary(given=None):
    """The `dof` binary: `given`, else the dev-profile build (the profile `cargo run --bin dof` uses),
    built once here so that every later call runs the same binary."""
    if given:
        return str(Path(given).resolve())
    if not shutil.which("cargo"):
        fail("cargo is not on PATH: build the project first (README.md), or pass --dof PATH/TO/dof")
    print("building dof (cargo build --bin dof)...", file=sys.stderr)
    subprocess.run(["cargo", "build", "--quiet", "--bin", "dof"], cwd=REPO, check=True)
    meta = subprocess.run(["cargo", "metadata", "--format-version", "1", "--no-deps"], cwd=REPO,
                          check=True, capture_output=True, text=True)
    return str(Path(json.loads(meta.stdout)["target_directory"]) / "debug" / "dof")


def run(cmd, quiet=True):
    """Runs a command; returns (ok, stdout, seconds). Failures are reported, not raised."""
    start = time.perf_counter()
    p = subprocess.run([str(c) for c in cmd], cwd=REPO, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if p.returncode != 0:
        last = (p.stderr.strip().splitlines() or ["(no message)"])[-1]
        print(f"  failed ({p.returncode}): {' '.join(map(str, cmd))}\n    {last}", file=sys.stderr)
        return False, p.stderr, seconds
    if not quiet:
        print(p.stdout, end="")
    return True, p.stdout, seconds


def export_scenes(dof, names, width, height, folder):
    """`dof scenes --export-mitsuba`: returns {name: metadata} (metadata['exported'] says whether
    `folder/<name>.xml` exists, metadata['reason'] why not)."""
    folder.mkdir(parents=True, exist_ok=True)
    ok, out, _ = run([dof, "scenes", "--only", ",".join(names), "--width", width, "--height", height,
                      "--export-mitsuba", folder])
    if not ok:
        fail(f"exporting the scenes failed:\n{out}")
    result = {}
    for name in names:
        path = folder / f"{name}.json"
        if not path.exists():
            fail(f"dof scenes wrote no {path} (is `{name}` a built-in scene?)")
        result[name] = json.loads(path.read_text())
    return result


def render_mitsuba(mi, xml, spp, seed):
    """One render of an exported scene file (its `$spp` parameter set to `spp`)."""
    scene = mi.load_file(str(xml), spp=spp)
    return mi.render(scene, seed=seed, spp=spp)


def write_exr(mi, image, path):
    mi.Bitmap(image, mi.Bitmap.PixelFormat.RGB).write(str(path))


def compare(dof, reference, image, mask_from=None):
    """`dof compare --json`: the project's metrics of `image` against `reference`; None on failure."""
    cmd = [dof, "compare", reference, image, "--json"]
    if mask_from:
        cmd += ["--mask-from", mask_from]
    ok, out, _ = run(cmd)
    return json.loads(out) if ok else None


def psnr(value):
    """A PSNR from `dof compare` (null means identical images)."""
    return float("inf") if value is None else value
