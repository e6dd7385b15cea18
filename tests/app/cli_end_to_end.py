#!/usr/bin/python3
"""End-to-end checks of the dvsgi executable: bad input gives one clear line
naming the file or option and a non-zero exit; good input writes EXR, PNG and
metrics. Usage: cli_end_to_end.py path/to/dvsgi"""
import base64, json, os, struct, subprocess, sys, tempfile

DVSGI = sys.argv[1]
TMP = tempfile.mkdtemp(prefix="dvsgi-cli-")
failures = []
checks = 0


def run(*args):
    # Renders that do not choose a grid get 32^3: the default 128^3 converges
    # its bounces (--bounces auto), which takes minutes on lavapipe.
    if args and args[0] == "render" and "--voxels" not in args:
        args = (*args, "--voxels", "32")
    p = subprocess.run([DVSGI, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def expect_error(name, args, must_contain):
    global checks
    checks += 1
    rc, out, err = run(*args)
    lines = [l for l in err.splitlines() if l.strip()]
    ok = rc != 0 and len(lines) == 1 and must_contain in lines[0] and "Segmentation" not in err
    print("%-34s rc=%d  %s" % (name, rc, lines[0] if lines else "<no message>"))
    if not ok:
        failures.append("%s: rc=%d stderr=%r (wanted one line containing %r)" % (name, rc, err, must_contain))


def tmpfile(name, content):
    path = os.path.join(TMP, name)
    with open(path, "w" if isinstance(content, str) else "wb") as f:
        f.write(content)
    return path


def triangle_gltf(image_uri=None):
    """A one-triangle glTF with a camera and a sun, buffer in a data URI."""
    pos = struct.pack("<9f", -1, 0, -1, 1, 0, -1, 0, 0, 1)
    uri = "data:application/octet-stream;base64," + base64.b64encode(pos).decode()
    g = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}], "buffers": [{"uri": uri, "byteLength": len(pos)}],
        "bufferViews": [{"buffer": 0, "byteLength": len(pos)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [-1, 0, -1], "max": [1, 0, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
    }
    if image_uri:
        g["images"] = [{"uri": image_uri}]
        g["textures"] = [{"source": 0}]
        g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return json.dumps(g)


out = os.path.join(TMP, "o.exr")
expect_error("missing scene file", ["render", os.path.join(TMP, "nope.gltf"), "--out", out], "nope.gltf")
expect_error("unsupported format", ["render", tmpfile("model.fbx", "x"), "--out", out], "model.fbx")
expect_error("malformed glTF", ["render", tmpfile("bad.gltf", "{ not json"), "--out", out], "bad.gltf")
expect_error("truncated glb", ["render", tmpfile("bad.glb", b"glTF\x02\x00"), "--out", out], "bad.glb")
expect_error("bad --width", ["render", "--width", "abc"], "--width")
expect_error("absurd --width", ["render", "--width", "100000"], "--width")
expect_error("bad --supersample", ["render", "--supersample", "0"], "--supersample")
expect_error("unknown option", ["render", "--frobnicate"], "--frobnicate")
expect_error("camera out of range", ["render", "--camera", "7", "--width", "8", "--height", "8", "--out", out], "--camera")
expect_error("unknown device", ["render", "--device", "no-such-gpu", "--out", out], "--device")
expect_error("unwritable output", ["render", "--width", "8", "--height", "8", "--out", "/proc/forbidden/x.exr"],
             "/proc/forbidden/x.exr")

# A missing texture falls back to the factor, with a warning naming the file.
checks += 3  # missing texture, default render + outputs, --help
scene = tmpfile("tex.gltf", triangle_gltf("missing_albedo.png"))
rc, so, se = run("render", scene, "--width", "16", "--height", "16", "--out", out, "--validate", "--quiet")
print("%-34s rc=%d  %s" % ("missing texture", rc, se.strip()))
if rc != 0 or "missing_albedo.png" not in se:
    failures.append("missing texture: rc=%d stderr=%r" % (rc, se))

# The default scene renders, writes EXR + PNG + metrics, with zero validation errors.
metrics = os.path.join(TMP, "m.json")
png = os.path.join(TMP, "o.png")
rc, so, se = run("render", "--width", "64", "--height", "64", "--out", out, "--png", png, "--metrics", metrics,
                 "--validate")
print(so)
if rc != 0:
    failures.append("default render failed: rc=%d %s" % (rc, se))
else:
    m = json.load(open(metrics))
    names = [p["name"] for p in m["passes"]]
    for want in ("shadow maps", "gbuffer", "direct lighting", "composite"):
        if want not in names:
            failures.append("metrics lacks pass %r: %s" % (want, names))
    if m["validation_errors"] != 0 or m["scene"] != "builtin:cornell":
        failures.append("metrics: %r" % m)
    if not (os.path.getsize(out) > 1000 and os.path.getsize(png) > 100):
        failures.append("EXR/PNG missing or too small")
    if "shadow maps" not in so or "GPU ms" not in so:
        failures.append("no timing table on stdout")

# Issue 3-5 surface: bad values name their option.
expect_error("bad --voxels", ["render", "--voxels", "100"], "--voxels")
expect_error("bad --view", ["render", "--view", "voxels:colour"], "--view")
expect_error("bad --output", ["render", "--output", "everything"], "--output")
expect_error("unknown --dynamic node", ["render", "--dynamic", "no_such_node", "--out", out], "--dynamic")
expect_error("missing --add-model", ["render", "--add-model", os.path.join(TMP, "nope.ply"), "--out", out], "nope.ply")

# Camera paths: a missing or malformed file is named; a walk moves the camera between frames.
expect_error("missing --camera-path", ["render", "--camera-path", os.path.join(TMP, "nope.json"), "--out", out],
             "nope.json")
bad_path = tmpfile("bad_path.json", '{"keyframes": [{"time": 0, "position": [0, 1, 3]}]}')
expect_error("malformed --camera-path", ["render", "--camera-path", bad_path, "--out", out], "bad_path.json")
checks += 1
walk = tmpfile("walk.json", json.dumps({"keyframes": [
    {"time": 0.0, "position": [0.0, 1.0, 3.4], "target": [0.0, 1.0, 0.0]},
    {"time": 0.1, "position": [0.6, 1.2, 3.0], "target": [0.0, 0.8, 0.0], "yfov_degrees": 50}]}))
walk_frames = os.path.join(TMP, "walk_#.exr")
rc, so, se = run("render", "--width", "32", "--height", "32", "--voxels", "32", "--frames", "2", "--time-step", "0.1",
                 "--camera-path", walk, "--out", walk_frames, "--png", "none", "--validate", "--quiet")
paths = [os.path.join(TMP, "walk_%d.exr" % i) for i in range(2)]
moved = all(os.path.exists(f) for f in paths) and open(paths[0], "rb").read() != open(paths[1], "rb").read()
print("%-34s rc=%d moved %s" % ("--camera-path walk", rc, moved))
if rc != 0 or not moved:
    failures.append("--camera-path walk: rc=%d, frames differ: %s %s" % (rc, moved, se))

# Clipmaps: combinations it does not support and absurd values are named; a walk with two levels
# renders (validation on) and scrolls.
expect_error("--clipmap with pv", ["render", "--clipmap", "2", "--voxelizer", "pv", "--width", "8", "--height", "8",
                                   "--out", out], "--clipmap")
expect_error("--clipmap with --voxel-box", ["render", "--clipmap", "2", "--voxel-box", "-1,-1,-1,1,1,1", "--width", "8",
                                            "--height", "8", "--out", out], "--clipmap")
expect_error("absurd --clipmap", ["render", "--clipmap", "9"], "--clipmap")
expect_error("--clipmap without voxels", ["render", "--clipmap", "2", "--voxels", "0", "--width", "8", "--height", "8",
                                          "--out", out], "--clipmap")
expect_error("negative --clipmap-voxel", ["render", "--clipmap-voxel", "-1"], "--clipmap-voxel")
checks += 1
clip_frames = os.path.join(TMP, "clip_#.exr")
rc, so, se = run("render", "--width", "32", "--height", "32", "--voxels", "32", "--clipmap", "2", "--frames", "2",
                 "--time-step", "0.1", "--camera-path", walk, "--out", clip_frames, "--png", "none", "--validate")
clip_paths = [os.path.join(TMP, "clip_%d.exr" % i) for i in range(2)]
ok = rc == 0 and all(os.path.exists(f) for f in clip_paths) and "voxel clipmap: 2 levels" in so
print("%-34s rc=%d %s" % ("--clipmap 2 walk", rc, "ok" if ok else se))
if not ok:
    failures.append("--clipmap 2 walk: rc=%d stdout=%r stderr=%r" % (rc, so[-400:], se))

# Several frames with an added moving model, every frame written; a voxel view; single terms.
checks += 3
bunny = os.path.join(os.path.dirname(__file__), "../../../shared/scenes/stanford-bunny/bun_zipper_res2.ply")
# Without the shared scenes this check would quietly run without the model: fail instead.
if not os.path.exists(bunny):
    failures.append("frames + moving model: %s not found" % bunny)
model = ["--add-model", bunny] if os.path.exists(bunny) else []
pattern = os.path.join(TMP, "frame_##.exr")
rc, so, se = run("render", "--width", "32", "--height", "32", "--voxels", "32", "--frames", "3", "--out", pattern,
                 "--png", "none", "--validate", "--quiet", *model)
written = [os.path.exists(os.path.join(TMP, "frame_%02d.exr" % i)) for i in range(3)]
print("%-34s rc=%d frames %s" % ("frames + moving model", rc, written))
if rc != 0 or not all(written):
    failures.append("frames: rc=%d written=%s %s" % (rc, written, se))
# The directional view reads one volume of the atlas at a coarser level.
for view in (["voxels:albedo"], ["voxels:radiance"], ["voxels:directional", "--view-direction=+y", "--view-mip", "1"]):
    rc, so, se = run("render", "--width", "32", "--height", "32", "--voxels", "32", "--view", *view, "--out", out,
                     "--validate", "--quiet")
    if rc != 0:
        failures.append("%s: rc=%d %s" % (view, rc, se))
for term in ("indirect", "ao"):
    rc, so, se = run("render", "--width", "32", "--height", "32", "--voxels", "32", "--output", term,
                     "--trace-scale", "0.5", "--shadows", "cone", "--out", out, "--validate", "--quiet")
    if rc != 0:
        failures.append("--output %s: rc=%d %s" % (term, rc, se))

rc, so, _ = run("--help")
for opt in ("--out", "--png", "--width", "--height", "--camera", "--exposure", "--metrics", "--device", "--validate"):
    if opt not in so:
        failures.append("--help does not document " + opt)

print("\n".join("FAIL " + f for f in failures))
print("%d passed, %d failed" % (max(checks - len(failures), 0), len(failures)))
sys.exit(1 if failures else 0)
