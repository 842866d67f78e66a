#!/usr/bin/env python3
"""Writes the glTF 2.0 models of the `gltf` scene group (SPEC 2.1, SPEC 10).

Every model is small and built so that each value a test checks can be derived
by hand: the comment block at the top of each `make_*` function says what the
file holds and lists those values. The unit tests of the importer and the
scenes in suite/scenes/gltf/ rely on them, so change a model only together with
its comment and the tests that quote it.

Every file is a `.gltf` JSON file with a single buffer embedded as a
`data:application/octet-stream;base64,` URI, so a model is one file that a
reviewer can read. The output is deterministic (fixed key order, `indent=1`,
a trailing newline): a test regenerates into a temporary folder and compares
the files byte for byte with the committed ones.

Usage:
  generate_models.py [--out DIR] [--check]

  --out    the folder to write into; default suite/scenes/gltf/models/ beside
           this script
  --check  after writing, read the files back and check them against the
           hand-derived values below with an independent little matrix
           computation; exit 1 on any mismatch

Python 3 standard library only.
"""
import argparse
import base64
import json
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUT = os.path.normpath(os.path.join(HERE, "..", "scenes", "gltf", "models"))
GENERATOR = "lightcts suite/gltf/generate_models.py"

# glTF enums.
FLOAT = 5126
UNSIGNED_SHORT = 5123
UNSIGNED_INT = 5125
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963
POINTS, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 0, 4, 5, 6

SQRT_HALF = math.sqrt(0.5)


