#!/usr/bin/env python3
"""Feeds lightcts broken glTF files and checks that it fails cleanly.

Makes COUNT mutants of the seed .gltf files (JSON with embedded base64
buffers), runs `LIGHTCTS lights --scene MUTANT.gltf` on each (a bare glTF file
is a scene, SPEC 2.1) and, for every 10th mutant that loaded (exit 0),
`LIGHTCTS reference --scene MUTANT.gltf --out DIR` too. A violation is:
an exit status other than 0, 2 or 3 (SPEC 8; a signal, 1 and 4 included), an
exit 2 whose stderr is empty or does not name the mutant's file, or a command
that runs past the timeout. Prints counts per exit status and per mutation
kind, then every violation with its command, status, stderr's tail and the
mutant file, which stays in the output folder (mutants.json there lists what
was done to each). Exit status: 0 no violation, 1 violations, 2 bad usage
(no seed file, output folder not fresh, LIGHTCTS not executable).

Usage:
  fuzz_gltf.py --lightcts PATH [--seeds DIR] [--out DIR] [--count N]
               [--seed S] [--jobs J] [--timeout SECONDS]

  --lightcts  the lightcts executable
  --seeds     folder whose .gltf files (searched recursively) are mutated;
              default suite/scenes/gltf/models/ beside this script
  --out       a new or empty folder for the mutants (default: a new temporary
              folder, printed)
  --count     number of mutants, default 400
  --seed      random seed, default 1; the same arguments make the same mutants
  --jobs      commands run in parallel, default 2
  --timeout   seconds one command may take, default 20

Mutation kinds (one to four stacked per mutant): see KINDS below.
"""
import argparse
import base64
import concurrent.futures
import copy
import json
import math
import os
import random
import re
import shlex
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SEEDS = os.path.normpath(os.path.join(HERE, "..", "scenes", "gltf", "models"))
ALLOWED_STATUS = (0, 2, 3)
REFERENCE_EVERY = 10  # rendering is slow: only every 10th loaded mutant is rendered
STDERR_TAIL = 1200

# json.dumps cannot write a number literal that is not a Python float's repr
# (-0, 1e999, NaN); such values are stored as a marked string and unquoted after.
RAW = "@@raw:"
RAW_RE = re.compile(r'"@@raw:([^"]*)"')


def raw(literal):
    return RAW + literal


# ---------------------------------------------------------------- helpers

def objects(doc, key):
    """The dict entries of a top-level array; earlier stacked mutations may
    have replaced the array or its entries with other types."""
    value = doc.get(key) if isinstance(doc, dict) else None
    return [v for v in value if isinstance(v, dict)] if isinstance(value, list) else []


def length(doc, key):
    value = doc.get(key) if isinstance(doc, dict) else None
    return len(value) if isinstance(value, list) else 0


def primitives(doc):
    return [p for mesh in objects(doc, "meshes") if isinstance(mesh.get("primitives"), list)
            for p in mesh["primitives"] if isinstance(p, dict)]


def index_of(values, obj):
    """Index of obj itself in values: equal copies must not be confused."""
    return next(i for i, v in enumerate(values) if v is obj)


def pick_other(rng, choices, old):
    """A choice that differs from the current value, so the mutation is never a no-op."""
    return rng.choice([c for c in choices if c != old or type(c) is not type(old)] or choices)


def is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def walk(value, pointer=""):
    """(container, key, JSON pointer) for every value under `value`."""
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, child in items:
        path = f"{pointer}/{key}"
        yield value, key, path
        yield from walk(child, path)


def data_buffers(doc):
    """(index, buffer) of buffers whose uri is a base64 data URI."""
    return [(i, b) for i, b in enumerate(doc.get("buffers", []) if isinstance(doc.get("buffers"), list) else [])
            if isinstance(b, dict) and isinstance(b.get("uri"), str)
            and b["uri"].startswith("data:") and ";base64," in b["uri"]]


def decode_buffer(buf):
    head, _, payload = buf["uri"].partition(";base64,")
    try:
        return head, bytearray(base64.b64decode(payload, validate=True))
    except ValueError:
        return head, None  # already truncated by a stacked mutation


def encode_buffer(buf, head, data):
    buf["uri"] = head + ";base64," + base64.b64encode(bytes(data)).decode("ascii")


