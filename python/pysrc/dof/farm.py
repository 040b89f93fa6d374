"""Sequences and sweeps on a Dask cluster (`dask.distributed`): one task a frame.

    from dask.distributed import Client, LocalCluster
    import dof.farm

    frames = dof.farm.sequence("shot-####.exr", "out/blur-####.exr", focus=4.0, f_number=2.0)
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        written = dof.farm.render(client, frames)

Each task reads its frame's EXR (flat layers, or deep files made into layers for the frame's lens),
blurs it with `dof.blur` and writes the result with the library's writer, which writes a temporary
file and renames it: an output is complete or absent, never cut short. Dask runs a task again on
another worker when its worker dies (the scheduler reschedules a lost worker's tasks), and
`retries` times when it raises, so a frame is never lost. Frames are independent, so the same list
can be split by `frame_range` as a render farm's manager splits a shot, and rendered by
`dof render --frame-range` on other machines with the same result.

Dask rather than Ray: a sequence is a bag of independent frames whose inputs and outputs are files,
which is exactly Dask's futures API; Dask is pure Python, starts a local cluster in-process for
tests, and needs no object store or extra daemons.

`python -m dof.farm PATTERN OUT --focus F --f-number N [--workers 2]` renders a sequence on a
local cluster and, with `--compare`, times the same frames in one process.
"""

from __future__ import annotations

import dataclasses
import os
import re
from typing import Callable, Sequence, Union

import dof

Value = Union[float, Callable[[int], float], None]

# The lens arguments `blur` and `deep_layers` share.
LENS = ("focus", "aperture_radius", "f_number", "focal_length", "sensor_height", "yfov", "pixels_per_unit", "metres_per_unit")


@dataclasses.dataclass(frozen=True)
class Frame:
    """One frame of work: the EXR to read (one file, or several deep files to merge), where to
    write, the lens (`blur`'s arguments), the method and its options, and the layer budget of
    deep input."""

    scene: tuple
    out: str
    lens: dict
    method: str = "multilayer"
    options: dict = dataclasses.field(default_factory=dict)
    max_layers: int = 4
    number: int = 0


def _numbered(pattern: str, number: int) -> str:
    """`pattern` with its run of `#` replaced by `number`, padded to the run's length."""
    run = re.search(r"#+", os.path.basename(pattern))
    if run is None:
        raise ValueError(f"the output pattern {pattern!r} holds no # for the frame number (e.g. out/blur-####.exr)")
    return os.path.join(os.path.dirname(pattern), os.path.basename(pattern).replace(run.group(0), f"{number:0{len(run.group(0))}d}", 1))


def sequence(
    pattern: str,
    out: str,
    *,
    frame_range: tuple | None = None,
    method: str = "multilayer",
    max_layers: int = 4,
    options: dict | None = None,
    **lens: Value,
) -> list:
    """The frames of the EXR sequence `pattern` (`shot-####.exr`, as `dof render --scene` takes
    it), each written to `out` with its frame number in place of the `#` run. Lens values (the
    keywords of `blur`: `focus`, `f_number` or `aperture_radius`, ...) are numbers, or functions of
    the frame number (a focus pull, a camera's recorded focus). `frame_range=(first, last)` keeps
    the frames numbered first to last."""
    unknown = set(lens) - set(LENS)
    if unknown:
        raise ValueError(f"unknown lens arguments {sorted(unknown)}; the lens takes {', '.join(LENS)}")
    frames = []
    for number, path in dof.exr_sequence(pattern):
        if frame_range is not None and not frame_range[0] <= number <= frame_range[1]:
            continue
        values = {k: (v(number) if callable(v) else v) for k, v in lens.items() if v is not None}
        frames.append(Frame((str(path),), _numbered(out, number), values, method, dict(options or {}), max_layers, number))
    if not frames:
        raise ValueError(f"no frame of {pattern} lies in the frame range {frame_range}")
    return frames


def render_frame(frame: Frame) -> str:
    """Renders one frame and writes it (the task each worker runs); returns the output's path."""
    paths = list(frame.scene)
    if all(dof.is_deep_exr(p) for p in paths):
        counts, samples = dof.read_deep_exr(paths)
        fragments, counts = dof.deep_layers(counts, samples, max_layers=frame.max_layers, **frame.lens)
    elif len(paths) == 1:
        fragments, counts = dof.read_exr(paths[0], layers=True)
    else:
        raise ValueError(f"several files merge only when all are deep: {paths}")
    image = dof.blur(fragments, counts, method=frame.method, **frame.lens, **frame.options)
    os.makedirs(os.path.dirname(os.path.abspath(frame.out)), exist_ok=True)
    dof.write_exr(frame.out, image)
    return frame.out


def render(client, frames: Sequence[Frame], *, retries: int = 2, task: Callable[[Frame], str] = render_frame) -> list:
    """Renders `frames` on the cluster of `client` (a `dask.distributed.Client`), one task a
    frame, and returns their outputs in order once all are written. A frame whose worker dies runs
    again on another; one that raises runs again up to `retries` times, then its error is raised
    here. `task` replaces the per-frame work (for sweeps: any function of one frame)."""
    futures = client.map(task, list(frames), retries=retries, pure=False)
    return client.gather(futures)


def render_here(frames: Sequence[Frame], task: Callable[[Frame], str] = render_frame) -> list:
    """The same frames in this process, one after another (the comparison for `render`)."""
    return [task(f) for f in frames]


def _main(argv=None) -> None:
    import argparse
    import time

    from dask.distributed import Client, LocalCluster

    parser = argparse.ArgumentParser(prog="python -m dof.farm", description=__doc__.split("\n\n")[0])
    parser.add_argument("pattern", help="the EXR sequence, e.g. shot-####.exr")
    parser.add_argument("out", help="the output pattern, e.g. out/blur-####.exr")
    parser.add_argument("--focus", type=float, required=True)
    parser.add_argument("--f-number", type=float)
    parser.add_argument("--aperture-radius", type=float)
    parser.add_argument("--method", default="multilayer")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--frame-range", help="FIRST:LAST")
    parser.add_argument("--compare", action="store_true", help="also render the frames in this process and time both")
    args = parser.parse_args(argv)
    frame_range = tuple(int(v) for v in args.frame_range.split(":")) if args.frame_range else None
    frames = sequence(
        args.pattern,
        args.out,
        frame_range=frame_range,
        method=args.method,
        focus=args.focus,
        f_number=args.f_number,
        aperture_radius=args.aperture_radius,
    )
    with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
        client.run(lambda: __import__("dof"))  # imported on every worker before the clock starts
        start = time.perf_counter()
        render(client, frames)
        cluster_s = time.perf_counter() - start
    print(f"{len(frames)} frames on {args.workers} workers: {cluster_s:.2f} s")
    if args.compare:
        start = time.perf_counter()
        render_here(frames)
        here_s = time.perf_counter() - start
        print(f"{len(frames)} frames in one process: {here_s:.2f} s; speed-up {here_s / cluster_s:.2f}x")


if __name__ == "__main__":
    _main()
