"""A tiny line-plot canvas for the scripts' PNG figures (numpy only; no text:
the docs caption each plot). Used by flicker-plot.py and pv-walk.py."""
import math

import numpy as np


class Canvas:
    """W x H white image with a margin M; y maps [lo, hi] (log10 when log)."""

    def __init__(self, points, lo, hi, log=False, W=640, H=320, M=20):
        self.W, self.H, self.M, self.points, self.log = W, H, M, points, log
        self.lo, self.hi = (math.log10(lo), math.log10(hi)) if log else (lo, hi)
        self.img = np.full((H, W, 3), 255, np.uint8)

    def y_of(self, value):
        v = math.log10(max(value, 10.0 ** self.lo)) if self.log else value
        v = min(max(v, self.lo), self.hi)
        return int(round(self.H - self.M - (v - self.lo) / (self.hi - self.lo) * (self.H - 2 * self.M)))

    def x_of(self, i):
        return int(round(self.M + i * (self.W - 2 * self.M) / max(self.points - 1, 1)))

    def hline(self, y, colour, dashed=False):
        for x in range(self.M, self.W - self.M):
            if not dashed or (x // 6) % 2 == 0:
                self.img[y, x] = colour

    def line(self, x0, y0, x1, y1, colour):
        n = max(abs(x1 - x0), abs(y1 - y0), 1)
        for k in range(n + 1):
            x = x0 + (x1 - x0) * k // n
            y = y0 + (y1 - y0) * k // n
            self.img[max(y - 1, 0):y + 2, max(x - 1, 0):x + 2] = colour

    def series(self, values, colour):
        """values[i] at point i; None breaks the line."""
        pts = [(self.x_of(i), self.y_of(v)) if v is not None else None for i, v in enumerate(values)]
        for a, b in zip(pts, pts[1:]):
            if a and b:
                self.line(a[0], a[1], b[0], b[1], colour)
