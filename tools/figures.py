#!/usr/bin/env python3
"""The current figures of the docs: tables made from what `dof eval` and `dof bench` write.

    python3 tools/figures.py measure [--dof PATH]   run the measurements into docs/figures/data/
    python3 tools/figures.py write                  rewrite every generated table in docs/
    python3 tools/figures.py check                  fail where a generated table differs from its data

A generated table sits in a Markdown file between `<!-- figures:NAME -->` and
`<!-- /figures:NAME -->`; `write` replaces what lies between with `TABLES[NAME]` of the data, and
`check` (run by CI) fails if any block differs, so no figure in such a block is edited by hand.
The data is the JSON the commands wrote, kept in docs/figures/data/ (and the GPU runs' logs in
docs/gpu/), each file naming its machine. `measure` runs on the CPU backend of the machine it
is run on: its times are no GPU figures. GPU tables come from `tools/gpu_run.sh` logs.

Standard library only.
"""
import argparse, glob, json, math, os, platform, re, shutil, subprocess, sys, tempfile, textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "docs", "figures", "data")
# The GPU run the GPU tables come from (`tools/gpu_run.sh`'s output, its commit in commit.txt).
GPU_RUN = os.path.join(ROOT, "docs", "gpu", "h200-2026-11-28")
DOCS = ["docs/measurements.md", "docs/methods.md"]

# The evaluation's scenes (all built-in opaque ones) and the point-sampled comparison of
# docs/methods.md (its per-method tables are point-sampled).
EVAL_SCENES = "simple,railing,columns,highlights,fence,edges"
POINT_SCENES = "simple,railing,columns,highlights"
POINT_METHODS = "layered,gather,tiled,multilayer,raytrace"
# The evaluation's plots the docs show.
PLOTS = ["simple-error-vs-time.png", "simple-max-coc.png", "railing-tile-size.png"]
METHODS = ["multilayer", "tiled", "gather", "ring-gather", "scatter-gather", "bokeh", "raytrace", "layered"]


# ---- measuring -------------------------------------------------------------------------------

def run(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr, flush=True)
    return subprocess.run(cmd, check=True, **kw)


def machine():
    """What the CPU figures ran on."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return {"cpu": cpu, "cores": os.cpu_count()}


def commit():
    """The commit measured, `+changes` where the tree differs from it outside docs/."""
    try:
        git = lambda *a: subprocess.run(["git", "-C", ROOT, *a], capture_output=True, text=True, check=True).stdout
        changed = [l for l in git("status", "--porcelain").splitlines() if not l[3:].startswith("docs/")]
        return git("rev-parse", "--short", "HEAD").strip() + ("+changes" if changed else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def measure(dof):
    """Runs every measurement, then writes the data and plots: all of them, or on a failure none."""
    about = {"machine": machine(), "commit": commit(), "dof": dof}
    data, plots = {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, extra in [
            # The plots of the first come into docs/figures/ (PLOTS).
            ("eval-cpu.json", ["--scenes", EVAL_SCENES]),
            ("eval-cpu-point.json", ["--scenes", POINT_SCENES, "--methods", POINT_METHODS, "--subsamples", "1", "--coc-sweep", "none", "--no-plots"]),
        ]:
            out = os.path.join(tmp, name)
            run([dof, "eval", "--backend", "cpu", "--runs", "3", "--out", out] + extra)
            with open(os.path.join(out, "report.json")) as f:
                data[name] = {"about": about, "command": f"dof eval --backend cpu --runs 3 {' '.join(extra)}", "report": json.load(f)}
            for plot in PLOTS if name == "eval-cpu.json" else []:
                with open(os.path.join(out, plot), "rb") as f:
                    plots[plot] = f.read()
        frame = ["bench", "frame", "--backend", "cpu", "--json"]
        rows = []
        for m in METHODS:
            cmd = [dof] + frame + ["--method", m, "--scene", "railing", "--width", "1920", "--height", "1080", "--frames", "1", "--warmup", "0", "--warmup-ms", "0"]
            rows.append(json.loads(run(cmd, capture_output=True, text=True).stdout))
        data["memory-1080p.json"] = {"about": about, "command": "dof bench frame --backend cpu --scene railing --width 1920 --height 1080 --frames 1", "rows": rows}
        cmd = [dof] + frame + ["--method", "multilayer", "--merge", "4x4", "--scene", "railing", "--width", "1920", "--height", "1080", "--frames", "5", "--warmup", "1"]
        bench = json.loads(run(cmd, capture_output=True, text=True).stdout)
        # The bound's cost of one disc test, measured on the same machine (docs/perf/disc-test-cost.rs).
        exe = os.path.join(tmp, "disc-test-cost")
        run(["rustc", "-C", "opt-level=3", "-o", exe, os.path.join(ROOT, "docs", "perf", "disc-test-cost.rs")])
        line = run([exe], capture_output=True, text=True).stdout
        ns = float(re.search(r"([0-9.]+) ns a test", line).group(1))
        data["cpu-frame-1080p.json"] = {"about": about, "command": " ".join(["dof"] + cmd[1:]), "frame": bench, "ns_per_disc_test": ns, "disc_test_output": line.strip()}
    os.makedirs(DATA, exist_ok=True)
    for name, value in data.items():
        with open(os.path.join(DATA, name), "w") as f:
            json.dump(value, f, indent=1, sort_keys=True)
            f.write("\n")
    for plot, png in plots.items():
        with open(os.path.join(ROOT, "docs", "figures", plot), "wb") as f:
            f.write(png)


# ---- tables ----------------------------------------------------------------------------------

def load(name):
    with open(os.path.join(DATA, name)) as f:
        return json.load(f)


def provenance(d):
    m = d["about"]["machine"]
    return f"`{d['command']}` at commit {d['about']['commit']}, {m['cpu']}, {m['cores']} threads"


def caption(text):
    """A table's caption as lines of at most 100 columns."""
    return textwrap.wrap(text, 100, break_on_hyphens=False) + [""]


