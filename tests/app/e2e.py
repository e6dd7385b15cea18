"""What the end-to-end scripts of this folder share: running dvsgi, reading an EXR's channels,
and a list of failed checks."""
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio


class Runner:
    """Runs `dvsgi` with `base` options before each call's own, and keeps the failed checks."""

    def __init__(self, dvsgi, base):
        self.dvsgi, self.base, self.failures = dvsgi, list(base), []

    def run(self, *args):
        p = subprocess.run([self.dvsgi, *self.base, *args], capture_output=True, text=True, timeout=300)
        return p.returncode, p.stderr

    def render(self, name, *extra):
        rc, err = self.run(*extra)
        print("%-34s rc=%d %s" % (name, rc, err.strip()))
        if rc != 0:
            sys.exit("FAIL %s: rc=%d %s" % (name, rc, err))

    def check(self, cond, what):
        print("%-6s %s" % ("ok" if cond else "FAIL", what))
        if not cond:
            self.failures.append(what)

    def finish(self):
        print("%d failed" % len(self.failures))
        sys.exit(1 if self.failures else 0)


def read(path):
    """An EXR's channels by name, and each channel's sample type."""
    img = oiio.ImageInput.open(path)
    if img is None:
        sys.exit("FAIL cannot open %s: %s" % (path, oiio.geterror()))
    spec = img.spec()
    px = img.read_image(oiio.FLOAT)
    formats = [str(f) for f in spec.channelformats] or [str(spec.format)] * spec.nchannels
    img.close()
    return {n: px[:, :, i] for i, n in enumerate(spec.channelnames)}, dict(zip(spec.channelnames, formats))


def rgb(ch, layer=""):
    p = layer + "." if layer else ""
    return np.stack([ch[p + c] for c in "RGB"], axis=-1)
