"""OpenImageIO must see our multi-layer EXR as named layers with our values.

Usage: exr_layers_oiio.py <exr_layers_sample executable>
Writes the sample as float and as half into a temporary directory and checks
channel names, sample formats and every value (exact for float, within half
precision for half) against the formula of aov_sample.h.
"""
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

W, H = 13, 9
LAYERS = [("direct", "RGB"), ("indirect", "RGB"), ("specular", "RGB"), ("ao", "Y"),
          ("albedo", "RGB"), ("normal", "XYZ"), ("depth", "Z")]


def expected(layer, channel):
    y, x = np.mgrid[0:H, 0:W]
    k = (layer * 131 + channel * 17 + x * 3 + y * 5) % 1000 - 300
    return k.astype(np.float32) / np.float32(7.0)


def check(writer, tmp, fmt):
    path = f"{tmp}/aov_{fmt}.exr"
    subprocess.run([writer, path, fmt], check=True)
    inp = oiio.ImageInput.open(path)
    if inp is None:
        sys.exit(f"{path}: OpenImageIO cannot open it: {oiio.geterror()}")
    spec = inp.spec()
    names = list(spec.channelnames)
    want = sorted(f"{name}.{c}" for name, chans in LAYERS for c in chans)
    assert sorted(names) == want, f"{path}: channels {names}, expected {want}"
    assert (spec.width, spec.height) == (W, H), f"{path}: size {spec.width}x{spec.height}"
    assert str(spec.format) == fmt, f"{path}: format {spec.format}, expected {fmt}"
    assert spec.get_string_attribute("compression") == "zip"
    pixels = inp.read_image(0, 0, 0, spec.nchannels, "float")
    assert pixels is not None, inp.geterror()
    pixels = np.asarray(pixels).reshape(H, W, spec.nchannels)
    for layer, (name, chans) in enumerate(LAYERS):
        for c, chan in enumerate(chans):
            got = pixels[:, :, names.index(f"{name}.{chan}")]
            ref = expected(layer, c)
            if fmt == "float":
                assert np.array_equal(got, ref), f"{path}: {name}.{chan} differs"
            else:
                err = np.abs(got - ref).max()
                assert np.all(np.abs(got - ref) <= np.abs(ref) * 2.0**-11), \
                    f"{path}: {name}.{chan} off by {err}"
                assert not np.array_equal(got, ref), f"{path}: {name}.{chan} not stored as half"
    print(f"{fmt}: {len(names)} channels in {len(LAYERS)} layers ok")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with tempfile.TemporaryDirectory(prefix="dvsgi_exr_layers_") as tmp:
        for fmt in ("float", "half"):
            check(sys.argv[1], tmp, fmt)


if __name__ == "__main__":
    main()