def db(v):
    return "inf" if v is None or v == float("inf") else f"{v:.2f}"


def records(d, **match):
    return [r for r in d["report"]["records"] if all(r.get(k) == v for k, v in match.items())]


def eval_every_method():
    """Every method and setting of the evaluation on `simple`: time on the CPU backend and error."""
    d = load("eval-cpu.json")
    scene = next(s for s in d["report"]["scenes"] if s["name"] == "simple")
    lines = caption(
        f"`simple` at {scene['width']}x{scene['height']} against its exact reference ({scene['reference_spp']} spp), "
        f"the partial-occlusion region {100 * scene['occlusion_region_share']:.1f}% of the pixels. Time: the median of "
        f"{d['report']['runs']} frames' kernel time through one context on the CPU backend (no GPU figure). "
        f"From {provenance(d)}."
    ) + [
        "| method | setting | CPU backend (ms) | PSNR full / region (dB) | FLIP full / region |",
        "|---|---|---|---|---|",
    ]
    for r in records(d, scene="simple"):
        t = "-" if r["backend"] == "host" else f"{r['time_ms']:.1f}"
        lines.append(f"| {r['method']} | {r['setting']} | {t} | {db(r['psnr_db'])} / {db(r['psnr_masked_db'])} "
                     f"| {r['flip']:.4f} / {r['flip_masked']:.4f} |")
    return lines


def eval_against_ring_gather():
    """Multi-layer splatting (merged 4x4) against the ring gather (5 rings), every scene."""
    d = load("eval-cpu.json")
    lines = caption(
        "Multi-layer splatting merged 4x4 against the ring gather with 5 rings, each scene at its evaluation "
        f"size, on the CPU backend (no GPU figure). From {provenance(d)}."
    ) + [
        "| scene | multilayer (ms) | ring gather (ms) | ratio | multilayer PSNR full / region (dB) | ring gather PSNR (dB) |",
        "|---|---|---|---|---|---|",
    ]
    for s in d["report"]["scenes"]:
        ml = records(d, scene=s["name"], method="multilayer", setting="merge=4x4 tile=16")
        rg = records(d, scene=s["name"], method="ring-gather", setting="rings=5")
        if ml and rg:
            ml, rg = ml[0], rg[0]
            lines.append(f"| {s['name']} | {ml['time_ms']:.1f} | {rg['time_ms']:.1f} | {ml['time_ms'] / rg['time_ms']:.2f} "
                         f"| {db(ml['psnr_db'])} / {db(ml['psnr_masked_db'])} | {db(rg['psnr_db'])} / {db(rg['psnr_masked_db'])} |")
    return lines