def f32(x):
    """x rounded to float32 the way struct (and a C++ double->float cast) rounds it."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


class Builder:
    """Collects one buffer's bytes with its bufferViews and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def _view(self, payload, target):
        # Every view starts on a multiple of 4, as FLOAT and UNSIGNED_INT need.
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload), "target": target}
        self.data.extend(payload)
        self.views.append(view)
        return len(self.views) - 1

    def vec3(self, values, with_bounds=False):
        """A FLOAT VEC3 accessor; POSITION accessors need min/max (with_bounds)."""
        payload = b"".join(struct.pack("<3f", *v) for v in values)
        view = self._view(payload, ARRAY_BUFFER)
        accessor = {"bufferView": view, "componentType": FLOAT, "count": len(values), "type": "VEC3"}
        if with_bounds:
            # glTF requires POSITION's bounds; they are those of the stored float32 values.
            stored = [[f32(c) for c in v] for v in values]
            accessor["min"] = [min(v[k] for v in stored) for k in range(3)]
            accessor["max"] = [max(v[k] for v in stored) for k in range(3)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def indices(self, values, component=UNSIGNED_INT):
        fmt = {UNSIGNED_INT: "<I", UNSIGNED_SHORT: "<H"}[component]
        payload = b"".join(struct.pack(fmt, i) for i in values)
        view = self._view(payload, ELEMENT_ARRAY_BUFFER)
        self.accessors.append({"bufferView": view, "componentType": component, "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def finish(self, document):
        """Adds accessors, bufferViews and the one buffer to `document` (in that key order)."""
        while len(self.data) % 4:
            self.data.append(0)
        document["accessors"] = self.accessors
        document["bufferViews"] = self.views
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode("ascii")
        document["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
        return document


def new_document(extensions_used=None):
    document = {"asset": {"version": "2.0", "generator": GENERATOR}}
    if extensions_used:
        document["extensionsUsed"] = extensions_used
    return document


def triangles_primitive(builder, positions, normals, triangles, material=None):
    primitive = {"attributes": {"POSITION": builder.vec3(positions, with_bounds=True)}}
    if normals is not None:
        primitive["attributes"]["NORMAL"] = builder.vec3(normals)
    primitive["indices"] = builder.indices([i for t in triangles for i in t])
    if material is not None:
        primitive["material"] = material
    primitive["mode"] = TRIANGLES
    return primitive


def quaternion_about(axis, degrees):
    """[x, y, z, w] of a rotation by `degrees` about a unit coordinate axis."""
    half = math.radians(degrees) / 2
    s = math.sin(half)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(half)]


# ---------------------------------------------------------------------------
# a. plane.gltf


def plane_geometry(sx, sz, n):
    # Line for line lighting/mesh.cpp's buildPlane, in doubles in the same order.
    positions, normals, triangles = [], [], []
    for j in range(n + 1):
        for i in range(n + 1):
            positions.append((-sx / 2 + sx * i / n, 0.0, -sz / 2 + sz * j / n))
            normals.append((0.0, 1.0, 0.0))

    def index(i, j):
        return j * (n + 1) + i

    for j in range(n):
        for i in range(n):
            v00, v10, v01, v11 = index(i, j), index(i + 1, j), index(i, j + 1), index(i + 1, j + 1)
            triangles.append((v00, v01, v11))
            triangles.append((v00, v11, v10))
    return positions, normals, triangles


def make_plane():
    # The built-in plane of SPEC 2 with size [8, 8] and 4 subdivisions, written
    # exactly as lighting/mesh.cpp builds it, so that builtin-plane.json and
    # plane-as-gltf.json give the same image.
    # - One node "plane" (mesh 0, no transform), one primitive, no material (the
    #   scene gives one). Object: "plane/0".
    # - 25 vertices: vertex (i, j), j the outer loop, index j*5 + i, at
    #   (-4 + 2i, 0, -4 + 2j), normal (0, 1, 0). All values exact in float32.
    # - 32 triangles: per cell (j outer, i inner, both 0..3) (v00, v01, v11) and
    #   (v00, v11, v10) with v00 = j*5+i, v10 = v00+1, v01 = v00+5, v11 = v00+6.
    #   The first cell gives (0, 5, 6) and (0, 6, 1); the last (18, 23, 24) and
    #   (18, 24, 19). Each winds counter-clockwise seen from +Y.
    # - Bounds: (-4, 0, -4) .. (4, 0, 4).
    positions, normals, triangles = plane_geometry(8.0, 8.0, 4)
    builder = Builder()
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "plane", "nodes": [0]}]
    document["nodes"] = [{"name": "plane", "mesh": 0}]
    document["meshes"] = [{"name": "plane", "primitives": [triangles_primitive(builder, positions, normals, triangles)]}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# b. sphere.gltf


def sphere_geometry(radius, segments, rings):
    # Line for line lighting/mesh.cpp's buildSphere, in doubles in the same
    # order (math.sin and math.cos are the C library's, as std::sin and std::cos).
    positions, normals, triangles = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            sin_theta = 0.0 if (r == 0 or r == rings) else math.sin(theta)
            cos_theta = 1.0 if r == 0 else (-1.0 if r == rings else math.cos(theta))
            cos_phi = 1.0 if s == segments else math.cos(phi)
            sin_phi = 0.0 if s == segments else math.sin(phi)
            unit = (sin_theta * cos_phi, cos_theta, sin_theta * sin_phi)
            positions.append((unit[0] * radius, unit[1] * radius, unit[2] * radius))
            normals.append(unit)

    def index(r, s):
        return r * (segments + 1) + s

    for r in range(rings):
        for s in range(segments):
            a, b, c, d = index(r, s), index(r + 1, s), index(r + 1, s + 1), index(r, s + 1)
            if r != rings - 1:
                triangles.append((a, c, b))
            if r != 0:
                triangles.append((a, d, c))
    return positions, normals, triangles


def make_sphere():
    # The built-in sphere of SPEC 2, radius 1, 24 segments, 12 rings, written
    # exactly as lighting/mesh.cpp's buildSphere computes it in double and then
    # rounded to float32 (nearest, as a C++ double->float conversion).
    # - One node "sphere" (mesh 0, no transform). Object: "sphere/0".
    # - 13 x 25 = 325 vertices: ring r (0 = +Y pole .. 12 = -Y pole), segment s
    #   (0..24, the seam column 24 repeats column 0), index r*25 + s, at
    #   (sin(pi r/12) cos(2 pi s/24), cos(pi r/12), sin(pi r/12) sin(2 pi s/24)),
    #   with the exact poles (0, +-1, 0) and seam (sin 0, cos 1) of buildSphere.
    #   Normal = position (radius 1). Vertex 0 = (0, 1, 0), vertex 324 = (0, -1, 0);
    #   vertex 6*25 + 0 = 150 = (1, cos(pi/2), 0) with cos(pi/2) = 6.1e-17 in
    #   double, which float32 keeps as 6.123234e-17.
    # - 12*24*2 - 2*24 = 528 triangles, in buildSphere's order: for r, for s,
    #   (a, c, b) unless r == 11, then (a, d, c) unless r == 0, with a = (r, s),
    #   b = (r+1, s), c = (r+1, s+1), d = (r, s+1). First three: (0, 26, 25),
    #   (1, 27, 26), (2, 28, 27); ring 0 gives 24 triangles, rings 1..10 48 each,
    #   ring 11 24.
    # - Material 0 "painted": baseColorFactor (0.75, 0.5, 0.25, 1), metallic 0.25,
    #   roughness 0.375; SPEC 2.1 maps it to brdf srp, albedo (0.75, 0.5, 0.25),
    #   metallic 0.25, smoothness 0.625 (all exact in binary), the material of
    #   builtin-sphere.json.
    # - Bounds: +-1 in every axis (min y = -1 and max y = 1 are the poles; x and
    #   z reach +-1 only at the equator: sin(pi/2) = 1 exactly).
    positions, normals, triangles = sphere_geometry(1.0, 24, 12)
    builder = Builder()
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "sphere", "nodes": [0]}]
    document["nodes"] = [{"name": "sphere", "mesh": 0}]
    document["meshes"] = [{"name": "sphere", "primitives": [triangles_primitive(builder, positions, normals, triangles, material=0)]}]
    document["materials"] = [{"name": "painted", "pbrMetallicRoughness": {
        "baseColorFactor": [0.75, 0.5, 0.25, 1.0], "metallicFactor": 0.25, "roughnessFactor": 0.375}}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# c. box.gltf

BOX_FACES = [  # (n, u, v) with cross(u, v) = n, in buildBox's order
    ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
    ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
]


def box_geometry(size):
    # Line for line lighting/mesh.cpp's buildBox.
    half = [c * 0.5 for c in size]
    positions, normals, triangles = [], [], []
    for n, u, v in BOX_FACES:
        centre = [n[k] * half[k] for k in range(3)]
        du = [u[k] * half[k] for k in range(3)]
        dv = [v[k] * half[k] for k in range(3)]
        base = len(positions)
        positions.append(tuple(centre[k] - du[k] - dv[k] for k in range(3)))  # p00
        positions.append(tuple(centre[k] + du[k] - dv[k] for k in range(3)))  # p10
        positions.append(tuple(centre[k] + du[k] + dv[k] for k in range(3)))  # p11
        positions.append(tuple(centre[k] - du[k] + dv[k] for k in range(3)))  # p01
        normals.extend([tuple(float(c) for c in n)] * 4)
        triangles.append((base, base + 1, base + 2))
        triangles.append((base, base + 2, base + 3))
    return positions, normals, triangles


def make_box():
    # The built-in box of SPEC 2 with size [2, 1, 1.5], written exactly as
    # lighting/mesh.cpp's buildBox builds it (half size h = (1, 0.5, 0.75)).
    # - One node "box" (mesh 0, no transform). Object: "box/0".
    # - 24 vertices, 12 triangles. Face f (0..5) has normal n, vertices 4f..4f+3 =
    #   p00, p10, p11, p01 = c-du-dv, c+du-dv, c+du+dv, c-du+dv with c = n*h,
    #   du = u*h, dv = v*h, and triangles (4f, 4f+1, 4f+2), (4f, 4f+2, 4f+3):
    #     f  n           u          v          p00                 p11
    #     0  (+1, 0, 0)  (0, 1, 0)  (0, 0, 1)  (1, -0.5, -0.75)    (1, 0.5, 0.75)
    #     1  (-1, 0, 0)  (0, 0, 1)  (0, 1, 0)  (-1, -0.5, -0.75)   (-1, 0.5, 0.75)
    #     2  (0, +1, 0)  (0, 0, 1)  (1, 0, 0)  (-1, 0.5, -0.75)    (1, 0.5, 0.75)
    #     3  (0, -1, 0)  (1, 0, 0)  (0, 0, 1)  (-1, -0.5, -0.75)   (1, -0.5, 0.75)
    #     4  (0, 0, +1)  (1, 0, 0)  (0, 1, 0)  (-1, -0.5, 0.75)    (1, 0.5, 0.75)
    #     5  (0, 0, -1)  (0, 1, 0)  (1, 0, 0)  (-1, -0.5, -0.75)   (1, 0.5, -0.75)
    #   e.g. face 0: (1,-0.5,-0.75), (1,0.5,-0.75), (1,0.5,0.75), (1,-0.5,0.75).
    #   Every value is exact in float32.
    # - Material 0: baseColorFactor (0.5, 0.75, 1, 1) and glTF's default metallic
    #   and roughness (1, 1): srp albedo (0.5, 0.75, 1), metallic 1, smoothness 0;
    #   in the legacy profile (box-as-gltf.json) lambert with albedo (0.5, 0.75, 1).
    # - Bounds: (-1, -0.5, -0.75) .. (1, 0.5, 0.75).
    positions, normals, triangles = box_geometry((2.0, 1.0, 1.5))
    builder = Builder()
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "box", "nodes": [0]}]
    document["nodes"] = [{"name": "box", "mesh": 0}]
    document["meshes"] = [{"name": "box", "primitives": [triangles_primitive(builder, positions, normals, triangles, material=0)]}]
    document["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.75, 1.0, 1.0]}}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# d. hierarchy.gltf

QUAD_POSITIONS = [(-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.5, 0.5, 0.0), (-0.5, 0.5, 0.0)]
QUAD_TRIANGLES = [(0, 1, 2), (0, 2, 3)]

# by-matrix: Rx(-90 degrees) then translation (0, 0, 2); column-major.
# Rx(-90) maps (x, y, z) to (x, z, -y): local +Z -> world +Y, local +Y -> -Z.
BY_MATRIX = [1, 0, 0, 0,
             0, 0, -1, 0,
             0, 1, 0, 0,
             0, 0, 2, 1]

# The hand values of make_hierarchy's comment, checked by --check:
# object name -> (world positions of quad vertices 0..3, world normal, reversed).
_Q = math.sqrt(2) / 4  # 0.35355339059327373 = sqrt(0.5) / 2
_E = math.sqrt(2) / 8  # 0.17677669529663687 = sqrt(0.5) / 4
HIERARCHY_EXPECTED = [
    ("turned/0", [(2, 0.5, 0.5), (2, 0.5, -0.5), (2, 1.5, -0.5), (2, 1.5, 0.5)], (1, 0, 0), False),
    ("stretched/0", [(-3, 0.75, 0), (-1, 0.75, 0), (-1, 1.25, 0), (-3, 1.25, 0)], (0, 0, 1), False),
    ("leaning/0", [(-3, 2 - _E, _Q), (-1, 2 - _E, _Q), (-1, 2 + _E, -_Q), (-3, 2 + _E, -_Q)],
     (0, 2 / math.sqrt(5), 1 / math.sqrt(5)), False),
    ("mirrored/0", [(0.5, 0.5, -2), (-0.5, 0.5, -2), (-0.5, 1.5, -2), (0.5, 1.5, -2)], (0, 0, 1), True),
    ("by-matrix/0", [(-0.5, 1, 2.5), (0.5, 1, 2.5), (0.5, 1, 1.5), (-0.5, 1, 1.5)], (0, 1, 0), False),
    ("grandchild/0", [(-0.5, 2, 2.5), (0.5, 2, 2.5), (0.5, 2, 1.5), (-0.5, 2, 1.5)], (0, 1, 0), False),
]


def make_hierarchy():
    # One shared mesh "quad" (mesh 0, one primitive, no material): the unit
    # square of local XY, vertices 0..3 = (-0.5,-0.5,0), (0.5,-0.5,0),
    # (0.5,0.5,0), (-0.5,0.5,0), normals (0,0,1), triangles (0,1,2), (0,2,3),
    # counter-clockwise seen from +Z. Seven nodes, one root; the node ARRAY order
    # is deliberately not the depth-first order, so an importer that walks
    # nodes by index, or pops children off a stack in reverse, names and orders
    # the objects differently:
    #   0 "base"       translation (0, 1, 0), no mesh, children [5, 3, 2, 1]
    #   1 "by-matrix"  matrix: Rx(-90) then translation (0, 0, 2), children [4]
    #   2 "mirrored"   translation (0, 0, -2), scale (-1, 1, 1)
    #   3 "stretched"  translation (-2, 0, 0), scale (2, 0.5, 1), children [6]
    #   4 "grandchild" translation (0, 0, 1) (in by-matrix's frame)
    #   5 "turned"     rotation (0, sqrt(0.5), 0, sqrt(0.5)) = 90 degrees about +Y,
    #                  translation (2, 0, 0)
    #   6 "leaning"    rotation (sin(-22.5deg), 0, 0, cos(22.5deg)) = -45 degrees
    #                  about +X, translation (0, 2, 0) (in stretched's frame)
    # Nodes 1..6 carry mesh 0. World = parent's world * T * R * S.
    #
    # Objects (SPEC 2.1), depth-first, children in array order:
    #   turned/0, stretched/0, leaning/0, mirrored/0, by-matrix/0, grandchild/0.
    # World vertices 0..3 and world normal of each (before the scene's import
    # transform; node-hierarchy.json adds translate (0, 0, 0.5) to every point):
    # - turned: Ry(90) maps (x, y, z) to (z, y, -x), so (x, y, 0) goes to
    #   (2, 1 + y, -x): (2, 0.5, 0.5), (2, 0.5, -0.5), (2, 1.5, -0.5), (2, 1.5, 0.5);
    #   normal (0,0,1) -> (1, 0, 0). det +1. (The quaternion's sqrt(0.5) is not
    #   exact, so expect these to about 1e-15.)
    # - stretched: (x, y, 0) -> (-2 + 2x, 1 + 0.5y, 0): (-3, 0.75, 0), (-1, 0.75, 0),
    #   (-1, 1.25, 0), (-3, 1.25, 0); normal: inverse transpose diag(0.5, 2, 1)
    #   keeps (0, 0, 1). det 2 * 0.5 * 1 = 1 > 0.
    # - leaning: Rx(-45) maps (x, y, 0) to (x, sqrt(.5) y, -sqrt(.5) y); add
    #   (0, 2, 0), then stretched's scale and translation:
    #   (-2 + 2x, 2 + y sqrt(2)/4, -y sqrt(2)/2). With e = sqrt(2)/8 = 0.1767767
    #   and q = sqrt(2)/4 = 0.3535534: (-3, 2-e, q), (-1, 2-e, q), (-1, 2+e, -q),
    #   (-3, 2+e, -q). Local normal (0,0,1) -> Rx(-45): (0, sqrt(.5), sqrt(.5));
    #   inverse transpose of the scale, diag(0.5, 2, 1): (0, 2 sqrt(.5), sqrt(.5)),
    #   normalised (0, 2, 1)/sqrt(5) = (0, 0.8944272, 0.4472136). Transforming the
    #   normal by the matrix itself would give (0, 1, 2)/sqrt(5) instead: this
    #   object is the one that checks the inverse transpose. det +1.
    # - mirrored: (x, y, 0) -> (-x, 1 + y, -2): (0.5, 0.5, -2), (-0.5, 0.5, -2),
    #   (-0.5, 1.5, -2), (0.5, 1.5, -2). Normal: inverse transpose diag(-1, 1, 1)
    #   keeps (0, 0, 1). det -1 < 0: the winding is REVERSED; the transformed
    #   (0, 1, 2) is clockwise seen from +Z, so the importer's triangles are
    #   (0, 2, 1), (0, 3, 2) in these vertices, counter-clockwise from +Z, front
    #   face +Z, agreeing with the normal.
    # - by-matrix: (x, y, 0) -> Rx(-90): (x, 0, -y), + (0, 0, 2), + base (0, 1, 0):
    #   (x, 1, 2 - y): (-0.5, 1, 2.5), (0.5, 1, 2.5), (0.5, 1, 1.5), (-0.5, 1, 1.5);
    #   normal (0, 0, 1) -> (0, 1, 0) (faces up). det +1. All exact.
    # - grandchild: (x, y, 0) + (0, 0, 1) = (x, y, 1), then by-matrix's:
    #   (x, 2, 2 - y): (-0.5, 2, 2.5), (0.5, 2, 2.5), (0.5, 2, 1.5), (-0.5, 2, 1.5);
    #   normal (0, 1, 0): its translation (0, 0, 1) along its parent's local +Z
    #   lands one metre UP in the world. det +1. All exact.
    # Only mirrored/0 has its winding reversed.
    builder = Builder()
    primitive = triangles_primitive(builder, QUAD_POSITIONS, [(0.0, 0.0, 1.0)] * 4, QUAD_TRIANGLES)
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "hierarchy", "nodes": [0]}]
    document["nodes"] = [
        {"name": "base", "children": [5, 3, 2, 1], "translation": [0, 1, 0]},
        {"name": "by-matrix", "children": [4], "matrix": BY_MATRIX, "mesh": 0},
        {"name": "mirrored", "mesh": 0, "scale": [-1, 1, 1], "translation": [0, 0, -2]},
        {"name": "stretched", "children": [6], "mesh": 0, "scale": [2, 0.5, 1], "translation": [-2, 0, 0]},
        {"name": "grandchild", "mesh": 0, "translation": [0, 0, 1]},
        {"name": "turned", "mesh": 0, "rotation": [0, SQRT_HALF, 0, SQRT_HALF], "translation": [2, 0, 0]},
        {"name": "leaning", "mesh": 0, "rotation": quaternion_about((1, 0, 0), -45), "translation": [0, 2, 0]},
    ]
    document["meshes"] = [{"name": "quad", "primitives": [primitive]}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# e. strips-and-fans.gltf

# Strip vertices in strip order s0..s4 (the file stores them reversed).
STRIP = [(-3, 1, 0), (-3, 0, 0), (-2, 1, 0), (-2, 0, 0), (-1, 1, 0)]
# Fan vertices f0 (the centre) .. f4, stored in this order, no indices.
FAN = [(1, 0, 0), (3, 0, 0), (3, 1, 0), (2, 1.5, 0), (1, 1, 0)]
POINTS_AT = [(-0.5, 2, 0), (0, 2, 0), (0.5, 2, 0)]
STRIP_EXPECTED = [[STRIP[0], STRIP[1], STRIP[2]], [STRIP[1], STRIP[3], STRIP[2]], [STRIP[2], STRIP[3], STRIP[4]]]
FAN_EXPECTED = [[FAN[1], FAN[2], FAN[0]], [FAN[2], FAN[3], FAN[0]], [FAN[3], FAN[4], FAN[0]]]


def make_strips_and_fans():
    # Three nodes, no transforms, no materials (so glTF's default material:
    # white, metallic 1, roughness 1, which SPEC 2.1 maps to srp albedo (1,1,1),
    # metallic 1, smoothness 0). Everything lies on z = 0 and faces +Z.
    # - node 0 "strip", mesh 0: TRIANGLE_STRIP (mode 5) of 5 vertices with
    #   UNSIGNED_SHORT indices. In strip order s0..s4 = (-3,1,0), (-3,0,0),
    #   (-2,1,0), (-2,0,0), (-1,1,0); the buffer stores them reversed
    #   (vertex k = s(4-k)) and the indices are [4, 3, 2, 1, 0], so an importer
    #   that ignores the indices draws the strip backwards (every triangle
    #   clockwise). Triangle i is (i, i+1, i+2) for even i, (i, i+2, i+1) for
    #   odd i, over the strip order:
    #     t0 = (s0, s1, s2) = (-3,1,0), (-3,0,0), (-2,1,0)
    #     t1 = (s1, s3, s2) = (-3,0,0), (-2,0,0), (-2,1,0)
    #     t2 = (s2, s3, s4) = (-2,1,0), (-2,0,0), (-1,1,0)
    #   As indices into the stored vertices: (4,3,2), (3,1,2), (2,1,0). All three
    #   wind counter-clockwise seen from +Z (twice the signed areas: 1, 1, 1);
    #   t1 without the odd-triangle swap would be clockwise and culled.
    #   Object "strip/0": 3 triangles, normals (0, 0, 1).
    # - node 1 "fan", mesh 1: TRIANGLE_FAN (mode 6) of 5 vertices, no indices
    #   (implicit 0..4): f0 = (1,0,0) (the centre), f1 = (3,0,0), f2 = (3,1,0),
    #   f3 = (2,1.5,0), f4 = (1,1,0). Triangle i = (i+1, i+2, 0):
    #     t0 = (f1, f2, f0) = (3,0,0), (3,1,0), (1,0,0)
    #     t1 = (f2, f3, f0) = (3,1,0), (2,1.5,0), (1,0,0)
    #     t2 = (f3, f4, f0) = (2,1.5,0), (1,1,0), (1,0,0)
    #   counter-clockwise seen from +Z (twice the signed areas: 2, 2, 1).
    #   Object "fan/0": 3 triangles, normals (0, 0, 1).
    # - node 2 "points", mesh 2: POINTS (mode 0), 3 vertices (-0.5,2,0),
    #   (0,2,0), (0.5,2,0), POSITION only: outside the model, skipped with a
    #   warning naming /meshes/2/primitives/0; no object.
    # Objects: strip/0, fan/0.
    builder = Builder()
    stored = list(reversed(STRIP))
    strip = {"attributes": {"POSITION": builder.vec3(stored, with_bounds=True),
                            "NORMAL": builder.vec3([(0.0, 0.0, 1.0)] * 5)},
             "indices": builder.indices([4, 3, 2, 1, 0], UNSIGNED_SHORT),
             "mode": TRIANGLE_STRIP}
    fan = {"attributes": {"POSITION": builder.vec3(FAN, with_bounds=True),
                          "NORMAL": builder.vec3([(0.0, 0.0, 1.0)] * 5)},
           "mode": TRIANGLE_FAN}
    points = {"attributes": {"POSITION": builder.vec3(POINTS_AT, with_bounds=True)}, "mode": POINTS}
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "strips-and-fans", "nodes": [0, 1, 2]}]
    document["nodes"] = [{"name": "strip", "mesh": 0}, {"name": "fan", "mesh": 1}, {"name": "points", "mesh": 2}]
    document["meshes"] = [{"name": "strip", "primitives": [strip]}, {"name": "fan", "primitives": [fan]},
                          {"name": "points", "primitives": [points]}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# f. flat-normals.gltf

ROOF = [(-1, 1, 0), (1, 1, 0), (-1, 0, 1), (1, 0, 1), (-1, 0, -1), (1, 0, -1)]
ROOF_TRIANGLES = [(2, 3, 1), (2, 1, 0), (5, 4, 0), (5, 0, 1)]
ROOF_NORMALS = [(0, SQRT_HALF, SQRT_HALF)] * 2 + [(0, SQRT_HALF, -SQRT_HALF)] * 2


def make_flat_normals():
    # A gable roof WITHOUT a NORMAL attribute, so the importer must give it flat
    # normals. One node "roof" (mesh 0, no transform), one primitive. Object "roof/0".
    # - 6 vertices: ridge r0 = (-1,1,0) [0], r1 = (1,1,0) [1]; front eaves
    #   (-1,0,1) [2], (1,0,1) [3]; back eaves (-1,0,-1) [4], (1,0,-1) [5]. The
    #   ridge vertices are SHARED by both slopes, so averaged (smooth) normals
    #   would give (0, 1, 0) at the ridge: flat normals must not.
    # - 4 triangles, each slope 45 degrees:
    #     (2, 3, 1), (2, 1, 0)  front slope, face normal (0, sqrt(.5), sqrt(.5))
    #     (5, 4, 0), (5, 0, 1)  back slope,  face normal (0, sqrt(.5), -sqrt(.5))
    #   e.g. (2,3,1): cross((2,0,0), (0,1,-1)) = (0, 2, 2). All counter-clockwise
    #   seen from outside (the side the normal points to).
    # - Material 0 "roof": baseColorFactor (0.8, 0.3, 0.2, 1), metallic 0,
    #   roughness 0.5: srp albedo (0.8, 0.3, 0.2), metallic 0, smoothness 0.5.
    builder = Builder()
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "flat-normals", "nodes": [0]}]
    document["nodes"] = [{"name": "roof", "mesh": 0}]
    document["meshes"] = [{"name": "roof", "primitives": [triangles_primitive(builder, ROOF, None, ROOF_TRIANGLES, material=0)]}]
    document["materials"] = [{"name": "roof", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.3, 0.2, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5}}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# g. double-sided.gltf

