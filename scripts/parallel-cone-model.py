#!/usr/bin/env python3
"""A one-dimensional model of a cone running parallel to a floor (docs/quality.md, "One bounce at a
time"): the cone tracer's diameter, clearance, level rounding, step and step correction
(shaders/lib/cone_trace.glsl, default settings: beta 0.5, clearance K = 3, origin 2.5 voxels off the
surface it leaves, 30-degree half-angle), with the floor a one-voxel layer whose coverage of a cell's
cross-section is 1 / (cell size), filtered bilinearly across the floor. Prints the opacity the cone
accumulates within 56 voxels at several heights, next to the fraction of its rays that reach the floor
within that distance (uniform over the cone's solid angle, Monte Carlo).

    scripts/parallel-cone-model.py [K]
"""
import math
import sys

import numpy as np


def traced_opacity(h, clearance, distance=56.0, beta=0.5, offset=2.5, tan_half=math.tan(math.radians(30))):
    t, transmittance = 1.0, 1.0
    while t < distance and transmittance > 0.005:
        cone = max(2 * t * tan_half, 2.0)
        d = cone if clearance <= 0 else min(max((offset + t - 1.0) / clearance, 2.0), cone)
        level = min(max(round(math.log2(d) - 1), 0), 5)
        cell = 2 ** (level + 1)
        # Cells of this level stacked on the floor layer [0, 1): cell 0 holds it, coverage 1 / cell.
        x = (h + 0.5) / cell - 0.5
        j = math.floor(x)
        f = x - j
        alpha = (1.0 / cell) * ((1 - f) * (j == 0) + f * (j + 1 == 0))
        step = max(min(beta * cone, d), 0.5)
        transmittance *= (1 - alpha) ** (step / d)
        t += step
    return 1 - transmittance


def rays_reaching_floor(h, distance=56.0, samples=200000, seed=3):
    rng = np.random.default_rng(seed)
    c = 1 - rng.random(samples) * (1 - math.cos(math.radians(30)))
    s, phi = np.sqrt(1 - c * c), 2 * math.pi * rng.random(samples)
    down = s * np.sin(phi)  # downward component; c is the horizontal axis component
    reach = np.where(down > 0, h / np.maximum(down, 1e-12) * c, np.inf)  # horizontal distance to the floor
    return float((reach <= distance).mean())


if __name__ == "__main__":
    k = float(sys.argv[1]) if len(sys.argv) > 1 else 3.0
    for h in (2, 4, 8, 16):
        print("height %2d voxels: model opacity %.2f (clearance %g), %.2f without clearance; rays reaching the "
              "floor %.2f" % (h, traced_opacity(h, k), k, traced_opacity(h, 0), rays_reaching_floor(h)))