def layered_point_sampled():
    """docs/methods.md's layered DoF table: cascaded and not, against gather and multi-layer."""
    d = load("eval-cpu-point.json")
    cols = [("layered", "layers_per_doubling=2"), ("layered", "no_cascade=true layers_per_doubling=2"),
            ("gather", None), ("multilayer", "merge=none tile=16")]
    lines = caption(
        "Point-sampled layers (`--subsamples 1`), each scene at its evaluation size against its exact reference, "
        f"full frame / region (dB), 2 layers per doubling. From {provenance(d)}."
    ) + [
        "| scene | cascaded | non-cascaded | gather (its best setting) | multilayer, no merge |",
        "|---|---|---|---|---|",
    ]
    for s in d["report"]["scenes"]:
        lines.append(f"| {s['name']} | " + " | ".join(point_cell(d, s["name"], m, setting) for m, setting in cols) + " |")
    return lines


def point_cell(d, scene, method, setting=None):
    """`full / region` of a point-sampled record (the best region PSNR of the method's settings
    without `setting`), or `-`."""
    rs = [r for r in records(d, scene=scene, method=method) if setting is None or r["setting"] == setting]
    if not rs:
        return "-"
    best = max(rs, key=lambda r: r["psnr_masked_db"])
    return f"{db(best['psnr_db'])} / {db(best['psnr_masked_db'])}"


def splat_quality():
    """docs/methods.md's tiled splatting table: splatting against the gather, with the lists merging shortens."""
    d = load("eval-cpu-point.json")
    lines = caption(
        "Point-sampled layers (`--subsamples 1`), each scene at its evaluation size against its exact reference, "
        "full frame / region (dB), 16-pixel tiles; the mean tile list without and with 4x4 merging. "
        f"From {provenance(d)}."
    ) + [
        "| scene | gather (its best setting) | single-layer 4x4 | multi-layer | multi-layer 4x4 | lists (4x4) |",
        "|---|---|---|---|---|---|",
    ]
    for s in d["report"]["scenes"]:
        n = s["name"]
        lists = "-"
        none = records(d, scene=n, method="multilayer", setting="merge=none tile=16")
        merged = records(d, scene=n, method="multilayer", setting="merge=4x4 tile=16")
        if none and merged:
            a, b = none[0]["figures"]["mean_list_length"], merged[0]["figures"]["mean_list_length"]
            lists = f"{a:.0f} -> {b:.0f} ({a / b:.1f}x)"
        lines.append(
            f"| {n} | {point_cell(d, n, 'gather')} | {point_cell(d, n, 'tiled', 'merge=4x4 tile=16')} "
            f"| {point_cell(d, n, 'multilayer', 'merge=none tile=16')} | {point_cell(d, n, 'multilayer', 'merge=4x4 tile=16')} | {lists} |"
        )
    return lines


def raytrace_point_sampled():
    """docs/methods.md's ray tracing table: rays a pixel against multi-layer splatting, with times."""
    d = load("eval-cpu-point.json")
    lines = caption(
        "Point-sampled layers (`--subsamples 1`), each scene at its evaluation size against its exact reference, "
        "full frame / region (dB), and the CPU backend's time a frame (no GPU figure). "
        f"From {provenance(d)}."
    ) + [
        "| scene | 16 rays a pixel | 32 rays a pixel | multilayer, no merge | multilayer 4x4 |",
        "|---|---|---|---|---|",
    ]
    for s in d["report"]["scenes"]:
        cells = []
        for method, setting in [("raytrace", "samples=16"), ("raytrace", "samples=32"),
                                ("multilayer", "merge=none tile=16"), ("multilayer", "merge=4x4 tile=16")]:
            r = records(d, scene=s["name"], method=method, setting=setting)
            cells.append("-" if not r else f"{db(r[0]['psnr_db'])} / {db(r[0]['psnr_masked_db'])}, {r[0]['time_ms']:.0f} ms")
        lines.append(f"| {s['name']} | " + " | ".join(cells) + " |")
    return lines


def memory_1080p():
    d = load("memory-1080p.json")
    lines = caption(
        "Device bytes of each method's context at 1920x1080 with 4 layers (the registry's default options, "
        f"one frame in flight, `device_bytes`). From {provenance(d)}; the CPU backend and Vulkan hold the same."
    ) + [
        "| method | MB |",
        "|---|---|",
    ]
    for r in d["rows"]:
        lines.append(f"| {r['method']} | {r['device_bytes'] / 1e6:.1f} |")
    return lines