COMPONENT_SIZE = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
TYPE_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def accessor_slots(doc, accessor):
    """(buffer index, [byte offsets of every component], component size) of an
    accessor, or None when its references no longer make sense."""
    ctype, ncomp = accessor.get("componentType"), TYPE_COMPONENTS.get(accessor.get("type"))
    views = doc.get("bufferViews")
    view_index, count = accessor.get("bufferView"), accessor.get("count")
    # The count bound keeps the offset list small after an accessor_count mutation.
    if ctype not in COMPONENT_SIZE or not ncomp or not is_int(view_index) or not is_int(count) \
            or not isinstance(views, list) or not 0 <= view_index < len(views) or not 0 < count <= 1 << 16:
        return None
    view = views[view_index]
    if not isinstance(view, dict) or not is_int(view.get("buffer")):
        return None
    size = COMPONENT_SIZE[ctype]
    view_offset, offset = view.get("byteOffset", 0), accessor.get("byteOffset", 0)
    stride = view.get("byteStride") or size * ncomp
    if not is_int(view_offset) or not is_int(offset) or not is_int(stride):
        return None
    base = view_offset + offset
    offsets = [base + k * stride + c * size for k in range(count) for c in range(ncomp)]
    return view["buffer"], offsets, size


def write_slots(doc, rng, accessor, pack):
    """Writes pack(size) into one to three components of an accessor, inside
    its buffer; returns a description or None."""
    slots = accessor_slots(doc, accessor)
    if not slots:
        return None
    buffer_index, offsets, size = slots
    for i, buf in data_buffers(doc):
        if i != buffer_index:
            continue
        head, data = decode_buffer(buf)
        offsets = [o for o in offsets if 0 <= o and o + size <= len(data)] if data is not None else []
        if not offsets:
            return None
        chosen = sorted(rng.sample(offsets, min(len(offsets), rng.randint(1, 3))))
        for o in chosen:
            data[o:o + size] = pack(size)
        encode_buffer(buf, head, data)
        return f"buffer {buffer_index} bytes {chosen}"
    return None


def ensure_nodes(doc, n):
    """Appends empty nodes until there are n, so node mutations always apply."""
    if not isinstance(doc.get("nodes"), list):
        doc["nodes"] = []
    while len(doc["nodes"]) < n:
        doc["nodes"].append({})
    return [i for i, v in enumerate(doc["nodes"]) if isinstance(v, dict)]


# ---------------------------------------------------------------- mutation kinds
# Each takes a Mutant, changes m.doc (or queues a change of the serialised
# text in m.text_ops) and returns what it did, or None when it does not apply
# to this document; then another kind is drawn.

class Mutant:
    def __init__(self, doc, rng):
        self.doc, self.rng, self.text_ops = doc, rng, []


