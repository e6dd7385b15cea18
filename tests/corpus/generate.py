#!/usr/bin/env python3
"""Writes the malformed-input corpus: one folder per case (scene files and a
case.json saying how to run it and what must happen). Usage:

    generate.py OUTDIR

Categories and counts are printed at the end and listed in
docs/RELIABILITY.md. Every case is produced here from code; nothing binary is
committed."""

import copy
import json
import struct
import os
import shutil
import sys

from corpus_lib import (Corpus, Gltf, OBJ_FACES, OBJ_QUAD, PLY_FACES, PLY_VERTS, bmp, jpeg, png, ply_ascii,
                        ply_binary, tga)

NAN = float("nan")


def gltf_case(c, slug, mutate, expect="any", textured=False, category="gltf-json"):
    # Structure cases either fail before rendering or are the plain scene:
    # the voxel path is exercised by the value and geometry categories.
    voxels = 0 if category == "gltf-json" else 32
    g = Gltf(textured=textured)
    doc = g.data_uri_doc()
    result = mutate(doc)
    text = result if isinstance(result, str) else json.dumps(doc)
    c.case(category, slug, {"scene.gltf": text}, expect=expect, voxels=voxels)


def setp(path, value):
    """A mutation setting doc[path...] = value (creating objects on the way)."""
    def mutate(doc):
        node = doc
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
    return mutate


def delp(path):
    def mutate(doc):
        node = doc
        for key in path[:-1]:
            node = node[key]
        del node[path[-1]]
    return mutate


def raw(replace_from, replace_to):
    """A mutation on the JSON text (for what json.dumps cannot write)."""
    def mutate(doc):
        text = json.dumps(doc)
        assert replace_from in text, replace_from
        return text.replace(replace_from, replace_to, 1)
    return mutate


PRIM = ["meshes", 0, "primitives", 0]
LIGHT = ["extensions", "KHR_lights_punctual", "lights", 0]
PERSP = ["cameras", 0, "perspective"]
PBR = ["materials", 0, "pbrMetallicRoughness"]