def cpu_frame_1080p():
    d = load("cpu-frame-1080p.json")
    f = d["frame"]
    tests = f["list_entries"] * 256
    bound_s = tests * d["ns_per_disc_test"] * 1e-9 / d["about"]["machine"]["cores"]
    t = f["table1_ms"]
    return caption(f"`railing` at 1920x1080, multi-layer splatting merged 4x4, on the CPU backend. From {provenance(d)}.") + [
        "| frame ms (p10-p90) | merge | splat | sort | apply | list entries | disc tests | ns a test | bound (s, all threads) | frame / bound |",
        "|---|---|---|---|---|---|---|---|---|---|",
        f"| {f['frame_ms']:.1f} ({f['frame_ms_p10']:.1f}-{f['frame_ms_p90']:.1f}) | {t['merge']:.1f} | {t['splat']:.1f} | {t['sort']:.1f} "
        f"| {t['apply']:.1f} | {f['list_entries']:,} | {tests / 1e6:.1f} M | {d['ns_per_disc_test']:.3f} | {bound_s:.3f} "
        f"| {f['frame_ms'] * 1e-3 / bound_s:.2f} |",
    ]


def bench_runs(folder, *prefixes):
    """The `dof bench frame --json` records of `folder` whose file names start with one of
    `prefixes`, in name order; a run cut short by its time limit leaves an empty file, skipped."""
    for p in sorted(glob.glob(os.path.join(folder, "*.json"))):
        if not os.path.basename(p).startswith(prefixes):
            continue
        try:
            with open(p) as f:
                yield json.load(f)
        except ValueError:
            continue


def gpu_frames(path=GPU_RUN):
    """Every method's frame time at 1920x1080 per scene, from a `tools/gpu_run.sh` log."""
    runs = {}
    for r in bench_runs(path, "frame-", "span-"):
        if r.get("orbit_deg") is not None:
            continue
        key = (r["scene"], r["width"], r["method"], r["merge"] if r["method"] in ("multilayer", "tiled") else "-")
        # A span-only run's frame time carries no per-command timestamps: it wins where both exist.
        runs.setdefault(key, {})["span" if r["span_only"] else "staged"] = r
    return runs


def frame_ms(entry):
    r = entry.get("span") or entry.get("staged")
    return r["frame_ms"]


def device_line(path=GPU_RUN):
    with open(os.path.join(path, "device.txt")) as f:
        text = f.read()
    dev = re.search(r"vulkan device 0: ([^,(]+?)\s*\([^)]*\), (Vulkan [0-9.]+), driver ([^\n]+)", text)
    kernels = re.search(r"source hash ([0-9a-f]+)", text)
    try:
        with open(os.path.join(path, "commit.txt")) as f:
            built = f"commit {f.read().strip()}"
    except OSError:
        built = "a commit it did not record"
    return f"{dev.group(1)}, {dev.group(2)}, driver {dev.group(3).strip()}; the release binary of {built}, kernels of source hash {kernels.group(1)}"


def gpu_1080p():
    runs = gpu_frames()
    cols = [("multilayer", "4x4"), ("multilayer", "none"), ("tiled", "4x4"), ("ring-gather", "-"), ("layered", "-"),
            ("raytrace", "-"), ("bokeh", "-"), ("gather", "-")]
    run = os.path.relpath(GPU_RUN, os.path.join(ROOT, "docs"))
    lines = caption(
        f"Frame time (ms) at 1920x1080, the median of one GPU timestamp pair around each frame's recording, "
        f"from [{run}/]({run}/) ({device_line()})."
    ) + [
        "| scene | " + " | ".join(m if g == "-" else f"{m} {g}" for m, g in cols) + " |",
        "|---|" + "---|" * len(cols),
    ]
    for scene in sorted({k[0] for k in runs}):
        cells = [f"{frame_ms(runs[(scene, 1920) + c]):.2f}" if (scene, 1920) + c in runs else "-" for c in cols]
        lines.append(f"| {scene} | " + " | ".join(cells) + " |")
    return lines


