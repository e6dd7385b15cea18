#!/usr/bin/python3
"""The chapter's Figure 6.10 from a `dvsgi bench --pv-tables` JSON: pv's
average Hausdorff distance (% of the bounding-box diagonal) per frame of the
orbits, one line per model at one grid size (blue bunny, red dragon, green
buddha), each model's exact geometric voxelizer as a dashed line in its colour;
linear from 0 to the largest value, grey lines every 1 %. No text: docs/pv.md
captions the plot.
Usage: pv-tables-plot.py PV_TABLES.json OUT.png [VOXELS]   (needs numpy and ../shared/tools)"""
import json, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/tools"))
import compare  # noqa: E402  (write_png)
import plot_png  # noqa: E402

rows = json.load(open(sys.argv[1]))["table_6_2"]
voxels = int(sys.argv[3]) if len(sys.argv) > 3 else 128
rows = [r for r in rows if r["voxels"] == voxels]
if not rows:
    sys.exit("no Table 6.2 rows at %d^3 in %s" % (voxels, sys.argv[1]))
top = max(max(r["pv_per_frame"]) for r in rows) * 1.05
canvas = plot_png.Canvas(max(len(r["pv_per_frame"]) for r in rows), 0.0, top)
for k in range(int(top) + 1):
    canvas.hline(canvas.y_of(float(k)), (200, 200, 200))
colours = {"bunny": (30, 60, 220), "dragon": (220, 40, 40), "buddha": (20, 150, 60)}
for r in rows:
    colour = colours.get(r["model"], (0, 0, 0))
    canvas.hline(canvas.y_of(r["geometric"]), colour, True)
    canvas.series(r["pv_per_frame"], colour)
compare.write_png(sys.argv[2], canvas.img)
