#!/usr/bin/env python3
"""Writes the small PLY files the importer tests read (run from this folder; the outputs are
committed, so the tests need no Python). Each encoding carries the same unit cube, so the tests
can expect the same counts and bounds from all of them."""
import gzip
import struct

# A cube from (-1, -2, -3) to (1, 2, 3): 8 corners, 6 quads -> 12 triangles.
V = [(x, y, z) for x in (-1.0, 1.0) for y in (-2.0, 2.0) for z in (-3.0, 3.0)]
QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]

def cube_header(fmt):
    return ("ply\nformat %s 1.0\ncomment a test cube\nobj_info made by make_test_files.py\n"
            "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 6\nproperty list uchar int vertex_indices\nend_header\n" % fmt)

def write(name, data):
    with open(name, "wb") as f:
        f.write(data)

# ASCII, Windows line endings in the body for good measure.
body = "".join("%g %g %g\r\n" % v for v in V) + "".join("4 %d %d %d %d\r\n" % q for q in QUADS)
write("cube_ascii.ply", (cube_header("ascii") + body).encode())
write("cube_ascii.ply.gz", gzip.compress((cube_header("ascii") + body).encode(), mtime=0))

# Binary, both byte orders, with properties and elements the importer must skip: a per-vertex
# double and a list in the vertex element, a per-face ushort, and a whole element with a list
# between vertices and faces.
extra_v = "property double confidence\nproperty list ushort short junk\n"
for order, tag in (("<", "binary_little_endian"), (">", "binary_big_endian")):
    out = bytearray(("ply\nformat %s 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                     "%selement edge 2\nproperty int vertex1\nproperty list uint double weights\n"
                     "element face 6\nproperty list uchar int vertex_indices\nproperty ushort flags\nend_header\n"
                     % (tag, extra_v)).encode())
    for i, v in enumerate(V):
        out += struct.pack(order + "fffd", *v, 0.5)
        out += struct.pack(order + "H", i % 3) + struct.pack(order + "%dh" % (i % 3), *range(i % 3))
    for e in range(2):
        out += struct.pack(order + "iI", e, 2) + struct.pack(order + "2d", 1.0, 2.0)
    for q in QUADS:
        out += struct.pack(order + "B4iH", 4, *q, 7)
    write("cube_%s.ply" % ("le" if order == "<" else "be"), bytes(out))

# Attributes: normals, uvs (s/t), 8-bit colours; a pentagon (3 triangles) and two degenerate
# faces (two corners; a repeated vertex).
attr = ("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 3\n"
        "property list uchar uint vertex_index\nend_header\n"
        "0 0 0 0 0 1 0 0 255 0 0\n1 0 0 0 0 1 1 0 255 0 0\n1.5 1 0 0 0 1 1 1 255 0 0\n"
        "0.5 1.5 0 0 0 1 0.5 1 255 0 0\n-0.5 1 0 0 0 1 0 1 255 0 0\n"
        "5 0 1 2 3 4\n2 0 1\n3 0 0 1\n")
write("pentagon_attributes.ply", attr.encode())