FLOOR_QUAD = [(-1, 0, 1), (1, 0, 1), (1, 0, -1), (-1, 0, -1)]  # 2 x 2, facing +Y


def make_double_sided():
    # Two identical 2 x 2 quads facing +Y, side by side; only the material differs.
    # - Shared accessors: vertices (-1,0,1), (1,0,1), (1,0,-1), (-1,0,-1), normals
    #   (0,1,0), triangles (0,1,2), (0,2,3) (counter-clockwise seen from +Y).
    # - node 0 "double-sided", translation (-1.5, 0, 0), mesh 0 (material 0,
    #   doubleSided true): world vertices (-2.5,0,1), (-0.5,0,1), (-0.5,0,-1),
    #   (-2.5,0,-1). Object "double-sided/0": 4 triangles, the two above with
    #   normal (0,1,0) and the same two reversed, (0,2,1), (0,3,2) in these
    #   vertices, with normal (0,-1,0).
    # - node 1 "single-sided", translation (1.5, 0, 0), mesh 1 (the same
    #   accessors, material 1, doubleSided false): world vertices (0.5,0,1),
    #   (2.5,0,1), (2.5,0,-1), (0.5,0,-1). Object "single-sided/0": 2 triangles,
    #   normal (0,1,0).
    # - Both materials: baseColorFactor (1,1,1,1), metallic 0, roughness 1:
    #   srp albedo (1,1,1), metallic 0, smoothness 0.
    # Seen from below (double-sided.json) only the double-sided quad shows.
    builder = Builder()
    primitive = triangles_primitive(builder, FLOOR_QUAD, [(0.0, 1.0, 0.0)] * 4, QUAD_TRIANGLES, material=0)
    single = dict(primitive, material=1)
    pbr = {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}
    document = new_document()
    document["scene"] = 0
    document["scenes"] = [{"name": "double-sided", "nodes": [0, 1]}]
    document["nodes"] = [{"name": "double-sided", "mesh": 0, "translation": [-1.5, 0, 0]},
                         {"name": "single-sided", "mesh": 1, "translation": [1.5, 0, 0]}]
    document["meshes"] = [{"name": "quad-double-sided", "primitives": [primitive]},
                          {"name": "quad-single-sided", "primitives": [single]}]
    document["materials"] = [{"name": "double-sided", "doubleSided": True, "pbrMetallicRoughness": dict(pbr)},
                             {"name": "single-sided", "doubleSided": False, "pbrMetallicRoughness": dict(pbr)}]
    return builder.finish(document)


