"""`dof.farm` on a local Dask cluster of two worker processes: a sequence renders as it does in one
process, and a worker killed in the middle of a frame loses no frame and leaves no partial file."""

import dataclasses
import os
import shutil
import sys

import cloudpickle
import numpy as np
import pytest
from dask.distributed import Client, LocalCluster

import dof
import dof.farm

DEEP = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data", "deep")

# This module's functions run on the workers, which cannot import it: send them by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


def shot(tmp_path, frames=6):
    for n in range(1001, 1001 + frames):
        shutil.copy(os.path.join(DEEP, "scene-rle.exr"), tmp_path / f"shot-{n}.exr")
    return str(tmp_path / "shot-####.exr")


def dies_once(marker, number):
    """A task that kills its worker process the first time it reaches frame `number` (as a
    machine lost mid-frame), then renders."""

    def task(frame):
        if frame.number == number and not os.path.exists(marker):
            open(marker, "w").close()
            os._exit(1)
        return dof.farm.render_frame(frame)

    return task


def test_a_sequence_on_two_workers_loses_no_frame_when_one_dies(tmp_path):
    pattern = shot(tmp_path)
    focus = lambda n: 3.0 + 0.5 * (n - 1001)  # noqa: E731 (a focus pull, frame by frame)
    frames = dof.farm.sequence(pattern, str(tmp_path / "farm" / "blur-####.exr"), focus=focus, aperture_radius=0.05)
    assert [f.number for f in frames] == list(range(1001, 1007))
    assert frames[1].lens["focus"] == 3.5
    marker = str(tmp_path / "died")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
        written = dof.farm.render(client, frames, task=dies_once(marker, 1003))
    assert os.path.exists(marker), "a worker died mid-frame"
    assert written == [f.out for f in frames]
    # The same frames in this process, one after another.
    here = [dataclasses.replace(f, out=f.out.replace("farm", "here")) for f in frames]
    dof.farm.render_here(here)
    for a, b in zip(frames, here):
        np.testing.assert_array_equal(dof.read_exr(a.out)[0], dof.read_exr(b.out)[0])
    leftovers = [n for n in os.listdir(tmp_path / "farm") if not n.startswith("blur-")]
    assert leftovers == [], "no partial output is left behind"
    # The focus moved: frames differ.
    assert not np.array_equal(dof.read_exr(frames[0].out)[0], dof.read_exr(frames[-1].out)[0])


def test_frame_ranges_and_bad_arguments(tmp_path):
    pattern = shot(tmp_path, frames=3)
    out = str(tmp_path / "o" / "b-####.exr")
    part = dof.farm.sequence(pattern, out, frame_range=(1002, 1003), focus=4.0, f_number=2.0)
    assert [f.out for f in part] == [str(tmp_path / "o" / "b-1002.exr"), str(tmp_path / "o" / "b-1003.exr")]
    with pytest.raises(ValueError, match="no frame"):
        dof.farm.sequence(pattern, out, frame_range=(5, 6), focus=4.0, f_number=2.0)
    with pytest.raises(ValueError, match="unknown lens"):
        dof.farm.sequence(pattern, out, focus=4.0, fnumber=2.0)
    with pytest.raises(ValueError, match="holds no #"):
        dof.farm.sequence(pattern, str(tmp_path / "b.exr"), focus=4.0, f_number=2.0)
    assert dof.is_deep_exr(os.path.join(DEEP, "scene-rle.exr"))
    assert not dof.is_deep_exr(os.path.join(DEEP, "scene-flat.exr"))
