#!/usr/bin/env python3
"""Writes a small seed corpus for the fuzz targets: OUT/{ply,obj,off,stl,gltf}/.

    python3 fuzz/make_corpus.py OUT
"""
import os
import struct
import sys

SQUARE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1)]
FACES = [[0, 1, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]


def ply_header(fmt, vertex_props, face_props, extra=""):
    h = f"ply\nformat {fmt} 1.0\ncomment seed\nobj_info fuzz\nelement vertex {len(SQUARE)}\n"
    h += "".join(f"property {p}\n" for p in vertex_props)
    h += extra
    h += f"element face {len(FACES)}\n" + "".join(f"property {p}\n" for p in face_props)
    return (h + "end_header\n").encode()


def ply_seeds():
    seeds = {}
    xyz = ["float x", "float y", "float z"]
    lst = ["list uchar int vertex_indices"]
    body = "".join(f"{x} {y} {z}\n" for x, y, z in SQUARE)
    body += "".join(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in FACES)
    seeds["ascii.ply"] = ply_header("ascii", xyz, lst) + body.encode()
    for name, e in (("le", "<"), ("be", ">")):
        fmt = "binary_little_endian" if e == "<" else "binary_big_endian"
        b = ply_header(fmt, xyz + ["float confidence"], lst)
        for p in SQUARE:
            b += struct.pack(e + "4f", *p, 0.5)
        for f in FACES:
            b += struct.pack(e + "B%di" % len(f), len(f), *f)
        seeds[f"binary_{name}.ply"] = b
    # Every type, lists on vertices, an unknown element, face extras.
    props = ["char a", "ushort b", "double x", "int16 c", "float32 y", "list uint8 float n", "float64 z",
             "uint d"]
    b = ply_header("binary_little_endian", props, ["uchar flags", "list ushort uint vertex_index", "int32 g"],
                   extra="element edge 1\nproperty list int short v\n")
    for p in SQUARE:
        b += struct.pack("<bHdhfBffdI", -1, 2, p[0], -3, p[1], 2, 0.5, 0.25, p[2], 7)
    b += struct.pack("<ihh", 2, 0, 1)
    for f in FACES:
        b += struct.pack("<BH%dIi" % len(f), 1, len(f), *f, -5)
    seeds["types.ply"] = b
    # Triangle strips.
    b = b"ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
    b += b"property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
    for p in SQUARE:
        b += struct.pack("<3f", *p)
    strip = [0, 1, 3, 2, -1, 0, 1, 4, 4, 2]
    b += struct.pack("<i%di" % len(strip), len(strip), *strip)
    seeds["tristrips.ply"] = b
    return seeds


def obj_seeds():
    v = "".join(f"v {x} {y} {z}\n" for x, y, z in SQUARE)
    f = "".join("f " + " ".join(str(i + 1) for i in face) + "\n" for face in FACES)
    rich = ("# seed\nmtllib a.mtl\no thing\n" + v + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nusemtl m\ns 1\n"
            "g g1\nf 1/1/1 2/2/1 3/3/1 4//1\nf -1 -2 -3\nf 5/1 4/2 1/3\nl 1 2\np 3\nvw 0 0 0.5\n")
    return {"plain.obj": (v + f).encode(), "rich.obj": rich.encode(), "cr.obj": (v + f).replace("\n", "\r").encode()}


def off_seeds():
    v = "".join(f"{x} {y} {z}\n" for x, y, z in SQUARE)
    f = "".join(f"{len(face)} " + " ".join(map(str, face)) + "\n" for face in FACES)
    counts = f"{len(SQUARE)} {len(FACES)} 8\n"
    cv = "".join(f"{x} {y} {z} 255 0 0 255\n" for x, y, z in SQUARE)
    fc = "".join(f"{len(face)} " + " ".join(map(str, face)) + " 1 0 0\n" for face in FACES)
    return {"plain.off": ("OFF\n" + counts + v + f).encode(),
            "coff.off": ("# c\nCOFF\n" + counts + cv + fc).encode(),
            "noff.off": ("nOFF\n3\n" + counts + v + f).encode()}


def stl_seeds():
    tris = [(SQUARE[0], SQUARE[1], SQUARE[4]), (SQUARE[1], SQUARE[2], SQUARE[4])]
    text = "solid s\n"
    for t in tris:
        text += "facet normal 0 0 1\nouter loop\n" + "".join(f"vertex {x} {y} {z}\n" for x, y, z in t)
        text += "endloop\nendfacet\n"
    text += "endsolid s\n"
    b = b"solid binary".ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        b += struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *p) for p in t) + struct.pack("<H", 0)
    return {"ascii.stl": text.encode(), "binary.stl": b}


def gltf_seeds():
    import base64, json
    pts = [SQUARE[0], SQUARE[1], SQUARE[2], SQUARE[4]]
    pos = b"".join(struct.pack("<3f", *p) for p in pts)
    idx = struct.pack("<6H", 0, 1, 3, 1, 2, 3)
    def doc(uri):
        d = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
             "nodes": [{"mesh": 0, "translation": [1, 0, 0]}],
             "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
             "buffers": [{"byteLength": len(pos) + len(idx)}],
             "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                             {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
             "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 4,
                            "min": [min(p[k] for p in pts) for k in range(3)],
                            "max": [max(p[k] for p in pts) for k in range(3)]},
                           {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 6}]}
        if uri:
            d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(pos + idx).decode()
        return json.dumps(d).encode()
    j = doc(False)
    j += b" " * (-len(j) % 4)
    binary = pos + idx
    binary += b"\0" * (-len(binary) % 4)
    glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(j) + 8 + len(binary))
    glb += struct.pack("<I", len(j)) + b"JSON" + j + struct.pack("<I", len(binary)) + b"BIN\0" + binary
    return {"square.gltf": doc(True), "square.glb": glb}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fuzz-corpus"
    groups = {"ply": ply_seeds(), "obj": obj_seeds(), "off": off_seeds(), "stl": stl_seeds(), "gltf": gltf_seeds()}
    for fmt, seeds in groups.items():
        os.makedirs(os.path.join(out, fmt), exist_ok=True)
        for name, data in seeds.items():
            with open(os.path.join(out, fmt, name), "wb") as fh:
                fh.write(data)
    # The dispatcher gets every seed.
    os.makedirs(os.path.join(out, "mesh"), exist_ok=True)
    for fmt, seeds in groups.items():
        for name, data in seeds.items():
            with open(os.path.join(out, "mesh", name), "wb") as fh:
                fh.write(data)


if __name__ == "__main__":
    main()