def truncate_base64(m):
    bufs = data_buffers(m.doc)
    if not bufs:
        return None
    i, buf = m.rng.choice(bufs)
    head, _, payload = buf["uri"].partition(";base64,")
    how = m.rng.choice(["cut k", "not a multiple of 4", "bad character", "empty"])
    if how == "cut k":
        k = m.rng.choice([4, 8, 64, max(4, len(payload) // 2 // 4 * 4)])
        payload = payload[:max(0, len(payload) - k)]
    elif how == "not a multiple of 4":
        payload = payload.rstrip("=")
        payload = payload[:max(1, len(payload) - m.rng.randint(1, 3))]
        if len(payload) % 4 == 0:
            payload = payload[:-1]
    elif how == "bad character":
        at = m.rng.randrange(len(payload) + 1)
        payload = payload[:at] + m.rng.choice(["!", " ", "\u00e9", "%"]) + payload[at:]
    else:
        payload = ""
    buf["uri"] = head + ";base64," + payload
    return f"/buffers/{i}/uri payload {how}, now {len(payload)} characters"


FLOAT_BITS = {"NaN": 0x7fc00000, "+Inf": 0x7f800000, "-Inf": 0xff800000, "max float": 0x7f7fffff,
              "denormal": 0x00000001}


def buffer_nonfinite(m):
    floats = [a for a in objects(m.doc, "accessors") if a.get("componentType") == 5126]
    if not floats:
        return None
    name = m.rng.choice(sorted(FLOAT_BITS))
    accessor = m.rng.choice(floats)
    done = write_slots(m.doc, m.rng, accessor, lambda size: struct.pack("<I", FLOAT_BITS[name]))
    return done and f"{name} into accessor {index_of(m.doc['accessors'], accessor)}: {done}"


def buffer_huge_index(m):
    index_ids = [p["indices"] for p in primitives(m.doc) if is_int(p.get("indices"))]
    accessors = m.doc.get("accessors") if isinstance(m.doc.get("accessors"), list) else []
    index_ids = [i for i in index_ids if 0 <= i < len(accessors) and isinstance(accessors[i], dict)]
    if not index_ids:
        return None
    accessor_id = m.rng.choice(index_ids)
    value = m.rng.choice([0xffffffff, 65535, 255, "vertex count"])
    if value == "vertex count":  # one past the last vertex: the off-by-one case
        counts = [accessors[p["attributes"]["POSITION"]].get("count") for p in primitives(m.doc)
                  if isinstance(p.get("attributes"), dict) and is_int(p["attributes"].get("POSITION"))
                  and 0 <= p["attributes"]["POSITION"] < len(accessors)
                  and isinstance(accessors[p["attributes"]["POSITION"]], dict)]
        value = counts[0] if counts and is_int(counts[0]) else 1 << 16

    def pack(size):
        return (value & ((1 << (8 * size)) - 1)).to_bytes(size, "little")
    done = write_slots(m.doc, m.rng, accessors[accessor_id], pack)
    return done and f"index value {value} into accessor {accessor_id}: {done}"


def buffer_zeros(m):
    """Zeroes a whole accessor: degenerate triangles, zero-length normals,
    every index 0."""
    accessors = objects(m.doc, "accessors")
    if not accessors:
        return None
    accessor = m.rng.choice(accessors)
    slots = accessor_slots(m.doc, accessor)
    if not slots:
        return None
    buffer_index, offsets, size = slots
    for i, buf in data_buffers(m.doc):
        if i == buffer_index:
            head, data = decode_buffer(buf)
            if data is None:
                return None
            for o in offsets:
                if 0 <= o and o + size <= len(data):
                    data[o:o + size] = bytes(size)
            encode_buffer(buf, head, data)
            return f"accessor {index_of(m.doc['accessors'], accessor)} zeroed in buffer {i}"
    return None


def buffer_flip(m):
    bufs = data_buffers(m.doc)
    if not bufs:
        return None
    i, buf = m.rng.choice(bufs)
    head, data = decode_buffer(buf)
    if not data:
        return None
    at = sorted(m.rng.sample(range(len(data)), min(len(data), m.rng.randint(1, 16))))
    for o in at:
        data[o] = pick_other(m.rng, [data[o] ^ (1 << m.rng.randrange(8)), 0x00, 0xff, 0x7f, 0x80], data[o])
    encode_buffer(buf, head, data)
    return f"buffer {i}: {len(at)} bytes flipped or replaced"


def byte_length(m):
    targets = [("buffers", i) for i in range(length(m.doc, "buffers"))] + \
              [("bufferViews", i) for i in range(length(m.doc, "bufferViews"))]
    targets = [(k, i) for k, i in targets if isinstance(m.doc[k][i], dict)]
    if not targets:
        return None
    key, i = m.rng.choice(targets)
    old = m.doc[key][i].get("byteLength", 0)
    old = old if is_int(old) else 0
    new = pick_other(m.rng, [old // 2, old - 1, old + 1, old * 2 + 100, 0, -1, -old, 1 << 40], old)
    m.doc[key][i]["byteLength"] = new
    return f"/{key}/{i}/byteLength {old} -> {new}"


def accessor_count(m):
    accessors = objects(m.doc, "accessors")
    if not accessors:
        return None
    a = m.rng.choice(accessors)
    old = a.get("count", 0)
    old = old if is_int(old) else 0
    a["count"] = pick_other(m.rng, [0, old + 1, old - 1, 2 ** 31, 2 ** 40], old)
    return f"/accessors/{index_of(m.doc['accessors'], a)}/count {old} -> {a['count']}"


def byte_offset(m):
    targets = [("accessors", a) for a in objects(m.doc, "accessors")] + \
              [("bufferViews", v) for v in objects(m.doc, "bufferViews")]
    if not targets:
        return None
    key, obj = m.rng.choice(targets)
    old = obj.get("byteOffset", 0)
    old = old if is_int(old) else 0
    extent = obj.get("byteLength") if key == "bufferViews" else None
    if key == "accessors":
        views = m.doc.get("bufferViews") if isinstance(m.doc.get("bufferViews"), list) else []
        view = obj.get("bufferView")
        extent = views[view].get("byteLength") if is_int(view) and 0 <= view < len(views) \
            and isinstance(views[view], dict) else None
    extent = extent if is_int(extent) else 1 << 16
    obj["byteOffset"] = pick_other(m.rng, [old + 1, 1, 3, extent, extent + 4, old + extent, 2 ** 32, -4], old)
    return f"/{key}/{index_of(m.doc[key], obj)}/byteOffset {old} -> {obj['byteOffset']}"


def component_type(m):
    accessors = objects(m.doc, "accessors")
    if not accessors:
        return None
    a = m.rng.choice(accessors)
    old = a.get("componentType")
    a["componentType"] = pick_other(m.rng, [5124, 5130, 9999, "5126", 5121, 5123, 5126], old)
    return f"/accessors/{index_of(m.doc['accessors'], a)}/componentType {old} -> {a['componentType']!r}"


def accessor_type(m):
    accessors = objects(m.doc, "accessors")
    if not accessors:
        return None
    a = m.rng.choice(accessors)
    old = a.get("type")
    a["type"] = pick_other(m.rng, ["VEC4", "SCALAR", "BOGUS", "MAT4", "vec3"], old)
    return f"/accessors/{index_of(m.doc['accessors'], a)}/type {old!r} -> {a['type']!r}"


def primitive_mode(m):
    prims = primitives(m.doc)
    if not prims:
        return None
    p = m.rng.choice(prims)
    old = p.get("mode", 4)
    p["mode"] = pick_other(m.rng, [0, 1, 2, 3, 4, 5, 6, 7, -1], old)
    return f"a primitive's mode {old} -> {p['mode']}"


def primitive_reference(m):
    prims = primitives(m.doc)
    if not prims:
        return None
    p = m.rng.choice(prims)
    n = length(m.doc, "accessors")
    attributes = p.get("attributes") if isinstance(p.get("attributes"), dict) else {}
    slots = ["indices"] + [f"attributes/{k}" for k in attributes]
    slot = m.rng.choice(slots)
    float_ids = [i for i, a in enumerate(m.doc.get("accessors", [])) if isinstance(a, dict)
                 and a.get("componentType") == 5126] if n else []
    choices = [n, n + 7, -1, "0", 2 ** 40] + ([m.rng.choice(float_ids)] if slot == "indices" and float_ids else [])
    value = m.rng.choice(choices)
    if slot == "indices":
        p["indices"] = value
    else:
        attributes[slot.split("/", 1)[1]] = value
    return f"a primitive's {slot} -> {value!r} ({n} accessors)"


def node_children(m):
    how = m.rng.choice(["self", "cycle of two", "out of range", "two parents"])
    ids = ensure_nodes(m.doc, 2 if how == "self" or how == "out of range" else 3)
    nodes = m.doc["nodes"]
    a, b = m.rng.sample(ids, 2) if len(ids) >= 2 else (ids[0], ids[0])

    def add_child(parent, child):
        kids = nodes[parent].get("children")
        nodes[parent]["children"] = (kids if isinstance(kids, list) else []) + [child]
    if how == "self":
        add_child(a, a)
        return f"/nodes/{a} is its own child"
    if how == "cycle of two":
        add_child(a, b)
        add_child(b, a)
        return f"/nodes/{a} and /nodes/{b} are each other's child"
    if how == "out of range":
        bad = m.rng.choice([len(nodes), 2 ** 31, -1])
        add_child(a, bad)
        return f"/nodes/{a} has child {bad} ({len(nodes)} nodes)"
    c = m.rng.choice([i for i in ids if i not in (a, b)] or [a])
    add_child(a, c)
    add_child(b, c)
    return f"/nodes/{c} is a child of both /nodes/{a} and /nodes/{b}"


def node_reference(m):
    ids = ensure_nodes(m.doc, 1)
    i = m.rng.choice(ids)
    key = m.rng.choice(["mesh", "camera"])
    n = length(m.doc, "meshes" if key == "mesh" else "cameras")
    m.doc["nodes"][i][key] = m.rng.choice([n, n + 3, -1, 2 ** 32])
    return f"/nodes/{i}/{key} -> {m.doc['nodes'][i][key]} ({n} {'meshes' if key == 'mesh' else 'cameras'})"


def node_matrix(m):
    ids = ensure_nodes(m.doc, 1)
    i = m.rng.choice(ids)
    node = m.doc["nodes"][i]
    identity = [1.0 if r == c else 0.0 for c in range(4) for r in range(4)]
    how = m.rng.choice(["15 elements", "a non-number", "all zeros", "with TRS too"])
    if how == "15 elements":
        node["matrix"] = identity[:15]
    elif how == "a non-number":
        node["matrix"] = identity
        node["matrix"][m.rng.randrange(16)] = m.rng.choice(["1", None, [1], True])
    elif how == "all zeros":  # a singular world matrix: normals' inverse transpose does not exist
        node["matrix"] = [0.0] * 16
    else:  # glTF forbids matrix and TRS on one node
        node["matrix"] = identity
        node["translation"] = [1.0, 2.0, 3.0]
    return f"/nodes/{i}/matrix {how}"


def node_rotation(m):
    ids = ensure_nodes(m.doc, 1)
    i = m.rng.choice(ids)
    value = m.rng.choice([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0, 0.0]])
    m.doc["nodes"][i].pop("matrix", None)
    m.doc["nodes"][i]["rotation"] = value
    return f"/nodes/{i}/rotation -> {value}"


def node_scale(m):
    ids = ensure_nodes(m.doc, 1)
    i = m.rng.choice(ids)
    value = m.rng.choice([[0.0, 0.0, 0.0], [0.0, 1.0, 1.0], [1e300, 1e300, 1e300], [1e-300, 1e-300, 1e-300]])
    node = m.doc["nodes"][i]
    node.pop("matrix", None)
    node["scale"] = value
    if value[0] == 1e300 and m.rng.random() < 0.5:
        node["translation"] = [1e308, 0.0, 0.0]  # overflows to inf once scaled by a parent
    return f"/nodes/{i}/scale -> {value}"


def scene_keys(m):
    how = m.rng.choice(["no scene", "no scenes", "scene a string", "scene out of range",
                        "scenes an object", "scene nodes a string", "scene node out of range"])
    doc = m.doc
    if how == "no scene":
        doc.pop("scene", None)
    elif how == "no scenes":
        doc.pop("scenes", None)
    elif how == "scene a string":
        doc["scene"] = "0"
    elif how == "scene out of range":
        doc["scene"] = length(doc, "scenes") + m.rng.choice([0, 5])
    elif how == "scenes an object":
        doc["scenes"] = {"nodes": [0]}
    else:
        scenes = objects(doc, "scenes")
        if not scenes:
            return None
        s = m.rng.choice(scenes)
        s["nodes"] = "0" if how == "scene nodes a string" else [length(doc, "nodes")]
    return how


def other_type_value(rng, value):
    kinds = {"null": None, "string": rng.choice(["", "0", "x"]), "object": {}, "array": rng.choice([[], [1]]),
             "bool": rng.choice([True, False]), "number": rng.choice([0, 1, 2.5])}
    current = ("null" if value is None else "bool" if isinstance(value, bool) else "number" if is_number(value)
               else "string" if isinstance(value, str) else "array" if isinstance(value, list) else "object")
    name = rng.choice(sorted(k for k in kinds if k != current))
    return name, kinds[name]


def wrong_type(m):
    paths = list(walk(m.doc))
    if not paths:
        return None
    parent, key, pointer = m.rng.choice(paths)
    name, value = other_type_value(m.rng, parent[key])
    parent[key] = value
    return f"{pointer} -> {name}"


def delete_required(m):
    doc = m.doc
    candidates = [(doc, "asset", "/asset")]
    if isinstance(doc.get("asset"), dict):
        candidates.append((doc["asset"], "version", "/asset/version"))
    for key, fields in (("buffers", ["byteLength"]), ("bufferViews", ["buffer", "byteLength"]),
                        ("accessors", ["componentType", "count", "type"]), ("meshes", ["primitives"])):
        for i, obj in enumerate(doc.get(key) if isinstance(doc.get(key), list) else []):
            if isinstance(obj, dict):
                candidates += [(obj, f, f"/{key}/{i}/{f}") for f in fields if f in obj]
    for p in primitives(doc):
        candidates.append((p, "attributes", "a primitive's attributes"))
        if isinstance(p.get("attributes"), dict) and "POSITION" in p["attributes"]:
            candidates.append((p["attributes"], "POSITION", "a primitive's POSITION"))
    candidates = [c for c in candidates if c[1] in c[0]]
    if not candidates:
        return None
    obj, key, pointer = m.rng.choice(candidates)
    del obj[key]
    return f"{pointer} deleted"


EXTREME = [1e308, -1e308, -0.0, raw("-0"), raw("1e999"), raw("-1e999"), raw("1e-400"), raw("NaN"),
           raw("Infinity")]


def extreme_number(m):
    slots = [(parent, key, pointer) for parent, key, pointer in walk(m.doc) if is_number(parent[key])]
    if not slots:
        return None
    parent, key, pointer = m.rng.choice(slots)
    value = m.rng.choice(EXTREME)
    parent[key] = value
    return f"{pointer} -> {str(value).replace(RAW, '')}"


def ensure_light(m):
    """Indices of the KHR_lights_punctual lights; when the document has none,
    adds a spot light on a new root node of scene 0, so that light mutations
    apply to every seed."""
    doc = m.doc
    if not isinstance(doc.get("extensions"), dict):
        doc["extensions"] = {}
    khr = doc["extensions"].get("KHR_lights_punctual")
    if not isinstance(khr, dict) or not isinstance(khr.get("lights"), list) or \
            not any(isinstance(light, dict) for light in khr["lights"]):
        khr = doc["extensions"]["KHR_lights_punctual"] = {"lights": [
            {"type": "spot", "color": [1.0, 1.0, 1.0], "intensity": 5.0, "range": 10.0,
             "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}}]}
        used = doc.get("extensionsUsed")
        doc["extensionsUsed"] = (used if isinstance(used, list) else []) + ["KHR_lights_punctual"]
        ensure_nodes(doc, 0)
        doc["nodes"].append({"translation": [0.0, 2.0, 0.0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
        scenes = objects(doc, "scenes")
        if scenes and isinstance(scenes[0].get("nodes"), list):
            scenes[0]["nodes"].append(len(doc["nodes"]) - 1)
    return [i for i, light in enumerate(khr["lights"]) if isinstance(light, dict)]


def khr_light(m):
    ids = ensure_light(m)
    i = m.rng.choice(ids)
    light = m.doc["extensions"]["KHR_lights_punctual"]["lights"][i]
    how = m.rng.choice(["type area", "negative range", "range 0", "outer > pi/2", "inner > outer",
                        "color of 2", "negative intensity", "no type", "node light out of range"])

    def spot(inner, outer):
        light["type"] = "spot"
        light["spot"] = {"innerConeAngle": inner, "outerConeAngle": outer}
    if how == "type area":
        light["type"] = "area"
    elif how == "negative range":
        light["range"] = -m.rng.choice([1.0, 1e-9])
    elif how == "range 0":
        light["range"] = 0.0
    elif how == "outer > pi/2":
        spot(0.1, math.pi / 2 + m.rng.choice([1e-6, 0.5, 10.0]))
    elif how == "inner > outer":
        spot(0.6, 0.3)
    elif how == "color of 2":
        light["color"] = [1.0, 1.0]
    elif how == "negative intensity":
        light["intensity"] = -1.0
    elif how == "no type":
        light.pop("type", None)
    else:
        n = len(m.doc["extensions"]["KHR_lights_punctual"]["lights"])
        ids = ensure_nodes(m.doc, 1)
        node = m.doc["nodes"][m.rng.choice(ids)]
        node["extensions"] = {"KHR_lights_punctual": {"light": m.rng.choice([n, -1, "0"])}}
    return f"light {i}: {how}"


def invalid_json(m):
    m.text_ops.append(("truncate", m.rng.random()))
    return "text truncated"


def empty_file(m):
    m.text_ops.append(("empty", None))
    return "file emptied"


def glb_magic(m):
    m.text_ops.append(("glb magic", m.rng.choice(["header", "magic only", "over the brace"])))
    return f"GLB magic ({m.text_ops[-1][1]}) at the start of the text"


KINDS = {
    "truncate_base64": truncate_base64,
    "buffer_nonfinite": buffer_nonfinite,
    "buffer_huge_index": buffer_huge_index,
    "buffer_zeros": buffer_zeros,
    "buffer_flip": buffer_flip,
    "byte_length": byte_length,
    "accessor_count": accessor_count,
    "byte_offset": byte_offset,
    "component_type": component_type,
    "accessor_type": accessor_type,
    "primitive_mode": primitive_mode,
    "primitive_reference": primitive_reference,
    "node_children": node_children,
    "node_reference": node_reference,
    "node_matrix": node_matrix,
    "node_rotation": node_rotation,
    "node_scale": node_scale,
    "scene_keys": scene_keys,
    "wrong_type": wrong_type,
    "delete_required": delete_required,
    "extreme_number": extreme_number,
    "khr_light": khr_light,
    "invalid_json": invalid_json,
    "empty_file": empty_file,
    "glb_magic": glb_magic,
}


def serialise(m):
    text = RAW_RE.sub(lambda match: match.group(1), json.dumps(m.doc, indent=1))
    data = text.encode("utf-8")
    for op, arg in m.text_ops:
        if op == "truncate":
            data = data[:max(1, int(len(data) * arg))] if len(data) > 1 else b""
        elif op == "empty":
            data = b""
        elif arg == "header":
            data = b"glTF" + struct.pack("<II", 2, len(data) + 12) + data
        elif arg == "magic only":
            data = b"glTF" + data
        else:
            data = b"glTF" + data[4:]
    return data


def make_mutant(seed_doc, rng):
    """The mutant's bytes and [(kind, detail)]: one kind, then each further
    one with probability 0.35, at most four."""
    m = Mutant(copy.deepcopy(seed_doc), rng)
    wanted = 1
    while wanted < 4 and rng.random() < 0.35:
        wanted += 1
    done, names = [], list(KINDS)
    for _ in range(wanted):
        for _attempt in range(50):
            kind = rng.choice(names)
            detail = KINDS[kind](m)
            if detail:
                done.append((kind, detail))
                break
    return serialise(m), done


# ---------------------------------------------------------------- running

def run_command(argv, timeout):
    """Runs argv in its own process group, so that a command past its time is
    killed with whatever it started."""
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = proc.communicate()
    return {"argv": argv, "status": proc.returncode, "timed_out": timed_out,
            "seconds": round(time.monotonic() - start, 3),
            "stdout": out.decode("utf-8", "replace"), "stderr": err.decode("utf-8", "replace")}


def status_label(result):
    if result["timed_out"]:
        return "timeout"
    if result["status"] < 0:
        try:
            return signal.Signals(-result["status"]).name
        except ValueError:
            return f"signal {-result['status']}"
    return str(result["status"])


def violation(result, file_name, timeout):
    if result["timed_out"]:
        return f"ran longer than {timeout:g} s and was killed"
    status = result["status"]
    if status < 0:
        return f"killed by {status_label(result)}"
    if status not in ALLOWED_STATUS:
        return f"exit status {status}; only 0, 2 and 3 are allowed for bad input"
    if status == 2 and not result["stderr"].strip():
        return "exit 2 with nothing on stderr"
    if status == 2 and file_name not in result["stderr"]:
        return f"exit 2 but stderr does not name {file_name}"
    return None


def find_seeds(folder):
    found = []
    for dirpath, dirnames, names in os.walk(folder):
        dirnames.sort()
        found += [os.path.join(dirpath, n) for n in sorted(names) if n.lower().endswith(".gltf")]
    return found


def load_seeds(paths):
    """Seeds as parsed JSON; a seed whose buffers are not all embedded is
    skipped, since a mutant away from its .bin would only test a missing file."""
    seeds, skipped = [], []
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                doc = json.load(f)
        except (OSError, ValueError) as e:
            skipped.append(f"{path}: {e}")
            continue
        if not isinstance(doc, dict):
            skipped.append(f"{path}: not a JSON object")
            continue
        buffers = doc.get("buffers") if isinstance(doc.get("buffers"), list) else []
        if len(data_buffers(doc)) != len(buffers):
            skipped.append(f"{path}: a buffer is not a base64 data URI")
            continue
        seeds.append((path, doc))
    return seeds, skipped


def tail(text):
    text = text.rstrip()
    return text if len(text) <= STDERR_TAIL else "..." + text[-STDERR_TAIL:]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lightcts", required=True)
    parser.add_argument("--seeds", default=DEFAULT_SEEDS)
    parser.add_argument("--out")
    parser.add_argument("--count", type=int, default=400)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=20.0)
    args = parser.parse_args()

    lightcts = os.path.abspath(args.lightcts)
    if not os.path.isfile(lightcts) or not os.access(lightcts, os.X_OK):
        print(f"fuzz_gltf: {args.lightcts} is not an executable file", file=sys.stderr)
        return 2
    if args.count < 1 or args.jobs < 1 or args.timeout <= 0:
        print("fuzz_gltf: --count and --jobs must be at least 1, --timeout positive", file=sys.stderr)
        return 2
    seed_paths = find_seeds(args.seeds) if os.path.isdir(args.seeds) else []
    if not seed_paths:
        print(f"fuzz_gltf: no .gltf seed file in {args.seeds}", file=sys.stderr)
        return 2
    seeds, skipped = load_seeds(seed_paths)
    for line in skipped:
        print(f"fuzz_gltf: seed skipped: {line}", file=sys.stderr)
    if not seeds:
        print(f"fuzz_gltf: no usable seed in {args.seeds} (each needs JSON with base64 data-URI buffers)",
              file=sys.stderr)
        return 2
    if args.out:
        out = os.path.abspath(args.out)
        # Mutants of an earlier run would mix with this one's: the folder must be fresh.
        if os.path.exists(out) and (not os.path.isdir(out) or os.listdir(out)):
            print(f"fuzz_gltf: --out {args.out} exists and is not an empty folder", file=sys.stderr)
            return 2
        os.makedirs(out, exist_ok=True)
    else:
        out = tempfile.mkdtemp(prefix="fuzz_gltf-")

    # All mutants first, from one generator in a fixed order: --jobs cannot change them.
    rng = random.Random(args.seed)
    mutants = []
    for n in range(args.count):
        seed_path, seed_doc = rng.choice(seeds)
        data, mutations = make_mutant(seed_doc, rng)
        stem = re.sub(r"[^A-Za-z0-9_-]+", "_", os.path.splitext(os.path.basename(seed_path))[0])
        path = os.path.join(out, f"mutant-{n:04d}-{stem}.gltf")
        with open(path, "wb") as f:
            f.write(data)
        mutants.append({"file": path, "seed": seed_path, "mutations": mutations})

    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = pool.map(lambda mu: run_command([lightcts, "lights", "--scene", mu["file"]], args.timeout),
                           mutants)
        for mu, result in zip(mutants, results):
            mu["lights"] = result
        loaded = [mu for mu in mutants if mu["lights"]["status"] == 0 and not mu["lights"]["timed_out"]]
        rendered = loaded[REFERENCE_EVERY - 1::REFERENCE_EVERY]
        for mu in rendered:
            mu["reference_out"] = os.path.join(out, "reference", os.path.splitext(os.path.basename(mu["file"]))[0])
        results = pool.map(lambda mu: run_command([lightcts, "reference", "--scene", mu["file"],
                                                   "--out", mu["reference_out"]], args.timeout), rendered)
        for mu, result in zip(rendered, results):
            mu["reference"] = result

    violations, notes = [], []
    for mu in mutants:
        name = os.path.basename(mu["file"])
        for command in ("lights", "reference"):
            result = mu.get(command)
            if not result:
                continue
            why = violation(result, name, args.timeout)
            if why:
                violations.append((mu, command, why))
        if mu.get("lights", {}).get("status") == 0:
            try:
                json.loads(mu["lights"]["stdout"])
            except ValueError:
                notes.append(f"{name}: lights exit 0 but its stdout is not JSON (SPEC 5.4)")
        ref = mu.get("reference")
        if ref and ref["status"] == 2:
            notes.append(f"{name}: lights loaded it (exit 0) but reference rejected it (exit 2)")
        if ref and not violation(ref, name, args.timeout):
            # Rendered images of a passing mutant are not needed again; the mutant file stays.
            shutil.rmtree(mu["reference_out"], ignore_errors=True)

    with open(os.path.join(out, "mutants.json"), "w") as f:
        json.dump([{"file": os.path.basename(mu["file"]), "seed": mu["seed"],
                    "mutations": [{"kind": k, "detail": d} for k, d in mu["mutations"]],
                    **{c: {"status": status_label(mu[c]), "seconds": mu[c]["seconds"]}
                       for c in ("lights", "reference") if c in mu}} for mu in mutants], f, indent=1)

    print_summary(args, out, seeds, mutants, rendered, violations, notes, time.monotonic() - started)
    return 1 if violations else 0


def count_labels(results):
    counts = {}
    for r in results:
        label = status_label(r)
        counts[label] = counts.get(label, 0) + 1
    return ", ".join(f"{k}: {v}" for k, v in sorted(counts.items(), key=lambda kv: (not kv[0].isdigit(), kv[0])))


def print_summary(args, out, seeds, mutants, rendered, violations, notes, seconds):
    print(f"fuzz_gltf: {len(mutants)} mutants of {len(seeds)} seed file(s), --seed {args.seed}, "
          f"{seconds:.1f} s with {args.jobs} job(s)")
    print(f"  lightcts: {os.path.abspath(args.lightcts)}")
    print(f"  mutants:  {out} (mutants.json lists each one's mutations and statuses)")
    print(f"lights exit status:    {count_labels([mu['lights'] for mu in mutants])}")
    print(f"reference exit status: {count_labels([mu['reference'] for mu in rendered]) or 'none run'}"
          f" (every {REFERENCE_EVERY}th of {sum(mu['lights']['status'] == 0 for mu in mutants)} loaded)")
    slowest = max((mu[c] for mu in mutants for c in ("lights", "reference") if c in mu), key=lambda r: r["seconds"])
    print(f"slowest command: {slowest['seconds']:.2f} s: {shlex.join(slowest['argv'])}")
    print("mutation kind         mutants  lights exit status")
    for kind in KINDS:
        used = [mu for mu in mutants if any(k == kind for k, _ in mu["mutations"])]
        print(f"  {kind:20} {len(used):7}  {count_labels([mu['lights'] for mu in used])}")
    unmutated = [mu for mu in mutants if not mu["mutations"]]
    if unmutated:
        print(f"  (no kind applied)    {len(unmutated):7}")
    for note in notes:
        print(f"note: {note}")
    print(f"violations: {len(violations)}")
    for mu, command, why in violations:
        result = mu[command]
        print(f"- {why}")
        print(f"  command:   {shlex.join(result['argv'])}")
        print(f"  status:    {status_label(result)} after {result['seconds']:.2f} s")
        print(f"  mutant:    {mu['file']} (from {mu['seed']})")
        print("  mutations: " + "; ".join(f"{k}: {d}" for k, d in mu["mutations"]))
        print("  stderr:    " + (tail(result["stderr"]).replace("\n", "\n             ") or "(empty)"))


if __name__ == "__main__":
    sys.exit(main())