def gpu_stages():
    runs = gpu_frames()
    lines = caption(
        "Multi-layer splatting merged 4x4 by stage (the columns of Franke et al. 2018, Table 1: per-stage "
        "means of each command's own timestamp pair), against the ring gather (5 rings); same run."
    ) + [
        "| scene | size | frame ms | merge | splat | sort | apply | ring gather ms | ratio | MB |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for scene in sorted({k[0] for k in runs}):
        for width, height in [(1920, 1080), (3840, 2160)]:
            ml, rg = runs.get((scene, width, "multilayer", "4x4")), runs.get((scene, width, "ring-gather", "-"))
            if ml is None or "staged" not in ml:
                continue
            t = ml["staged"]["table1_ms"]
            rg_ms = frame_ms(rg) if rg else None
            ratio = "-" if rg_ms is None else f"{frame_ms(ml) / rg_ms:.1f}"
            lines.append(f"| {scene} | {width}x{height} | {frame_ms(ml):.2f} | {t['merge']:.2f} | {t['splat']:.2f} | {t['sort']:.2f} "
                         f"| {t['apply']:.2f} | {'-' if rg_ms is None else f'{rg_ms:.2f}'} | {ratio} | {ml['staged']['device_bytes'] / 1e6:.1f} |")
    return lines


def image_input_rows(folder):
    """Each `dof bench frame --input images|copied-images` run in `folder` (`images-*.json` and
    `copied-images-*.json`, as `tools/gpu_run.sh` names them): input, scene, size, method, the two
    copies' ms (NaN read in place), the conversion's ms, all commands' ms."""
    rows = []
    for r in bench_runs(folder, "images-", "copied-images-"):
        st = r["stage_ms"]
        copies = st.get("frame/input-color", float("nan")) + st.get("frame/input-depth", float("nan"))
        rows.append((r["input"], r["scene"], f"{r['width']}x{r['height']}", r["method"], copies, st.get("frame/input", float("nan")),
                     r["gpu_ms"]))
    return rows


def ms_cell(ms):
    """Milliseconds to three places, or a dash where there are none (a stage that did not run)."""
    return "–" if math.isnan(ms) else f"{ms:.3f}"


def gpu_image_input():
    """What bringing a renderer's colour and depth images in costs on the GPU run, where it ran."""
    rows = image_input_rows(GPU_RUN)
    if not rows:
        return caption("The run measured no image input (`dof bench frame --input images` and `--input copied-images`; "
                       "`tools/gpu_run.sh` measures both).")[:-1]
    return caption(
        "An RGBA16F colour and a D32 depth image brought in each frame, read in place (`dof bench frame --input images`) "
        "or copied first (`--input copied-images`): the two copies and the conversion to one slot a pixel, per-stage means, "
        "same run."
    ) + ["| input | scene | size | method | copies ms | conversion ms | all commands ms |", "|---|---|---|---|---|---|---|"] + [
        f"| {inp} | {scene} | {size} | {method} | {ms_cell(copies)} | {convert:.3f} | {total:.3f} |"
        for inp, scene, size, method, copies, convert, total in rows
    ]


TABLES = {
    "every-method": eval_every_method,
    "against-ring-gather": eval_against_ring_gather,
    "layered": layered_point_sampled,
    "splat-quality": splat_quality,
    "raytrace": raytrace_point_sampled,
    "memory": memory_1080p,
    "cpu-frame": cpu_frame_1080p,
    "gpu-frames": gpu_1080p,
    "gpu-stages": gpu_stages,
    "gpu-image-input": gpu_image_input,
}

BLOCK = re.compile(r"(<!-- figures:([a-z-]+) -->\n)(.*?)(<!-- /figures:\2 -->)", re.S)


def rewritten(text):
    unknown = [m.group(2) for m in BLOCK.finditer(text) if m.group(2) not in TABLES]
    if unknown:
        raise SystemExit(f"unknown generated tables: {', '.join(unknown)} (known: {', '.join(TABLES)})")
    return BLOCK.sub(lambda m: m.group(1) + "\n".join(TABLES[m.group(2)]()) + "\n" + m.group(4), text)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("action", choices=["measure", "write", "check"])
    p.add_argument("--dof", default=shutil.which("dof") or os.path.join(ROOT, "target", "release", "dof"))
    a = p.parse_args()
    if a.action == "measure":
        try:
            measure(a.dof)
        except (OSError, subprocess.CalledProcessError, ValueError) as e:
            raise SystemExit(f"measure: {e}; no data or plot was written")
        return
    stale = []
    for doc in DOCS:
        path = os.path.join(ROOT, doc)
        with open(path) as f:
            text = f.read()
        new = rewritten(text)
        if new != text:
            stale.append(doc)
            if a.action == "write":
                with open(path, "w") as f:
                    f.write(new)
    if a.action == "check" and stale:
        raise SystemExit(f"generated tables differ from docs/figures/data in {', '.join(stale)}: run `python3 tools/figures.py write`")
    if a.action == "write":
        print("rewrote " + (", ".join(stale) if stale else "nothing (every table current)"))


if __name__ == "__main__":
    main()