def gltf_structure(c):
    cases = [
        ("valid", lambda d: None, "ok"),
        ("empty_object", lambda d: "{}", "error"),
        ("empty_file", lambda d: "", "error"),
        ("top_level_array", lambda d: "[]", "error"),
        ("truncated_json", lambda d: json.dumps(d)[:200], "error"),
        ("version_1", setp(["asset", "version"], "1.0"), "error"),
        ("version_number", setp(["asset", "version"], 2), "error"),
        ("asset_string", setp(["asset"], "x"), "error"),
        ("required_unknown_ext", setp(["extensionsRequired"], ["EXT_unknown"]), "error"),
        ("required_not_array", setp(["extensionsRequired"], "x"), "error"),
        ("number_overflow", raw('"zfar": 50', '"zfar": 1e400'), "error"),
        ("number_overflow_negative", raw('"znear": 0.05', '"znear": -1e999'), "error"),
        ("nan_token", raw('"yfov": 0.8', '"yfov": NaN'), "error"),
        ("huge_integer", raw('"mesh": 0', '"mesh": 123456789012345678901234567890'), "error"),
        ("index_minus_one", setp(PRIM + ["attributes", "POSITION"], -1), "error"),
        ("index_uint64_max", raw('"POSITION": 0', '"POSITION": 18446744073709551615'), "error"),
        ("index_float", setp(PRIM + ["attributes", "POSITION"], 0.5), "error"),
        ("index_string", setp(PRIM + ["attributes", "POSITION"], "0"), "error"),
        ("indices_minus_one", setp(PRIM + ["indices"], -1), "error"),
        ("material_out_of_range", setp(PRIM + ["material"], 7), "error"),
        ("no_position", delp(PRIM + ["attributes", "POSITION"]), "error"),
        ("attributes_array", setp(PRIM + ["attributes"], []), "error"),
        ("mode_points", setp(PRIM + ["mode"], 0), "error"),
        ("mode_huge", setp(PRIM + ["mode"], 99999), "error"),
        ("no_primitives", setp(["meshes", 0, "primitives"], []), "error"),
        ("meshes_object", setp(["meshes"], {}), "error"),
        ("nodes_string", setp(["nodes"], "abc"), "error"),
        ("node_null", setp(["nodes", 0], None), "error"),
        ("node_mesh_out_of_range", setp(["nodes", 0, "mesh"], 5), "error"),
        ("self_child", setp(["nodes", 0, "children"], [0]), "error"),
        ("cycle", lambda d: d["nodes"][0].update(children=[1]) or d["nodes"][1].update(children=[0]), "error"),
        ("two_parents", lambda d: d["nodes"][0].update(children=[2]) or d["nodes"][1].update(children=[2]),
         "error"),
        ("child_out_of_range", setp(["nodes", 0, "children"], [99]), "error"),
        ("scene_index_out_of_range", setp(["scene"], 4), "error"),
        ("scene_node_out_of_range", setp(["scenes", 0, "nodes"], [0, 77]), "error"),
        ("empty_scene", setp(["scenes", 0, "nodes"], []), "any"),
        ("no_scenes", delp(["scenes"]), "any"),
        ("accessor_count_zero", setp(["accessors", 0, "count"], 0), "error"),
        ("accessor_count_huge", setp(["accessors", 0, "count"], 4000000000), "error"),
        ("accessor_count_negative", setp(["accessors", 0, "count"], -3), "error"),
        ("accessor_offset_past_end", setp(["accessors", 0, "byteOffset"], 1000000), "error"),
        ("accessor_bad_component", setp(["accessors", 0, "componentType"], 5130), "error"),
        ("accessor_bad_type", setp(["accessors", 0, "type"], "VEC7"), "error"),
        ("accessor_wrong_type", setp(["accessors", 0, "type"], "VEC2"), "error"),
        ("accessor_sparse", setp(["accessors", 0, "sparse"], {"count": 1}), "error"),
        ("accessor_no_view_huge", delp(["accessors", 0, "bufferView"]), "any"),
        ("view_out_of_range", setp(["accessors", 0, "bufferView"], 42), "error"),
        ("view_offset_huge", setp(["bufferViews", 0, "byteOffset"], 2 ** 62), "error"),
        ("view_length_huge", setp(["bufferViews", 0, "byteLength"], 2 ** 40), "error"),
        ("view_stride_small", setp(["bufferViews", 0, "byteStride"], 4), "error"),
        ("view_stride_huge", setp(["bufferViews", 0, "byteStride"], 100000), "error"),
        ("view_buffer_out_of_range", setp(["bufferViews", 0, "buffer"], 3), "error"),
        ("buffer_length_too_big", setp(["buffers", 0, "byteLength"], 10 ** 9), "error"),
        ("buffer_length_negative", setp(["buffers", 0, "byteLength"], -1), "error"),
        ("buffer_no_uri", delp(["buffers", 0, "uri"]), "error"),
        ("buffer_bad_base64", setp(["buffers", 0, "uri"], "data:application/octet-stream;base64,@@@@"), "error"),
        ("buffer_data_not_base64", setp(["buffers", 0, "uri"], "data:application/octet-stream,AAAA"), "error"),
        ("buffer_uri_number", setp(["buffers", 0, "uri"], 5), "error"),
        ("buffers_empty", setp(["buffers"], []), "error"),
        ("index_past_vertices", lambda d: d["accessors"][3].update(componentType=5125, count=1), "error"),
        ("odd_index_count", setp(["accessors", 3, "count"], 5), "error"),
        ("light_type_unknown", setp(LIGHT + ["type"], "area"), "error"),
        ("light_index_out_of_range", setp(["nodes", 2, "extensions", "KHR_lights_punctual", "light"], 3),
         "error"),
        ("camera_type_ortho", setp(["cameras", 0, "type"], "orthographic"), "any"),
        ("camera_no_perspective", delp(["cameras", 0, "perspective"]), "error"),
        ("camera_index_out_of_range", setp(["nodes", 1, "camera"], 9), "error"),
        ("material_alpha_unknown", setp(["materials", 0, "alphaMode"], "CUTOUT"), "error"),
        ("material_not_object", setp(["materials", 0], 3), "error"),
        ("texture_index_out_of_range", setp(PBR + ["baseColorTexture"], {"index": 4}), "error"),
        ("animation_bad_sampler", setp(["animations"], [{"samplers": [], "channels": [
            {"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]), "error"),
        ("deep_json_nesting", lambda d: '{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000
         + "}", "any"),
        ("unicode_names", lambda d: d["nodes"][0].update(name="\u00e9\u4e2d\U0001F600\n\t\x00"), "ok"),
        ("matrix_and_trs", setp(["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]), "ok"),
        ("matrix_short", setp(["nodes", 0, "matrix"], [1, 0, 0]), "error"),
        ("translation_strings", setp(["nodes", 0, "translation"], ["a", "b", "c"]), "error"),
        ("rotation_zero", setp(["nodes", 0, "rotation"], [0, 0, 0, 0]), "ok"),
    ]
    for slug, mutate, expect in cases:
        gltf_case(c, slug, mutate, expect)


def gltf_values(c):
    big = 3e38
    cases = [
        ("light_intensity_3e38", setp(LIGHT + ["intensity"], big), "error"),
        ("light_intensity_negative", setp(LIGHT + ["intensity"], -20), "error"),
        ("light_color_3e38", setp(LIGHT + ["color"], [big, big, big]), "error"),
        ("light_color_negative", setp(LIGHT + ["color"], [1, -1, 1]), "error"),
        ("light_intensity_zero", setp(LIGHT + ["intensity"], 0), "ok"),
        ("spot_outer_zero", lambda d: d["extensions"]["KHR_lights_punctual"]["lights"][0].update(
            type="spot", spot={"outerConeAngle": 0}), "error"),
        ("spot_outer_above_half_pi", lambda d: d["extensions"]["KHR_lights_punctual"]["lights"][0].update(
            type="spot", spot={"outerConeAngle": 3}), "error"),
        ("spot_valid", lambda d: d["extensions"]["KHR_lights_punctual"]["lights"][0].update(
            type="spot", spot={"innerConeAngle": 0.2, "outerConeAngle": 0.6}), "ok"),
        ("directional_light", setp(LIGHT + ["type"], "directional"), "ok"),
        ("base_color_3e38", setp(PBR + ["baseColorFactor"], [big, big, big, 1]), "ok"),
        ("base_color_negative", setp(PBR + ["baseColorFactor"], [-0.5, 0.5, 0.5, 1]), "error"),
        ("base_alpha_negative", setp(PBR + ["baseColorFactor"], [0.5, 0.5, 0.5, -1]), "error"),
        ("emissive_3e38", setp(["materials", 0, "emissiveFactor"], [big, big, big]), "error"),
        ("emissive_negative", setp(["materials", 0, "emissiveFactor"], [-1, 0, 0]), "error"),
        ("emissive_strength_3e38", lambda d: d["materials"][0].update(
            emissiveFactor=[1, 1, 1], extensions={"KHR_materials_emissive_strength": {"emissiveStrength": big}}),
         "error"),
        ("emissive_strength_negative", lambda d: d["materials"][0].update(
            emissiveFactor=[1, 1, 1], extensions={"KHR_materials_emissive_strength": {"emissiveStrength": -4}}),
         "error"),
        ("emissive_valid", lambda d: d["materials"][0].update(emissiveFactor=[1, 0.5, 0.2]), "ok"),
        ("metallic_huge", setp(PBR + ["metallicFactor"], 1e30), "ok"),
        ("roughness_negative", setp(PBR + ["roughnessFactor"], -5), "ok"),
        ("alpha_cutoff_huge", lambda d: d["materials"][0].update(alphaMode="MASK", alphaCutoff=1e30), "ok"),
        ("camera_scale_zero", setp(["nodes", 1, "scale"], [0, 0, 0]), "error"),
        ("camera_scale_flat", setp(["nodes", 1, "scale"], [1, 1, 0]), "error"),
        ("camera_matrix_singular", lambda d: d["nodes"][1].clear() or d["nodes"][1].update(
            camera=0, matrix=[1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 4, 1]), "error"),
        ("camera_quat_huge", setp(["nodes", 1, "rotation"], [big, big, big, big]), "any"),
        ("camera_quat_tiny", setp(["nodes", 1, "rotation"], [1e-30, 0, 0, 1e-30]), "any"),
        ("camera_yfov_pi", setp(PERSP + ["yfov"], 3.14159265358979), "error"),
        ("camera_yfov_4", setp(PERSP + ["yfov"], 4.0), "error"),
        ("camera_yfov_zero", setp(PERSP + ["yfov"], 0), "error"),
        ("camera_yfov_negative", setp(PERSP + ["yfov"], -1), "error"),
        ("camera_zfar_eq_znear", setp(PERSP + ["zfar"], 0.05), "error"),
        ("camera_zfar_near_znear", setp(PERSP + ["zfar"], 0.05000001), "error"),
        ("camera_znear_zero", setp(PERSP + ["znear"], 0), "error"),
        ("camera_aspect_negative", setp(PERSP + ["aspectRatio"], -2), "error"),
        ("camera_aspect_huge", setp(PERSP + ["aspectRatio"], 1e30), "any"),
        ("camera_no_zfar", delp(PERSP + ["zfar"]), "ok"),
        ("node_translation_3e38", setp(["nodes", 0, "translation"], [big, 0, 0]), "error"),
        ("node_scale_3e38", setp(["nodes", 0, "scale"], [big, big, big]), "error"),
        ("node_scale_zero", setp(["nodes", 0, "scale"], [0, 0, 0]), "any"),
        ("node_scale_negative", setp(["nodes", 0, "scale"], [-1, 1, 1]), "ok"),
    ]
    for slug, mutate, expect in cases:
        gltf_case(c, slug, mutate, expect, category="gltf-values")


def gltf_geometry(c):
    """Attribute data edited inside the binary buffer."""

    def with_bin(slug, edit, expect):
        g = Gltf()
        b = bytearray(g.bin)
        edit(b)
        g.bin = bytes(b)
        c.case("gltf-geometry", slug, {"scene.gltf": json.dumps(g.data_uri_doc())}, expect=expect)

    nan = struct.pack("<f", NAN)
    inf = struct.pack("<f", float("inf"))
    with_bin("position_nan", lambda b: b.__setitem__(slice(0, 4), nan), "error")
    with_bin("position_inf", lambda b: b.__setitem__(slice(16, 20), inf), "error")
    with_bin("position_3e38", lambda b: b.__setitem__(slice(0, 4), struct.pack("<f", 3e38)), "error")
    with_bin("normals_zero", lambda b: b.__setitem__(slice(48, 96), b"\0" * 48), "ok")
    with_bin("normals_nan", lambda b: b.__setitem__(slice(48, 60), nan * 3), "ok")
    with_bin("indices_out_of_range", lambda b: b.__setitem__(slice(128, 130), struct.pack("<H", 60000)), "error")
    with_bin("degenerate_triangles", lambda b: b.__setitem__(slice(128, 140), b"\0" * 12), "any")
    with_bin("uv_nan", lambda b: b.__setitem__(slice(96, 100), nan), "ok")

    # A mesh without NORMAL: flat normals from the geometry.
    gltf_case(c, "no_normals", delp(PRIM + ["attributes", "NORMAL"]), "ok", category="gltf-geometry")
    # 200,000-node parent chain and 50,000 instances: must load quickly.
    g = Gltf()
    doc = g.data_uri_doc()
    n = 200000
    doc["nodes"][0]["children"] = [3]
    doc["nodes"] += [{"children": [i + 1]} for i in range(3, n + 2)] + [{"mesh": 0, "scale": [0.5, 0.5, 0.5]}]
    c.case("gltf-geometry", "chain_200k", {"scene.gltf": json.dumps(doc)}, expect="ok")
    doc = g.data_uri_doc()
    doc["nodes"] += [{"mesh": 0, "translation": [i % 200 * 0.01, 0, i // 200 * 0.01],
                      "scale": [0.01, 0.01, 0.01]} for i in range(50000)]
    doc["scenes"][0]["nodes"] += list(range(3, 3 + 50000))
    # Loading takes 0.1 s; the renderer's shadow maps draw each instance six
    # times (about 5 s on lavapipe, more on a loaded machine), hence its own limit.
    c.case("gltf-geometry", "instances_50k", {"scene.gltf": json.dumps(doc)}, expect="ok", voxels=0,
           timeout=60)


def glb_cases(c):
    g = Gltf()
    good = g.glb()
    cases = [
        ("valid", good, "ok"),
        ("magic_only", b"glTF", "error"),
        ("header_only", good[:12], "error"),
        ("truncated_json_chunk", good[:40], "error"),
        ("truncated_bin_chunk", good[:-20], "error"),
        ("version_1", good[:4] + b"\1\0\0\0" + good[8:], "error"),
        ("length_huge", good[:8] + b"\xff\xff\xff\x7f" + good[12:], "error"),
        ("length_zero", good[:8] + b"\0\0\0\0" + good[12:], "error"),
        ("json_chunk_length_huge", good[:12] + b"\xff\xff\xff\x0f" + good[16:], "error"),
        ("first_chunk_bin", good[:16] + b"BIN\0" + good[20:], "error"),
        ("json_garbage", good[:20] + b"\xff" * 16 + good[36:], "error"),
        ("no_bin_chunk", good[:20 + int.from_bytes(good[12:16], "little")], "error"),
        ("trailing_garbage", good + b"\x00garbage", "any"),
    ]
    for slug, data, expect in cases:
        c.case("glb", slug, {"scene.glb": data}, scene="scene.glb", expect=expect, voxels=0)
    for k in range(12):
        # Single-byte corruptions at spread-out offsets.
        data = bytearray(good)
        pos = (k * 7919) % len(data)
        data[pos] ^= 0xA5
        c.case("glb", "flip_%d" % pos, {"scene.glb": bytes(data)}, scene="scene.glb", voxels=0)


def references(c):
    """External files: buffers and images outside the folder, percent tricks."""
    g = Gltf(textured=True)
    sentinel_dir = os.path.join(c.out, "sentinel")
    os.makedirs(sentinel_dir, exist_ok=True)
    with open(os.path.join(sentinel_dir, "secret.bin"), "wb") as f:
        f.write(g.bin)
    with open(os.path.join(sentinel_dir, "secret.png"), "wb") as f:
        f.write(png(2, 2))
    secret_bin = os.path.join(sentinel_dir, "secret.bin")

    def buf(slug, uri, expect="error", extra=None):
        doc = copy.deepcopy(g.doc)
        doc["buffers"] = [{"byteLength": len(g.bin), "uri": uri}]
        files = {"scene.gltf": json.dumps(doc), "scene.bin": g.bin}
        files.update(extra or {})
        return c.case("references", slug, files, expect=expect, voxels=0)

    buf("valid_external_bin", "scene.bin", "ok")
    buf("sentinel_dotdot", "../sentinel/secret.bin")
    buf("sentinel_absolute", secret_bin)
    buf("sentinel_percent_dots", "%2e%2e/sentinel/secret.bin")
    buf("sentinel_percent_slash", "..%2fsentinel%2fsecret.bin")
    buf("file_scheme", "file://" + secret_bin)
    buf("http_scheme", "http://example.invalid/scene.bin")
    buf("nul_escape", "scene.bin%00.png")
    buf("bad_escape", "scene%zz.bin")
    buf("trailing_percent", "scene.bin%")
    buf("etc_passwd", "/etc/passwd")
    buf("missing_file", "absent.bin")
    buf("subfolder_dotdot_inside", "sub/../scene.bin", "ok", {"sub/keep.txt": "x"})
    buf("percent_space", "scene%20copy.bin", "ok", {"scene copy.bin": g.bin})
    folder = buf("symlink_outside", "link.bin")
    os.symlink(secret_bin, os.path.join(folder, "link.bin"))
    folder = buf("directory_as_buffer", "dir.bin")
    os.makedirs(os.path.join(folder, "dir.bin"), exist_ok=True)
    for slug, uri in [("image_dotdot", "../sentinel/secret.png"),
                      ("image_absolute", os.path.join(sentinel_dir, "secret.png")),
                      ("image_nul", "tex.png%00"), ("image_missing", "nothere.png")]:
        t = Gltf(textured=True)
        t.texture(uri=uri)
        expect = "any" if slug == "image_missing" else "error"
        c.case("references", slug, {"scene.gltf": json.dumps(t.data_uri_doc()), "tex.png": png(2, 2)},
               expect=expect)


def textures(c):
    good = png(4, 4)

    def tex(slug, data, expect="any", mime="image/png", slot="baseColorTexture", external=None):
        t = Gltf(textured=True)
        files = {}
        if external:
            t.texture(uri=external, slot=slot)
            files[external] = data
        else:
            t.texture(data=data, mime=mime, slot=slot)
        files["scene.gltf"] = json.dumps(t.data_uri_doc())
        c.case("textures", slug, files, expect=expect)

    tex("png_valid", good, "ok")
    tex("png_external", good, "ok", external="tex.png")
    tex("png_emissive", good, "ok", slot="emissiveTexture")
    tex("png_normal_map", png(4, 4, bytes([128, 128, 255, 255]) * 16), "ok", slot="normalTexture")
    tex("png_truncated", good[:40])
    tex("png_header_only", good[:33])
    tex("png_empty", b"")
    tex("png_garbage", b"\x89PNG\r\n\x1a\n" + b"\xff" * 64)
    tex("png_grey", png(4, 4, color_type=0, raw=b"".join(b"\0" + bytes([100] * 4) for _ in range(4))), "ok")
    tex("png_16bit", png(2, 2, color_type=2, bit_depth=16, raw=b"".join(b"\0" + b"\x80\x00" * 6 for _ in
                                                                         range(2))), "ok")
    tex("png_claims_20000_square_grey", png(20000, 20000, color_type=0, raw=b"\0" * 10))
    tex("png_claims_100000_square", png(100000, 100000, raw=b"\0" * 10))
    tex("png_claims_2e9_wide", png(2000000000, 1, raw=b"\0" * 10))
    tex("png_zero_width", png(0, 4, raw=b""))
    tex("png_70000x1", png(70000, 1), "ok")
    tex("png_1x70000", png(1, 70000), "ok")
    tex("png_as_jpeg_mime", good, "ok", mime="image/jpeg")
    tex("text_as_png", b"hello, this is not an image", external="tex.png")
    jpg = jpeg(8, 8, os.path.join(c.out, "tmp.jpg"))
    tex("jpeg_valid", jpg, "ok", mime="image/jpeg")
    tex("jpeg_truncated", jpg[:len(jpg) // 2], mime="image/jpeg")
    tex("jpeg_header_only", jpg[:20], mime="image/jpeg")
    bad = bytearray(jpg)
    for k in range(30, len(bad), 17):
        bad[k] ^= 0x5A
    tex("jpeg_corrupted", bytes(bad), mime="image/jpeg")
    tex("jpeg_external", jpg, "ok", external="tex.jpg")
    tex("bmp_external", bmp(4, 4), "ok", external="tex.bmp")
    tex("bmp_truncated", bmp(4, 4)[:60], external="tex.bmp")
    tex("bmp_claims_huge", bmp(4, 4)[:18] + struct.pack("<ii", 30000, 30000) + bmp(4, 4)[26:], external="tex.bmp")
    tex("tga_external", tga(4, 4), "ok", external="tex.tga")
    tex("tga_truncated", tga(4, 4)[:25], external="tex.tga")
    tex("gif_unsupported", b"GIF89a" + b"\0" * 20, external="tex.gif")


def obj_cases(c):
    mtl = "newmtl m\nKd 0.8 0.6 0.4\nKe 0 0 0\nd 1\n"

    def obj(slug, text, expect="any", mtl_text=None, extra=None):
        files = {"scene.obj": text}
        if mtl_text is not None:
            files["scene.obj"] = "mtllib scene.mtl\nusemtl m\n" + text
            files["scene.mtl"] = mtl_text
        files.update(extra or {})
        c.case("obj", slug, files, scene="scene.obj", expect=expect)

    base = OBJ_QUAD + OBJ_FACES
    obj("valid", base, "ok")
    obj("valid_with_mtl", base, "ok", mtl)
    obj("empty", "", "error")
    obj("comments_only", "# nothing\n# here\n", "error")
    obj("no_faces", OBJ_QUAD, "error")
    obj("position_nan", base.replace("v -1 0 -1", "v nan 0 -1"), "error")
    obj("position_inf", base.replace("v 1 0 1", "v inf 0 1"), "error")
    obj("position_1e39", base.replace("v 1 0 1", "v 1e39 0 1"), "error")
    obj("position_3e38", base.replace("v 1 0 1", "v 3e38 0 1"), "error")
    obj("position_two_coords", base.replace("v 1 0 1", "v 1 0"), "error")
    obj("position_text", base.replace("v 1 0 1", "v one 0 1"), "error")
    obj("normal_zero", base.replace("vn 0 1 0", "vn 0 0 0"), "ok")
    obj("normal_nan", base.replace("vn 0 1 0", "vn nan nan nan"), "ok")
    obj("uv_nan", base.replace("vt 1 1", "vt nan 1"), "error")
    obj("face_empty", base + "f\n", "error")
    obj("face_two", base + "f 1 2\n", "error")
    obj("face_index_zero", base + "f 0 1 2\n", "error")
    obj("face_index_past_end", base + "f 1 2 99\n", "error")
    obj("face_negative_past_start", base + "f -1 -2 -99\n", "error")
    obj("face_index_huge", base + "f 1 2 99999999999999999999\n", "error")
    obj("face_normal_past_end", base + "f 1//9 2//9 3//9\n", "error")
    obj("face_uv_past_end", base + "f 1/9 2/9 3/9\n", "error")
    obj("face_four_slashes", base + "f 1/1/1/1 2/2/1/1 3/3/1/1\n", "error")
    obj("face_negative_valid", OBJ_QUAD + "f -7 -5 -6\n", "ok")
    obj("face_forward_reference", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "any")
    obj("face_1025_corners", OBJ_QUAD + "f" + " 1 2 3" * 342 + "\n", "error")
    obj("line_one_vertex", base + "l 1\n", "error")
    obj("lines_and_points_only", OBJ_QUAD + "l 1 2\np 3\n", "error")
    obj("long_line", base + "# " + "x" * 1000000 + "\n", "ok")
    obj("binary_garbage", "".join(chr(x) for x in range(1, 256)) * 20, "any")
    obj("crlf", base.replace("\n", "\r\n"), "ok")
    obj("mtl_d_nan", base, "error", mtl.replace("d 1", "d nan"))
    obj("mtl_kd_nan", base, "error", mtl.replace("Kd 0.8 0.6 0.4", "Kd nan 0.6 0.4"))
    obj("mtl_kd_inf", base, "error", mtl.replace("Kd 0.8 0.6 0.4", "Kd inf inf inf"))
    obj("mtl_kd_negative", base, "error", mtl.replace("Kd 0.8 0.6 0.4", "Kd -1 0.6 0.4"))
    obj("mtl_kd_3e38", base, "ok", mtl.replace("Kd 0.8 0.6 0.4", "Kd 3e38 3e38 3e38"))
    obj("mtl_ke_3e38", base, "error", mtl.replace("Ke 0 0 0", "Ke 3e38 3e38 3e38"))
    obj("mtl_ke_negative", base, "error", mtl.replace("Ke 0 0 0", "Ke -5 0 0"))
    obj("mtl_ns_nan", base, "error", mtl + "Ns nan\nKs 1 1 1\n")
    obj("mtl_tr_text", base, "error", mtl.replace("d 1", "Tr abc"))
    obj("mtl_missing", "mtllib absent.mtl\n" + base, "ok")
    obj("mtllib_dotdot", "mtllib ../sentinel/secret.mtl\n" + base, "error")
    obj("mtllib_absolute", "mtllib /etc/passwd\n" + base, "error")
    obj("map_kd_valid", OBJ_QUAD + OBJ_FACES, "ok", mtl + "map_Kd tex.png\n", {"tex.png": png(4, 4)})
    obj("map_kd_dotdot", base, "error", mtl + "map_Kd ../sentinel/secret.png\n")
    obj("map_kd_absolute", base, "error", mtl + "map_Kd " + os.path.join(c.out, "sentinel", "secret.png") + "\n")
    obj("map_kd_missing", base, "ok", mtl + "map_Kd nothere.png\n")
    obj("map_kd_truncated_png", base, "any", mtl + "map_Kd tex.png\n", {"tex.png": png(4, 4)[:30]})
    obj("map_kd_70000x1", base, "ok", mtl + "map_Kd tex.png\n", {"tex.png": png(70000, 1)})
    obj("map_kd_huge_header", base, "any", mtl + "map_Kd tex.png\n",
        {"tex.png": png(20000, 20000, color_type=0, raw=b"\0" * 10)})
    obj("map_d_mask", base, "ok", mtl + "map_Kd tex.png\nmap_d mask.png\n",
        {"tex.png": png(4, 4), "mask.png": png(2, 2)})


def ply_cases(c):
    v, f = PLY_VERTS, PLY_FACES

    def ply(slug, data, expect="any"):
        c.case("ply", slug, {"scene.ply": data}, scene="scene.ply", expect=expect)

    good = ply_ascii(v, f)
    ply("valid_ascii", good, "ok")
    ply("valid_binary_le", ply_binary(v, f), "ok")
    ply("valid_binary_be", ply_binary(v, f, big=True), "ok")
    ply("valid_ushort_count", ply_binary(v, f, count_fmt="H", index_fmt="I"), "ok")
    ply("no_end_header", good.replace("end_header\n", ""), "error")
    ply("no_end_header_binary", ply_binary(v, f).replace(b"end_header\n", b""), "error")
    ply("header_only", good[:good.index("end_header") + 11], "error")
    ply("empty", "", "error")
    ply("magic_only", "ply\n", "error")
    ply("not_ply_magic", "plx\n" + good[4:], "error")
    ply("no_format", good.replace("format ascii 1.0\n", ""), "error")
    ply("format_unknown", good.replace("ascii 1.0", "utf16 1.0"), "error")
    ply("format_version_2", good.replace("ascii 1.0", "ascii 2.0"), "error")
    ply("truncated_ascii", good[:-12], "error")
    ply("truncated_binary", ply_binary(v, f)[:-7], "error")
    ply("truncated_binary_vertices", ply_binary(v, f)[:-60], "error")
    ply("vertex_count_huge", good.replace("element vertex 5", "element vertex 4000000000"), "error")
    ply("face_count_huge", good.replace("element face 3", "element face 2147483647"), "error")
    ply("vertex_count_negative", good.replace("element vertex 5", "element vertex -5"), "error")
    ply("face_zero_indices", ply_ascii(v, f + [()]), "error")
    ply("face_zero_indices_binary", ply_binary(v, f + [()]), "error")
    ply("face_two_indices", ply_ascii(v, f + [(0, 1)]), "error")
    ply("face_index_out_of_range", ply_ascii(v, f + [(0, 1, 50)]), "error")
    ply("face_index_negative", ply_ascii(v, f + [(0, 1, -2)]), "error")
    ply("face_index_out_of_range_binary", ply_binary(v, f + [(0, 1, 1 << 30)]), "error")
    ply("face_255_corners", ply_ascii(v, f + [tuple(range(5)) * 51]), "any")
    ply("face_count_negative_char", ply_binary(v, f + [(0, 1, 2)], count_fmt="b")[:-13] + b"\xff", "error")
    ply("position_nan", ply_ascii([("nan", 0, 0)] + v[1:], f), "error")
    ply("position_inf_binary", ply_binary([(float("inf"), 0, 0)] + v[1:], f), "error")
    ply("position_nan_binary_be", ply_binary([(NAN, 0, 0)] + v[1:], f, big=True), "error")
    ply("position_text", ply_ascii([("x", 0, 0)] + v[1:], f), "error")
    ply("no_vertex_element", "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n3 0 1 2\n", "error")
    ply("no_xyz", good.replace("property float z\n", ""), "error")
    ply("property_before_element", "ply\nformat ascii 1.0\nproperty float x\n" + good[good.index("element"):],
        "error")
    ply("unknown_type", good.replace("property float x", "property float128 x"), "error")
    ply("list_float_count", good.replace("list uchar int", "list float int"), "error")
    ply("unknown_keyword", good.replace("end_header", "bogus 1\nend_header"), "error")
    ply("element_no_properties", good.replace("element face 3", "element extra 100\nelement face 3"), "error")
    ply("points_only", ply_ascii(v, []).replace("element face 0\nproperty list uchar int vertex_indices\n", ""),
        "error")
    ply("comments_and_obj_info", good.replace("format ascii 1.0\n", "format ascii 1.0\ncomment hi\nobj_info x\n"),
        "ok")
    ply("crlf_header", good.replace("\n", "\r\n"), "any")
    ply("extra_vertex_props", good.replace("property float z\n", "property float z\nproperty uchar red\n")
        .replace("\n-1 0 -1\n", "\n-1 0 -1 7\n"), "any")


def cli_cases(c):
    """Option misuse: each must fail with one line naming the option."""
    def cli(slug, files, **kw):
        # Options are checked before any rendering; no voxel grid is needed.
        kw.setdefault("voxels", 0)
        return c.case("cli", slug, files, **kw)

    g = Gltf()
    scene = {"scene.gltf": json.dumps(g.data_uri_doc())}
    bad = [
        ("--width", "0"), ("--width", "-5"), ("--width", "abc"), ("--width", "99999999999999999999"),
        ("--width", "16385"), ("--height", "0"), ("--height", "1.5"), ("--voxels", "33"), ("--voxels", "1024"),
        ("--voxels", "-32"), ("--supersample", "0"), ("--supersample", "9"), ("--shadow-map", "300"),
        ("--exposure", "nan"), ("--exposure", "inf"), ("--exposure", "1e400"), ("--bounces", "-1"),
        ("--cones", "5"), ("--cone-step", "0"), ("--cone-step", "nan"), ("--max-distance", "-1"),
        ("--ao", "maybe"), ("--specular", "1"), ("--shadows", "soft"), ("--shadow-aperture", "0"),
        ("--trace-scale", "2"), ("--trace-scale", "nan"), ("--output", "normals"), ("--frames", "0"),
        ("--time-step", "-1"), ("--out", "x.png"), ("--out", ".exr"), ("--png", "x.jpg"),
        ("--voxel-box", "0,0,0,1,1"), ("--voxel-box", "1,1,1,0,0,0"), ("--voxel-box", "nan,0,0,1,1,1"),
        ("--camera", "-1"), ("--add-model-size", "0"), ("--view", "voxels:magic"), ("--conservative", "hw"),
        ("--soft-kappa", "nan"), ("--ao-lambda", "-1"),
    ]
    for opt, value in bad:
        cli("opt%s_%s" % (opt.replace("-", "_"), "".join(ch if ch.isalnum() else "_" for ch in value)),
               dict(scene), args=[opt, value], expect="error", names=[opt])
    misuse = [
        ("unknown_option", ["--frobnicate"], ["--frobnicate"]),
        ("missing_value", ["--width"], ["--width"]),
        ("value_is_option", ["--width", "--quiet"], ["--width"]),
        ("flag_with_value", ["--quiet=yes"], ["--quiet"]),
        ("empty_equals", ["--width="], ["--width"]),
        ("two_scenes", ["other.gltf"], ["other.gltf"]),
    ]
    for slug, args, names in misuse:
        cli(slug, dict(scene), args=args, expect="error", names=names)
    cli("scene_missing", {}, scene="absent.gltf", expect="error")
    cli("scene_directory", {"dir.gltf/keep": "x"}, scene="dir.gltf", expect="error")
    cli("scene_unknown_extension", {"scene.fbx": "x"}, scene="scene.fbx", expect="error")
    cli("scene_no_extension", {"scene": "x"}, scene="scene", expect="error")
    folder = cli("scene_fifo", {}, scene="pipe.gltf", expect="error")
    os.mkfifo(os.path.join(folder, "pipe.gltf"))
    cli("add_model_missing", dict(scene), args=["--add-model", "{case}/absent.obj"], expect="error")
    cli("add_model_bad_ply", dict(scene, **{"m.ply": "ply\nformat ascii 1.0\n"}),
           args=["--add-model", "{case}/m.ply"], expect="error")
    cli("add_model_70000x1_texture", dict(scene, **{"m.obj": "mtllib m.mtl\nusemtl m\n" + OBJ_QUAD + OBJ_FACES,
                                                               "m.mtl": "newmtl m\nKd 1 1 1\nmap_Kd t.png\n",
                                                               "t.png": png(70000, 1)}),
           args=["--add-model", "{case}/m.obj"], expect="ok")
    cli("out_under_a_file", dict(scene, **{"afile": "x"}), argv=[
        "render", "{case}/scene.gltf", "--width", "32", "--height", "32", "--voxels", "0", "--quiet", "--png",
        "none", "--out", "{case}/afile/x.exr"], expect="error", names=["afile/x.exr", "--out"])
    cli("metrics_under_a_file", dict(scene, **{"afile": "x"}),
           args=["--metrics", "{case}/afile/m.json"], expect="error", names=["--metrics", "afile"])
    cli("huge_supersampled_target", dict(scene), args=["--width", "16384", "--height", "2",
                                                                 "--supersample", "8"], expect="error",
           names=["--width", "--supersample"])
    cli("camera_index_missing", dict(scene), args=["--camera", "7"], expect="error", names=["--camera"])
    cli("no_command", {}, argv=["--quiet"], expect="error", names=["--quiet"])
    cli("unknown_command", {}, argv=["paint"], expect="error", names=["paint"])


def regressions(c):
    """Inputs that crashed a fuzz target, kept once fixed (tests/corpus/regressions)."""
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "regressions")
    if not os.path.isdir(folder):
        sys.exit("generate.py: regressions folder missing: " + folder)
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as f:
            data = f.read()
        stem, ext = os.path.splitext(name)
        if ext in (".png", ".jpg", ".tga", ".bmp"):
            t = Gltf(textured=True)
            t.texture(uri="tex" + ext)
            c.case("regressions", stem, {"scene.gltf": json.dumps(t.data_uri_doc()), "tex" + ext: data})
        elif ext in (".gltf", ".glb", ".obj", ".ply"):
            c.case("regressions", stem, {"scene" + ext: data}, scene="scene" + ext)
        else:
            sys.exit("generate.py: unknown regression input type: " + name)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: generate.py OUTDIR")
    out = sys.argv[1]
    if os.path.isdir(out):
        shutil.rmtree(out)
    c = Corpus(out)
    for section in (gltf_structure, gltf_values, gltf_geometry, glb_cases, references, textures, obj_cases,
                    ply_cases, cli_cases, regressions):
        section(c)
    summary = {"total": c.count, "categories": c.categories}
    with open(os.path.join(c.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print("generated %d cases in %s: %s" % (c.count, c.out,
                                             ", ".join("%s %d" % kv for kv in sorted(c.categories.items()))))


if __name__ == "__main__":
    main()