# ---------------------------------------------------------------------------
# h. punctual-lights.gltf

FLOOR_8 = [(-4, 0, 4), (4, 0, 4), (4, 0, -4), (-4, 0, -4)]  # 8 x 8, facing +Y


def make_punctual_lights():
    # KHR_lights_punctual (in extensionsUsed): four lights, a floor and a camera.
    # Nodes (scene 0 = [0, 1, 2, 3, 4, 6]; depth-first order = node order
    # 0, 1, 2, 3, 4, 5, 6, so the lights come out in light-index order):
    #   0 "floor"       mesh 0: 8 x 8 quad at y = 0, vertices (-4,0,4), (4,0,4),
    #                   (4,0,-4), (-4,0,-4), normals (0,1,0), triangles (0,1,2),
    #                   (0,2,3); material 0 "white": baseColorFactor (1,1,1,1),
    #                   metallic 0, roughness 1 (srp albedo 1, metallic 0,
    #                   smoothness 0). Object "floor/0".
    #   1 "sun-node"    light 0, rotation (-0.5, 0, 0, sqrt(3)/2) = -60 degrees
    #                   about +X. Rx(-60) maps (0, 0, -1) to (0, -sin 60, -cos 60).
    #   2 "bulb-node"   light 1, translation (1, 2, 0).
    #   3 "spot-node"   light 2, translation (-1, 3, 1), rotation (-sqrt(.5), 0,
    #                   0, sqrt(.5)) = -90 degrees about +X: (x, y, z) -> (x, z, -y),
    #                   so (0, 0, -1) -> (0, -1, 0): it points straight down.
    #   4 "lamp-holder" translation (0, 1, 0), children [5]
    #   5 "lamp"        light 3, translation (0, 1, -2)
    #   6 "camera"      camera 0, translation (0, 6, 6), rotation (sin(-22.5deg),
    #                   0, 0, cos(22.5deg)) = -45 degrees about +X.
    # Lights after SPEC 2.1's mapping (imported lights' names: the light's name,
    # else its node's; range from the scene's light_defaults where absent):
    #   0 "sun"  directional, direction (0, -sqrt(3)/2, -0.5) = (0, -0.8660254,
    #            -0.5), color (1, 0.5, 0.25) x intensity 2 = finalColor (2, 1, 0.5);
    #            its position (the node's origin) is (0, 0, 0) and unused.
    #   1 "bulb" point, position (1, 2, 0), color absent = (1, 1, 1) x 4 =
    #            (4, 4, 4), range 5.
    #   2 "spot" spot, position (-1, 3, 1), direction (0, -1, 0) (to about 1e-16:
    #            sqrt(.5) is not exact), color (0.5, 0.75, 1) x 3 = (1.5, 2.25, 3),
    #            range 6, innerConeAngle pi/8, outerConeAngle pi/4:
    #            spot_angle_deg = 2 x 45 = 90, inner_spot_angle_deg = 2 x 22.5 = 45
    #            (up to double rounding of pi/4 * 180/pi).
    #   3 (no name: "lamp") point, position (0, 1, 0) + (0, 1, -2) = (0, 2, -2),
    #            color absent x 1 = (1, 1, 1), NO range: the importing scene's
    #            light_defaults.range (4 in punctual-lights.json); without one
    #            the import is an error naming this light.
    # Camera 0 (perspective, yfov 0.8, znear 0.1, zfar 50, aspectRatio 1):
    #   position (0, 6, 6); view direction = Rx(-45) (0, 0, -1) = (0, -sqrt(.5),
    #   -sqrt(.5)), looking at the origin (it lies on the view line, 6 sqrt(2)
    #   away); up = Rx(-45) (0, 1, 0) = (0, sqrt(.5), -sqrt(.5)); fov_y_deg =
    #   0.8 * 180 / pi = 45.83662361046586; near 0.1, far 50.
    builder = Builder()
    floor = triangles_primitive(builder, FLOOR_8, [(0.0, 1.0, 0.0)] * 4, QUAD_TRIANGLES, material=0)
    document = new_document(["KHR_lights_punctual"])
    document["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": [1.0, 0.5, 0.25], "intensity": 2.0},
        {"name": "bulb", "type": "point", "intensity": 4.0, "range": 5.0},
        {"name": "spot", "type": "spot", "color": [0.5, 0.75, 1.0], "intensity": 3.0, "range": 6.0,
         "spot": {"innerConeAngle": math.pi / 8, "outerConeAngle": math.pi / 4}},
        {"type": "point", "intensity": 1.0},
    ]}}
    document["scene"] = 0
    document["scenes"] = [{"name": "punctual-lights", "nodes": [0, 1, 2, 3, 4, 6]}]
    document["nodes"] = [
        {"name": "floor", "mesh": 0},
        {"name": "sun-node", "extensions": {"KHR_lights_punctual": {"light": 0}},
         "rotation": [-0.5, 0, 0, math.sqrt(3) / 2]},
        {"name": "bulb-node", "extensions": {"KHR_lights_punctual": {"light": 1}}, "translation": [1, 2, 0]},
        {"name": "spot-node", "extensions": {"KHR_lights_punctual": {"light": 2}},
         "rotation": [-SQRT_HALF, 0, 0, SQRT_HALF], "translation": [-1, 3, 1]},
        {"name": "lamp-holder", "children": [5], "translation": [0, 1, 0]},
        {"name": "lamp", "extensions": {"KHR_lights_punctual": {"light": 3}}, "translation": [0, 1, -2]},
        {"name": "camera", "camera": 0, "rotation": quaternion_about((1, 0, 0), -45), "translation": [0, 6, 6]},
    ]
    document["cameras"] = [{"name": "overview", "type": "perspective",
                            "perspective": {"aspectRatio": 1.0, "yfov": 0.8, "zfar": 50.0, "znear": 0.1}}]
    document["meshes"] = [{"name": "floor", "primitives": [floor]}]
    document["materials"] = [{"name": "white", "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}]
    return builder.finish(document)


MODELS = [
    ("plane.gltf", make_plane),
    ("sphere.gltf", make_sphere),
    ("box.gltf", make_box),
    ("hierarchy.gltf", make_hierarchy),
    ("strips-and-fans.gltf", make_strips_and_fans),
    ("flat-normals.gltf", make_flat_normals),
    ("double-sided.gltf", make_double_sided),
    ("punctual-lights.gltf", make_punctual_lights),
]


def render(document):
    return json.dumps(document, indent=1, sort_keys=False) + "\n"


# ---------------------------------------------------------------------------
# --check: read the written files back and compare them with the hand values,
# through a matrix computation of its own (nothing above is reused for the
# transforms), so a slip in a comment or in a node shows up here.


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def node_matrix(node):
    if "matrix" in node:
        m = node["matrix"]
        return [[m[col * 4 + row] for col in range(4)] for row in range(4)]
    tx, ty, tz = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    sx, sy, sz = node.get("scale", [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    s = (sx, sy, sz)
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], (tx, ty, tz)[i]] for i in range(3)] + [[0, 0, 0, 1]]


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def cofactor3(m):
    # The cofactor matrix is det * inverse transpose: the normals' direction,
    # flipped where det < 0 (the caller multiplies by det's sign).
    c = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            rows = [r for r in range(3) if r != i]
            cols = [k for k in range(3) if k != j]
            minor = m[rows[0]][cols[0]] * m[rows[1]][cols[1]] - m[rows[0]][cols[1]] * m[rows[1]][cols[0]]
            c[i][j] = (-1) ** (i + j) * minor
    return c


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def walk(document, scene_index):
    """(node index, world matrix) in depth-first order, children in array order."""
    nodes = document["nodes"]
    out = []

    def visit(index, parent):
        world = mat_mul(parent, node_matrix(nodes[index]))
        out.append((index, world))
        for child in nodes[index].get("children", []):
            visit(child, world)

    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    for root in document["scenes"][scene_index]["nodes"]:
        visit(root, identity)
    return out


def read_accessor(document, blob, index):
    accessor = document["accessors"][index]
    view = document["bufferViews"][accessor["bufferView"]]
    offset = view["byteOffset"] + accessor.get("byteOffset", 0)
    width = {"SCALAR": 1, "VEC3": 3}[accessor["type"]]
    fmt = {FLOAT: "f", UNSIGNED_INT: "I", UNSIGNED_SHORT: "H"}[accessor["componentType"]]
    size = struct.calcsize("<" + fmt) * width
    count = accessor["count"]
    assert offset % 4 == 0 and offset + count * size <= view["byteOffset"] + view["byteLength"]
    values = [struct.unpack_from("<" + fmt * width, blob, offset + k * size) for k in range(count)]
    return [v[0] for v in values] if width == 1 else [list(v) for v in values]


def primitive_triangles(document, blob, primitive):
    positions = read_accessor(document, blob, primitive["attributes"]["POSITION"])
    count = len(positions)
    indices = read_accessor(document, blob, primitive["indices"]) if "indices" in primitive else list(range(count))
    mode = primitive.get("mode", TRIANGLES)
    if mode == TRIANGLES:
        return [tuple(indices[i:i + 3]) for i in range(0, len(indices) - 2, 3)]
    if mode == TRIANGLE_STRIP:
        return [(indices[i], indices[i + 1], indices[i + 2]) if i % 2 == 0 else (indices[i], indices[i + 2], indices[i + 1])
                for i in range(len(indices) - 2)]
    if mode == TRIANGLE_FAN:
        return [(indices[i + 1], indices[i + 2], indices[0]) for i in range(len(indices) - 2)]
    return None


def transform_point(m, p):
    return [sum(m[i][k] * p[k] for k in range(3)) + m[i][3] for i in range(3)]


def check_files(out_dir):
    problems = []

    def close(a, b, tol=1e-12):
        return all(abs(x - y) <= tol for x, y in zip(a, b))

    def expect(condition, what):
        if not condition:
            problems.append(what)

    loaded = {}
    for name, _ in MODELS:
        with open(os.path.join(out_dir, name), encoding="utf-8") as f:
            document = json.load(f)
        prefix = "data:application/octet-stream;base64,"
        (buffer,) = document["buffers"]
        expect(buffer["uri"].startswith(prefix), name + ": buffer is not an embedded octet stream")
        blob = base64.b64decode(buffer["uri"][len(prefix):])
        expect(len(blob) == buffer["byteLength"], name + ": byteLength")
        for k, view in enumerate(document["bufferViews"]):
            expect(view["byteOffset"] % 4 == 0, "%s: bufferView %d offset" % (name, k))
            expect(view["byteOffset"] + view["byteLength"] <= len(blob), "%s: bufferView %d range" % (name, k))
        for mesh in document["meshes"]:
            for primitive in mesh["primitives"]:
                accessor = document["accessors"][primitive["attributes"]["POSITION"]]
                positions = read_accessor(document, blob, primitive["attributes"]["POSITION"])
                expect(accessor["min"] == [min(p[k] for p in positions) for k in range(3)], name + ": POSITION min")
                expect(accessor["max"] == [max(p[k] for p in positions) for k in range(3)], name + ": POSITION max")
        loaded[name] = (document, blob)

    def first_primitive(name, mesh=0):
        document, blob = loaded[name]
        primitive = document["meshes"][mesh]["primitives"][0]
        positions = read_accessor(document, blob, primitive["attributes"]["POSITION"])
        normals = read_accessor(document, blob, primitive["attributes"]["NORMAL"]) if "NORMAL" in primitive["attributes"] else None
        return positions, normals, primitive_triangles(document, blob, primitive)

    # The built-ins: what the file holds is buildPlane/Sphere/Box rounded to float32.
    for name, geometry in (("plane.gltf", plane_geometry(8.0, 8.0, 4)),
                           ("sphere.gltf", sphere_geometry(1.0, 24, 12)),
                           ("box.gltf", box_geometry((2.0, 1.0, 1.5)))):
        positions, normals, triangles = first_primitive(name)
        expect(positions == [[f32(c) for c in p] for p in geometry[0]], name + ": positions")
        expect(normals == [[f32(c) for c in n] for n in geometry[1]], name + ": normals")
        expect(triangles == [tuple(t) for t in geometry[2]], name + ": triangles")
    expect(len(first_primitive("plane.gltf")[0]) == 25 and len(first_primitive("plane.gltf")[2]) == 32, "plane counts")
    expect(first_primitive("plane.gltf")[2][:2] == [(0, 5, 6), (0, 6, 1)], "plane first cell")
    expect(len(first_primitive("sphere.gltf")[0]) == 325 and len(first_primitive("sphere.gltf")[2]) == 528, "sphere counts")
    expect(first_primitive("sphere.gltf")[2][:3] == [(0, 26, 25), (1, 27, 26), (2, 28, 27)], "sphere first triangles")
    expect(len(first_primitive("box.gltf")[0]) == 24 and len(first_primitive("box.gltf")[2]) == 12, "box counts")

    # Hierarchy: world positions, normals (inverse transpose) and determinants.
    document, blob = loaded["hierarchy.gltf"]
    objects = [(document["nodes"][i]["name"] + "/0", world) for i, world in walk(document, 0) if "mesh" in document["nodes"][i]]
    expect([o[0] for o in objects] == [e[0] for e in HIERARCHY_EXPECTED], "hierarchy object order %s" % [o[0] for o in objects])
    positions, normals, triangles = first_primitive("hierarchy.gltf")
    expect(triangles == QUAD_TRIANGLES, "hierarchy quad triangles")
    for (name, world), (_, corners, normal, reversed_) in zip(objects, HIERARCHY_EXPECTED):
        linear = [row[:3] for row in world[:3]]
        got = [transform_point(world, p) for p in positions]
        expect(all(close(g, c) for g, c in zip(got, corners)), "%s positions %s" % (name, got))
        sign = 1 if det3(linear) > 0 else -1
        n = normalize([sign * sum(cofactor3(linear)[i][k] * normals[0][k] for k in range(3)) for i in range(3)])
        expect(close(n, normal), "%s normal %s" % (name, n))
        expect((det3(linear) < 0) == reversed_, "%s determinant %g" % (name, det3(linear)))
        # The normal must lie on the side the (possibly reversed) winding faces.
        a, b, c = (got[i] for i in QUAD_TRIANGLES[0])
        e1, e2 = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
        face = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        facing = sum(face[k] * n[k] for k in range(3))
        expect((facing < 0) == reversed_, "%s winding against normal" % name)

    # Strips and fans: the triangles as positions, each counter-clockwise from +Z.
    def ccw_from_z(tri):
        (ax, ay, _), (bx, by, _), (cx, cy, _) = tri
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) > 0

    for mesh, expected in ((0, STRIP_EXPECTED), (1, FAN_EXPECTED)):
        positions, normals, triangles = first_primitive("strips-and-fans.gltf", mesh)
        got = [[tuple(positions[i]) for i in t] for t in triangles]
        want = [[tuple(float(c) for c in p) for p in t] for t in expected]
        expect(got == want, "strips-and-fans mesh %d triangles %s" % (mesh, got))
        expect(all(ccw_from_z(t) for t in got), "strips-and-fans mesh %d winding" % mesh)
    expect(loaded["strips-and-fans.gltf"][0]["accessors"][
        loaded["strips-and-fans.gltf"][0]["meshes"][0]["primitives"][0]["indices"]]["componentType"] == UNSIGNED_SHORT,
        "strip indices are UNSIGNED_SHORT")
    expect("indices" not in loaded["strips-and-fans.gltf"][0]["meshes"][1]["primitives"][0], "fan has no indices")

    # Flat normals: the face normals of the roof.
    positions, normals, triangles = first_primitive("flat-normals.gltf")
    expect(normals is None, "roof has no NORMAL")
    for t, want in zip(triangles, ROOF_NORMALS):
        a, b, c = (positions[i] for i in t)
        e1, e2 = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
        n = normalize([e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]])
        expect(close(n, want), "roof face normal %s" % n)

    # Lights and camera.
    document, blob = loaded["punctual-lights.gltf"]
    lights = document["extensions"]["KHR_lights_punctual"]["lights"]
    found = []
    for i, world in walk(document, 0):
        node = document["nodes"][i]
        if "KHR_lights_punctual" in node.get("extensions", {}):
            light = lights[node["extensions"]["KHR_lights_punctual"]["light"]]
            direction = normalize([-world[r][2] for r in range(3)])
            found.append((light.get("name", node["name"]), light["type"], [world[r][3] for r in range(3)], direction,
                          light.get("range"), light.get("spot")))
        if "camera" in node:
            position = [world[r][3] for r in range(3)]
            forward = normalize([-world[r][2] for r in range(3)])
            up = normalize([world[r][1] for r in range(3)])
            expect(close(position, [0, 6, 6]), "camera position %s" % position)
            expect(close(forward, [0, -SQRT_HALF, -SQRT_HALF]), "camera direction %s" % forward)
            expect(close(up, [0, SQRT_HALF, -SQRT_HALF]), "camera up %s" % up)
    expect([f[0] for f in found] == ["sun", "bulb", "spot", "lamp"], "light order %s" % [f[0] for f in found])
    expect(close(found[0][3], [0, -math.sqrt(3) / 2, -0.5]), "sun direction %s" % found[0][3])
    expect(close(found[1][2], [1, 2, 0]), "bulb position")
    expect(close(found[2][2], [-1, 3, 1]) and close(found[2][3], [0, -1, 0]), "spot position/direction %s" % found[2][3])
    spot = found[2][5]
    expect(abs(math.degrees(2 * spot["outerConeAngle"]) - 90) < 1e-12, "spot outer angle")
    expect(abs(math.degrees(2 * spot["innerConeAngle"]) - 45) < 1e-12, "spot inner angle")
    expect(close(found[3][2], [0, 2, -2]) and found[3][4] is None, "lamp position / no range")
    expect(abs(math.degrees(document["cameras"][0]["perspective"]["yfov"]) - 45.83662361046586) < 1e-12, "camera fov")
    return problems


def main():
    parser = argparse.ArgumentParser(description="Writes the glTF models of suite/scenes/gltf/.")
    parser.add_argument("--out", default=DEFAULT_OUT, help="folder to write into (default: %(default)s)")
    parser.add_argument("--check", action="store_true", help="check the written files against the hand-derived values")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, make in MODELS:
        with open(os.path.join(args.out, name), "w", encoding="utf-8", newline="\n") as f:
            f.write(render(make()))
    if args.check:
        problems = check_files(args.out)
        for p in problems:
            print("check: " + p, file=sys.stderr)
        if problems:
            return 1
        print("check: %d files match their hand-derived values" % len(MODELS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
