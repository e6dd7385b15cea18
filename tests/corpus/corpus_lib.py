"""Writers shared by the malformed-input corpus generator: a minimal glTF
scene builder, PNG/JPEG encoders and the case folder layout (see
docs/RELIABILITY.md, "Malformed-input corpus")."""

import base64
import copy
import json
import os
import struct
import zlib


class Corpus:
    """Collects cases; each is a folder <out>/<NNN>_<slug>/ with case.json."""

    def __init__(self, out):
        self.out = os.path.abspath(out)
        self.count = 0
        self.categories = {}
        os.makedirs(self.out, exist_ok=True)

    def case(self, category, slug, files, scene="scene.gltf", expect="any", args=None, voxels=32,
             names=None, argv=None, timeout=None):
        """Writes one case. files: {relative name: bytes|str}. scene: file the
        render command gets (None: no scene argument; a string starting with
        '/' or '{' is passed as is after substitution). expect: 'ok', 'error'
        or 'any'. voxels: --voxels (32 runs the voxel GI path, where NaNs
        would spread through the grid). names: strings one of which the error line must contain
        (default: the case folder). argv: a full argument list replacing the
        default render command ({out} and {case} are substituted). timeout:
        seconds, replacing the runner's per-case limit."""
        self.count += 1
        self.categories[category] = self.categories.get(category, 0) + 1
        folder = os.path.join(self.out, "%03d_%s" % (self.count, slug))
        os.makedirs(folder, exist_ok=True)
        for name, data in files.items():
            path = os.path.join(folder, name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            mode = "wb" if isinstance(data, (bytes, bytearray)) else "w"
            with open(path, mode) as f:
                f.write(data)
        meta = {"category": category, "scene": scene, "expect": expect, "args": args or [],
                "voxels": voxels, "names": names, "argv": argv, "timeout": timeout}
        with open(os.path.join(folder, "case.json"), "w") as f:
            json.dump(meta, f, indent=1)
        return folder


# ---- images ----

def png(width, height, rgba=None, color_type=6, bit_depth=8, raw=None):
    """A PNG of RGBA8 texels (row 0 on top), or with `raw` scanline bytes."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    if raw is None:
        if rgba is None:
            rgba = bytes([200, 120, 40, 255]) * (width * height)
        stride = width * 4
        raw = b"".join(b"\0" + rgba[y * stride:(y + 1) * stride] for y in range(height))
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def bmp(width, height, bgr=(40, 120, 200)):
    """An uncompressed 24-bit BMP (rows bottom-up, padded to 4 bytes)."""
    row = bytes(bgr) * width
    row += b"\0" * (-len(row) % 4)
    pixels = row * height
    header = b"BM" + struct.pack("<IHHI", 54 + len(pixels), 0, 0, 54)
    dib = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    return header + dib + pixels


def tga(width, height, bgr=(40, 120, 200)):
    """An uncompressed true-colour TGA."""
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, width, height, 24, 0)
    return header + bytes(bgr) * (width * height)


def jpeg(width, height, path_hint):
    """A baseline JPEG written by OpenImageIO (the runner needs it anyway)."""
    import OpenImageIO as oiio
    spec = oiio.ImageSpec(width, height, 3, "uint8")
    buf = oiio.ImageBuf(spec)
    oiio.ImageBufAlgo.fill(buf, (0.8, 0.4, 0.2))
    buf.write(path_hint)
    with open(path_hint, "rb") as f:
        data = f.read()
    os.remove(path_hint)
    return data


# ---- glTF ----

def f32(values):
    return struct.pack("<%df" % len(values), *values)


def u16(values):
    data = struct.pack("<%dH" % len(values), *values)
    return data + b"\0" * (-len(data) % 4)


class Gltf:
    """A floor quad and a small box in front of a camera, lit by a point light.
    `bin` holds every buffer view; call data() or files() to finish."""

    def __init__(self, textured=False):
        self.bin = b""
        self.doc = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": [], "buffers": []}
        quad_pos = [-2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2]
        quad_nrm = [0, 1, 0] * 4
        quad_uv = [0, 0, 1, 0, 1, 1, 0, 1]
        quad_idx = [0, 2, 1, 0, 3, 2]
        p = self.accessor(f32(quad_pos), 5126, 4, "VEC3", bounds=([-2, 0, -2], [2, 0, 2]))
        n = self.accessor(f32(quad_nrm), 5126, 4, "VEC3")
        t = self.accessor(f32(quad_uv), 5126, 4, "VEC2")
        i = self.accessor(u16(quad_idx), 5123, 6, "SCALAR", target=34963)
        attrs = {"POSITION": p, "NORMAL": n}
        if textured:
            attrs["TEXCOORD_0"] = t
        self.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                           "metallicFactor": 0, "roughnessFactor": 1}}]
        self.doc["meshes"] = [{"primitives": [{"attributes": attrs, "indices": i, "material": 0}]}]
        self.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.05, "zfar": 50}}]
        self.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1, 1, 1], "intensity": 20}]}}
        self.doc["extensionsUsed"] = ["KHR_lights_punctual"]
        self.doc["nodes"] = [
            {"mesh": 0},
            {"camera": 0, "translation": [0, 1.5, 4], "rotation": [-0.17, 0, 0, 0.985]},
            {"translation": [0, 2, 1], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ]
        self.doc["scenes"] = [{"nodes": [0, 1, 2]}]
        self.doc["scene"] = 0

    def accessor(self, data, ctype, count, kind, bounds=None, target=None):
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data + b"\0" * (-len(data) % 4)
        self.doc["bufferViews"].append(view)
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": ctype, "count": count,
               "type": kind}
        if bounds:
            acc["min"], acc["max"] = bounds
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def texture(self, uri=None, data=None, mime="image/png", slot="baseColorTexture"):
        img = {"uri": uri} if uri is not None else {
            "uri": "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())}
        self.doc.setdefault("images", []).append(img)
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        info = {"index": len(self.doc["textures"]) - 1}
        mat = self.doc["materials"][0]
        if slot in ("baseColorTexture", "metallicRoughnessTexture"):
            mat["pbrMetallicRoughness"][slot] = info
        else:
            mat[slot] = info
            if slot == "emissiveTexture":
                mat["emissiveFactor"] = [1, 1, 1]

    def data_uri_doc(self):
        doc = copy.deepcopy(self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(self.bin).decode()}]
        return doc

    def files(self, name="scene.gltf", bin_name="scene.bin"):
        doc = copy.deepcopy(self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin), "uri": bin_name}]
        return {name: json.dumps(doc), bin_name: self.bin}

    def glb(self, doc=None):
        doc = copy.deepcopy(doc or self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        body = self.bin + b"\0" * (-len(self.bin) % 4)
        total = 12 + 8 + len(text) + 8 + len(body)
        return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(text)) + b"JSON" + text +
                struct.pack("<I", len(body)) + b"BIN\0" + body)


# ---- OBJ / PLY ----

OBJ_QUAD = ("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv -0.3 0 0\nv 0.3 0 0\nv 0 0.6 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 1 0\nvn 0 0 1\n")
OBJ_FACES = "f 1/1/1 3/3/1 2/2/1\nf 1/1/1 4/4/1 3/3/1\nf 5/1/2 6/2/2 7/3/2\n"


def ply_ascii(verts, faces, header_extra="", face_type="uchar int"):
    head = ("ply\nformat ascii 1.0\n%selement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list %s vertex_indices\nend_header\n"
            % (header_extra, len(verts), len(faces), face_type))
    body = "".join("%s %s %s\n" % tuple(v) for v in verts)
    body += "".join(" ".join(str(x) for x in [len(f)] + list(f)) + "\n" for f in faces)
    return head + body


def ply_binary(verts, faces, big=False, count_fmt="B", index_fmt="i"):
    e = ">" if big else "<"
    names = {"B": "uchar", "H": "ushort", "I": "uint", "i": "int", "b": "char"}
    head = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list %s %s vertex_indices\nend_header\n"
            % ("binary_big_endian" if big else "binary_little_endian", len(verts), len(faces),
               names[count_fmt], names[index_fmt])).encode()
    body = b"".join(struct.pack(e + "3f", *v) for v in verts)
    for f in faces:
        body += struct.pack(e + count_fmt, len(f)) + b"".join(struct.pack(e + index_fmt, i) for i in f)
    return head + body


PLY_VERTS = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1), (0, 0.5, 0)]
PLY_FACES = [(0, 2, 1), (0, 3, 2), (0, 1, 4)]
