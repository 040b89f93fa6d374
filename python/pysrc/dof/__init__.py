"""Order-correct depth of field on numpy arrays: every method of the `dof` library (multi-layer
tiled splatting, Franke et al. 2018, and the methods it is measured against), on the CPU or Vulkan,
with the library's EXR reader and writer (flat and deep files).

`blur` blurs, `methods` lists the methods, `read_exr`/`write_exr` read and write EXR files,
`read_deep_exr` and `deep_layers` take deep files, `exr_sequence` lists a sequence's files.
`dof.farm` renders sequences on a Dask cluster (`pip install dof[farm]`).
"""

from ._native import (
    blur,
    deep_layers,
    exr_sequence,
    is_deep_exr,
    methods,
    read_deep_exr,
    read_exr,
    write_exr,
)

__all__ = [
    "blur",
    "deep_layers",
    "exr_sequence",
    "is_deep_exr",
    "methods",
    "read_deep_exr",
    "read_exr",
    "write_exr",
]
