#!/usr/bin/env python3
"""Irradiance at a point from a 180-degree equidistant fisheye render made there
(scripts/cycles-reference.py --probe): E / pi = (1 / pi) * integral of L cos(theta) over the
hemisphere, each pixel weighted by its solid angle. Prints E / pi (R, G, B) and its luminance.

    scripts/probe-irradiance.py PROBE.exr
"""
import sys

import numpy as np
import OpenImageIO as oiio


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: scripts/probe-irradiance.py PROBE.exr")
    inp = oiio.ImageInput.open(sys.argv[1])
    if inp is None:
        sys.exit(f"probe-irradiance: {sys.argv[1]}: {oiio.geterror()}")
    img = np.asarray(inp.read_image(format="float"), dtype=np.float64)[:, :, :3]
    inp.close()
    h, w = img.shape[:2]
    radius = min(w, h) / 2.0
    y, x = np.mgrid[0:h, 0:w]
    r = np.hypot(x + 0.5 - w / 2.0, y + 0.5 - h / 2.0) / radius
    theta = r * np.pi / 2.0  # equidistant: the angle from the axis grows with the radius
    inside = r < 1.0
    # A pixel of side 1/radius at angle theta subtends (pi/2 / radius)^2 sin(theta) / theta.
    sinc = np.where(theta > 1e-9, np.sin(theta) / np.maximum(theta, 1e-9), 1.0)
    weight = np.where(inside, np.cos(theta) * sinc, 0.0) * (np.pi / 2.0 / radius) ** 2 / np.pi
    e = (img * weight[:, :, None]).sum(axis=(0, 1))
    lum = float(e @ np.array([0.2126, 0.7152, 0.0722]))
    print(f"E/pi {e[0]:.6f} {e[1]:.6f} {e[2]:.6f}  luminance {lum:.6f}  (weights sum {weight.sum():.4f}, 1 for a full hemisphere)")


main()
