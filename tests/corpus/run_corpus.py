#!/usr/bin/env python3
"""Runs every malformed-input case through `dvsgi render` and checks the
project's rule: a non-zero exit with exactly one stderr line naming the file
or option (and no output file left behind), or exit 0 with an EXR whose pixels
are all finite and >= 0. Never a signal, never a hang.

    run_corpus.py [--bin DVSGI] [--corpus DIR] [--work DIR] [--jobs 2] [--timeout 20] [--only TEXT]

The binary comes from --bin or $DVSGI_BIN. Without --corpus the cases are
generated first, into --work (ctest: the build folder) or a temporary folder."""

import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# Cases whose fix lies outside src/scene (the CLI, the renderer, device
# limits). Each still runs: it must fail the check as recorded here, and a
# case that starts passing is reported so that it is removed from this list.
EXPECTED_FAILURES = {
}


def load_cases(corpus):
    cases = []
    for name in sorted(os.listdir(corpus)):
        folder = os.path.join(corpus, name)
        meta = os.path.join(folder, "case.json")
        if os.path.isfile(meta):
            with open(meta) as f:
                cases.append((name, folder, json.load(f)))
    return cases


def slug_of(name):
    return name.split("_", 1)[1] if "_" in name else name


def command(binary, folder, meta, out_exr):
    def sub(text):
        return text.replace("{case}", folder).replace("{out}", out_exr)
    if meta.get("argv"):
        return [binary] + [sub(a) for a in meta["argv"]]
    argv = [binary, "render"]
    if meta.get("scene") is not None:
        argv.append(os.path.join(folder, meta["scene"]))
    # The smallest shadow map halves a lavapipe render (0.44 s instead of
    # 0.83 s) and changes nothing about what the checks look for.
    argv += ["--width", "32", "--height", "32", "--voxels", str(meta.get("voxels", 32)), "--shadow-map", "256",
             "--quiet", "--out", out_exr, "--png", "none"]
    return argv + [sub(a) for a in meta.get("args", [])]


def image_problem(path):
    """None when the EXR exists and every value is finite and >= 0."""
    import numpy as np
    import OpenImageIO as oiio
    if not os.path.isfile(path):
        return "exit 0 but no output image"
    inp = oiio.ImageInput.open(path)
    if not inp:
        return "output image cannot be read: " + oiio.geterror()
    pixels = inp.read_image("float")
    inp.close()
    if pixels is None or pixels.size == 0:
        return "output image is empty"
    pixels = np.asarray(pixels)
    if not np.all(np.isfinite(pixels)):
        return "output image has %d non-finite values" % int(np.sum(~np.isfinite(pixels)))
    if np.any(pixels < 0):
        return "output image has %d negative values (min %g)" % (int(np.sum(pixels < 0)), float(pixels.min()))
    return None


def judge(proc, meta, folder, out_dir, out_exr):
    """The problem with one finished run, or None."""
    stderr = proc.stderr.decode("utf-8", "replace")
    lines = [line for line in stderr.splitlines() if line.strip()]
    expect = meta.get("expect", "any")
    if proc.returncode < 0:
        return "crash (signal %d)" % -proc.returncode
    if proc.returncode > 128:
        return "crash (exit %d)" % proc.returncode
    if proc.returncode != 0:
        left = os.listdir(out_dir)
        names = meta.get("names") or [folder]
        if expect == "ok":
            return "expected a render, got exit %d: %s" % (proc.returncode, stderr.strip()[:300])
        if len(lines) != 1:
            return "error output is %d lines, not 1: %r" % (len(lines), stderr[:400])
        if not any(n in lines[0] for n in names):
            return "error line names none of %s: %s" % (names, lines[0][:300])
        if left:
            return "failed but left files behind: %s" % left
        return None
    if expect == "error":
        return "expected an error, got exit 0 (stderr: %s)" % stderr.strip()[:200]
    return image_problem(out_exr)


def run_case(binary, work, timeout, case):
    """(name, problem or None, seconds, exit status or None after a timeout)."""
    name, folder, meta = case
    out_dir = os.path.join(work, name)
    os.makedirs(out_dir)
    out_exr = os.path.join(out_dir, "x.exr")
    argv = command(binary, folder, meta, out_exr)
    # A case's own limit is for the plain build; a slower one (sanitizers) raises both.
    timeout = max(meta.get("timeout") or 0, timeout)
    start = time.monotonic()
    try:
        proc = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return name, "hang (no exit within %g s)" % timeout, timeout, None
    seconds = time.monotonic() - start
    return name, judge(proc, meta, folder, out_dir, out_exr), seconds, proc.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=os.environ.get("DVSGI_BIN"))
    ap.add_argument("--corpus")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20.0)
    ap.add_argument("--only")
    ap.add_argument("--work", help="folder for generated cases and outputs (emptied first, kept afterwards)")
    args = ap.parse_args()
    try:
        import numpy  # noqa: F401
        import OpenImageIO  # noqa: F401
    except ImportError as e:
        sys.exit("run_corpus: cannot check images (%s); install python3-openimageio and python3-numpy" % e)
    if not args.bin or not os.access(args.bin, os.X_OK):
        sys.exit("run_corpus: dvsgi binary not found (give --bin or DVSGI_BIN): %r" % args.bin)

    if args.work:
        work = os.path.abspath(args.work)
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
    else:
        work = tempfile.mkdtemp(prefix="dvsgi_corpus_")
    try:
        corpus = args.corpus
        if not corpus:
            corpus = os.path.join(work, "cases")
            subprocess.run([sys.executable, os.path.join(HERE, "generate.py"), corpus], check=True)
        cases = load_cases(corpus)
        if args.only:
            cases = [c for c in cases if args.only in c[0]]
        if not cases:
            sys.exit("run_corpus: no cases found in %s" % corpus)
        outputs = os.path.join(work, "out")
        os.makedirs(outputs)
        start = time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            results = list(pool.map(lambda c: run_case(args.bin, outputs, args.timeout, c), cases))
        elapsed = time.monotonic() - start

        failures, xfail, slowest = [], [], sorted(results, key=lambda r: -r[2])[:3]
        known = dict(EXPECTED_FAILURES)
        for name, problem, _, _ in results:
            slug = slug_of(name)
            if slug in known:
                if problem is None:
                    failures.append((name, "passes now: remove it from EXPECTED_FAILURES"))
                else:
                    xfail.append((name, problem, known[slug]))
            elif problem is not None:
                failures.append((name, problem))
        for name, problem, reason in xfail:
            print("XFAIL %s: %s [%s]" % (name, problem, reason))
        for name, problem in failures:
            print("FAIL  %s: %s" % (name, problem))
        renders = sum(1 for _, _, _, rc in results if rc == 0)
        print("corpus: %d cases (%d rendered), %d passed, %d expected failures, %d failed in %.1f s (%d at a time); "
              "slowest: %s" % (len(results), renders, len(results) - len(failures) - len(xfail), len(xfail),
                               len(failures), elapsed, args.jobs,
                               ", ".join("%s %.1f s" % (n, s) for n, _, s, _ in slowest)))
        return 1 if failures else 0
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
