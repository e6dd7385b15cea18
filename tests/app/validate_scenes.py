#!/usr/bin/python3
"""Every scene file under shared/scenes through `dvsgi render --validate` at a
small size (64x64, 32^3 voxels, 256^2 shadow maps): the Khronos validation
layer, with synchronization validation, must report no error. A scene that
does not render, a missing scenes folder or an empty one fails the test.

    validate_scenes.py DVSGI SHARED_DIR WORKDIR [--only TEXT] [--jobs 2] [--report FILE.json]

The report lists each distinct validation message id with the scenes that
raised it and one shortened example (for SYNC-HAZARD-* messages, the hazard
to fix in the pass code)."""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import time

EXTENSIONS = (".gltf", ".glb", ".obj", ".ply")
MESSAGE = re.compile(r"^\[validation (error|warning)\] (.*)$")
MESSAGE_ID = re.compile(r"\[ ([A-Za-z0-9_.:-]+) \]")


def scene_files(root):
    found = []
    for folder, _, files in os.walk(root):
        found += [os.path.join(folder, f) for f in files if f.lower().endswith(EXTENSIONS)]
    return sorted(found)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dvsgi")
    ap.add_argument("shared")
    ap.add_argument("work")
    ap.add_argument("--only")
    ap.add_argument("--report")
    # Loading (one thread) dominates a 64x64 render: two at a time fill two cores.
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    root = os.path.join(args.shared, "scenes")
    if not os.path.isdir(root):
        sys.exit("validate_scenes: no scenes folder at %s" % root)
    scenes = scene_files(root)
    if args.only:
        scenes = [s for s in scenes if args.only in s]
    if not scenes:
        sys.exit("validate_scenes: no scene files under %s" % root)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)

    def render(i, scene):
        out = os.path.join(args.work, "%02d.exr" % i)
        argv = [args.dvsgi, "render", scene, "--width", "64", "--height", "64", "--voxels", "32",
                "--shadow-map", "256", "--validate", "--quiet", "--out", out, "--png", "none"]
        start = time.monotonic()
        # The limit only catches a hang; it judges nothing.
        proc = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=1800)
        return proc, out, time.monotonic() - start

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda a: render(*a), enumerate(scenes)))

    failures = []
    by_id = {}  # message id -> {"severity", "scenes", "count", "example"}
    for scene, (proc, out, seconds) in zip(scenes, results):
        name = os.path.relpath(scene, root)
        stderr = proc.stderr.decode("utf-8", "replace")
        errors = 0
        for line in stderr.splitlines():
            m = MESSAGE.match(line)
            if not m:
                continue
            severity, text = m.groups()
            errors += severity == "error"
            mid = MESSAGE_ID.search(text)
            key = mid.group(1) if mid else text[:60]
            entry = by_id.setdefault(key, {"severity": severity, "scenes": [], "count": 0, "example": text[:700]})
            entry["count"] += 1
            if name not in entry["scenes"]:
                entry["scenes"].append(name)
        status = "ok"
        if proc.returncode != 0:
            status = "exit %d" % proc.returncode
        elif errors:
            status = "%d validation errors but exit 0" % errors
        elif not os.path.isfile(out):
            status = "exit 0 but no image"
        print("%-50s %5.1f s  %s%s" % (name, seconds, status,
                                       " (%d validation errors)" % errors if errors and proc.returncode else ""))
        if status != "ok":
            last = [l for l in stderr.splitlines() if l.strip() and not MESSAGE.match(l)]
            failures.append("%s: %s%s" % (name, status, (": " + last[-1]) if last else ""))

    for key, entry in sorted(by_id.items()):
        print("%s %s x%d in %s\n    %s" % (entry["severity"], key, entry["count"], ", ".join(entry["scenes"]),
                                           entry["example"][:300]))
    if args.report:
        with open(args.report, "w") as f:
            json.dump(by_id, f, indent=1)
    print("validate_scenes: %d scenes, %d failed" % (len(scenes), len(failures)))
    if failures:
        sys.exit("validate_scenes: FAILED\n  " + "\n  ".join(failures))


if __name__ == "__main__":
    main()
