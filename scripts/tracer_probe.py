"""What the probe scripts that set a voxel dump against the CPU tracer share (scripts/floor-flux.py,
scripts/wall-gather-probe.py): the tracer of scripts/bounce-reference.py on a scene, and a dump's grid."""
import importlib.util
import os
import sys

import numpy as np

LUMA = np.array([0.2126, 0.7152, 0.0722])


def bounce_reference():
    """scripts/bounce-reference.py as a module (its name has a hyphen)."""
    here = os.path.dirname(os.path.abspath(__file__))
    spec = importlib.util.spec_from_file_location("bounce_reference", os.path.join(here, "bounce-reference.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def scene_tracer(path):
    """(the bounce-reference module, a Tracer over the scene's triangles, the scene's punctual lights)."""
    br = bounce_reference()
    tris, albedo, emission, lights, _ = br.load(path)
    return br, br.Tracer(tris, albedo, emission), lights


def dump_grid(path):
    """A `dvsgi render --voxel-dump` file: (its rows, grid coordinates, centres, voxel size, the grid's
    origin). centre = origin + (grid + 0.5) * size, the size fitted over x."""
    d = np.load(path)
    grid, centre = d[:, 0:3].astype(int), d[:, 3:6].astype(np.float64)
    size = float(np.polyfit(grid[:, 0] + 0.5, centre[:, 0], 1)[0]) if np.ptp(grid[:, 0]) > 0 else 0.0
    if not size > 0:
        sys.exit("%s: cannot tell the voxel size (one column of voxels)" % path)
    return d, grid, centre, size, centre[0] - (grid[0] + 0.5) * size
