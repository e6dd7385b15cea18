#!/usr/bin/python3
"""A dvsgi render of a scene without a shared reference against Cycles references split by bounce.

    scripts/scene-compare.py REF_PREFIX RENDER_AOV.exr [FIRST_BOUNCE_AOV.exr] [--json OUT.json]
                             [--row LABEL]

REF_PREFIX names three Cycles renders of the same scene, camera and size
(scripts/cycles-reference.py): REF_PREFIX.exr (converged, 64 bounces),
REF_PREFIX-b0.exr (direct light only) and REF_PREFIX-b1.exr (direct + one bounce);
docs/quality/cycles/ holds them for the shared Sponza and Sibenik scenes.
RENDER_AOV.exr is dvsgi's `--aov` of the render under test and FIRST_BOUNCE_AOV.exr
the `--aov` of the same render with `--bounces 0` (the per-pixel gather over the
voxels' direct light, which is the first bounce). Prints mean-luminance ratios,
dvsgi / Cycles:
  direct      dvsgi's direct term against the direct-only render;
  indirect    dvsgi's indirect term against converged - direct-only;
  first       the first bounce against (direct + one bounce) - direct-only;
  later       the bounces after it (converged - first) against converged - (direct + one bounce);
  shadowed    the indirect term where neither renderer has direct light (so that
              shadow edges, where the two renderers' direct light differs, stay out).
--json writes them to a file; --row prints them instead as one markdown table row
(| LABEL | direct | indirect | first | later | shadowed |, which needs FIRST_BOUNCE_AOV).
"""
import json
import os
import sys

import numpy as np
import OpenImageIO as oiio

LUM = np.array([0.2126, 0.7152, 0.0722])


def fail(msg):
    # Named after the script that was run: scripts/bounce-by-facing.py reads its images with these too.
    print("%s: %s" % (os.path.splitext(os.path.basename(sys.argv[0]))[0], msg), file=sys.stderr)
    sys.exit(1)


def layer_pixels(path, layer=None, channels="RGB"):
    """The three channels of an EXR's `layer` (its first three channels without one), float64 H x W x 3."""
    inp = oiio.ImageInput.open(path)
    if inp is None:
        fail("%s: cannot open (%s)" % (path, oiio.geterror()))
    names = list(inp.spec().channelnames)
    pixels = np.asarray(inp.read_image(format="float"), dtype=np.float64)
    inp.close()
    if layer is None:
        index = [0, 1, 2]
    else:
        wanted = [layer + "." + c for c in channels]
        if not all(w in names for w in wanted):
            fail("%s: no %s layer (write it with dvsgi render --aov)" % (path, layer))
        index = [names.index(w) for w in wanted]
    values = pixels[:, :, index]
    if not np.all(np.isfinite(values)):
        fail("%s: non-finite pixels" % path)
    return values


def luminance(path, layer=None):
    return layer_pixels(path, layer) @ LUM


def take_option(argv, name):
    """The value of `name VALUE` in argv (None if absent) and argv without the pair."""
    if name not in argv:
        return None, argv
    i = argv.index(name)
    if i + 1 >= len(argv):
        fail("%s needs a value" % name)
    return argv[i + 1], argv[:i] + argv[i + 2:]


def main(argv):
    out_json, argv = take_option(argv, "--json")
    row, argv = take_option(argv, "--row")
    if len(argv) not in (2, 3) or (row is not None and len(argv) != 3):
        fail("usage: scene-compare.py REF_PREFIX RENDER_AOV.exr [FIRST_BOUNCE_AOV.exr] [--json OUT.json] "
             "[--row LABEL] (--row needs FIRST_BOUNCE_AOV.exr)")
    prefix, render = argv[0], argv[1]
    ref_full, ref_b0, ref_b1 = (luminance(prefix + s + ".exr") for s in ("", "-b0", "-b1"))
    direct, indirect = luminance(render, "direct"), luminance(render, "indirect")
    if direct.shape != ref_full.shape:
        fail("%s is %s, the references %s: render at the references' size" % (render, direct.shape, ref_full.shape))
    shadowed = (direct < 1e-4) & (ref_b0 < 1e-5)
    r = {
        "direct": direct.mean() / ref_b0.mean(),
        "indirect": indirect.mean() / (ref_full - ref_b0).mean(),
        "shadowed_indirect": indirect[shadowed].mean() / (ref_full - ref_b0)[shadowed].mean(),
        "shadowed_fraction": float(shadowed.mean()),
    }
    if len(argv) == 3:
        first = luminance(argv[2], "indirect")
        r["first"] = first.mean() / (ref_b1 - ref_b0).mean()
        r["later"] = (indirect - first).mean() / (ref_full - ref_b1).mean()
    if row is not None:
        print("| %s | %.3f | **%.3f** | %.3f | %.3f | %.3f |" % (row, r["direct"], r["indirect"], r["first"],
                                                                r["later"], r["shadowed_indirect"]))
    else:
        for k, v in r.items():
            print("%-18s %.4f" % (k, v))
    if out_json:
        with open(out_json, "w") as f:
            json.dump({k: float(v) for k, v in r.items()}, f, indent=2)


if __name__ == "__main__":
    main(sys.argv[1:])
