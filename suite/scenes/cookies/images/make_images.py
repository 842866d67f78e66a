#!/usr/bin/env python3
"""Writes every cookie image of suite/scenes/cookies (README.md beside this file).

Python 3 standard library only (zlib, struct): 8-bit PNGs of colour type 0
(grey), 2 (RGB) or 6 (RGBA), no gamma, sRGB or other ancillary chunks, so the
loader reads each level n as n / 255 (SPEC 3.10). Deterministic: the same
bytes on every run (filter 0 on every row, zlib level 9).

    python3 suite/scenes/cookies/images/make_images.py
"""

import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

GREY, RGB, RGBA = 0, 2, 6
CHANNELS = {GREY: 1, RGB: 3, RGBA: 4}


def level(x):
    """A value in [0, 1] as an 8-bit level."""
    return max(0, min(255, int(round(x * 255.0))))


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def write_png(name, width, height, colour_type, texel):
    """texel(i, j) -> tuple of CHANNELS[colour_type] values in [0, 1];
    i is the column (u), j the row (v), row 0 first (v = 0)."""
    channels = CHANNELS[colour_type]
    raw = bytearray()
    for j in range(height):
        raw.append(0)  # filter type 0 (None)
        for i in range(width):
            values = texel(i, j)
            assert len(values) == channels, name
            raw.extend(level(v) for v in values)
    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9))
    png += chunk(b"IEND", b"")
    path = os.path.join(HERE, name)
    with open(path, "wb") as out:
        out.write(png)
    return path


# --- tile-arrow.png: the directional cookie, tiled ------------------------
# 8 x 8 grey. A ramp along v (0.2 at row 0 to 0.55 at row 7) under a bright
# arrow whose head points to v = 1 and whose shaft sits left of centre.
# Clamped to edge (one tile, then its border texels), the floor outside the
# tile at the origin takes the border rows and columns as long streaks; a v
# flip turns every arrow round and reverses the ramp.
ARROW = [
    "........",
    "..#.....",
    "..#.....",
    "..#.....",
    "..#.....",
    "#####...",
    ".###....",
    "..#.....",
]


def tile_arrow(i, j):
    if ARROW[j][i] == "#":
        return (1.0,)
    return (0.2 + 0.05 * j,)


# --- spot-bands.png: the spot cookie, clamp to edge -------------------------
# 16 x 16 grey, made for a 160-degree cone seen on the floor below a low
# spot: the floor takes the lower half (v < 0.5, rows 0-7), spread wide in
# u, so that half carries bands of unequal widths and levels along u (no
# mirror symmetry), dimmer in rows 0-2 (the cone's rim behind the light's
# foot). The upper half (rows 8-15) is a dim ramp in u with one bright bar,
# so a v flip shows the floor the upper half's values instead.
SPOT_BANDS = [0.9, 0.9, 0.9, 0.9, 0.3, 0.3, 0.75, 0.75, 0.75, 0.75, 0.2, 0.2, 0.55, 0.55, 0.55, 0.55]


def spot_bands(i, j):
    if j < 3:
        return (0.6 * SPOT_BANDS[i],)
    if j < 8:
        return (SPOT_BANDS[i],)
    if j in (11, 12) and i < 10:
        return (1.0,)
    return (0.15 + 0.02 * i,)


# --- cube-{px,nx,py,ny,pz,nz}.png: the point cookie ------------------------
# Six 8 x 8 grey faces. Each is a plane base + a*s + b*t (s, t in [0, 1]
# across the face) with a != b and both non-zero, so no face equals any of
# its own rotations or flips, plus a dark 2 x 2 notch in a corner of its own.
# The bases differ by face, so every seam is a visible step; a cube turned
# 90 degrees about y moves the side faces round and turns the +-Y faces'
# ramps and notches.
CUBE_FACES = [
    # name, base, a (along s), b (along t), notch corner (i0, j0)
    ("cube-px.png", 0.55, 0.30, -0.15, (1, 1)),
    ("cube-nx.png", 0.25, 0.10, 0.35, (5, 1)),
    ("cube-py.png", 0.70, -0.20, 0.10, (1, 5)),
    ("cube-ny.png", 0.40, 0.45, 0.15, (5, 5)),
    ("cube-pz.png", 0.85, -0.10, -0.30, (1, 3)),
    ("cube-nz.png", 0.15, 0.20, 0.50, (4, 1)),
]


def cube_face(base, a, b, notch):
    def texel(i, j):
        if notch[0] <= i < notch[0] + 2 and notch[1] <= j < notch[1] + 2:
            return (0.05,)
        s, t = i / 7.0, j / 7.0
        return (base + a * s + b * t,)
    return texel


# --- alpha-rings.png: RGBA, the value is alpha -----------------------------
# 16 x 16. Alpha: bands along v (0.25 / 0.9 alternating, four rows each)
# with a bright bar along u in the top-left corner rows; red = 1 - alpha, so
# taking red instead of alpha inverts the pattern. Green and blue are
# constant 0.5 and 0.2, so taking any colour channel is caught too.
def alpha_rings(i, j):
    alpha = 0.9 if (j // 4) % 2 == 0 else 0.25
    if j < 3 and i < 6:
        alpha = 0.55
    alpha += 0.005 * i  # a slight ramp in u: asymmetric in u as well
    return (1.0 - alpha, 0.5, 0.2, alpha)


# --- no-alpha-rgb.png: RGB, the value is red ------------------------------
# 16 x 16. Red: a ramp along v from 0.15 to 0.95 with a dark square at
# (3..6, 10..13); green = 1 - red, blue a ramp along u, so taking green,
# blue or the luminance instead of the first channel is caught.
def no_alpha_rgb(i, j):
    red = 0.15 + 0.8 * j / 15.0
    if 3 <= i <= 6 and 10 <= j <= 13:
        red = 0.1
    return (red, 1.0 - red, i / 15.0)


# --- one-spot.png: the one cookie in one-of-several-lights -----------------
# 16 x 16 grey: a diagonal ramp (0.2 to 1.0) cut by a dark cross off centre.
def one_spot(i, j):
    if i == 5 or j == 9:
        return (0.1,)
    return (0.2 + 0.8 * (0.7 * i + 0.3 * j) / 15.0,)


def main():
    written = [
        write_png("tile-arrow.png", 8, 8, GREY, tile_arrow),
        write_png("spot-bands.png", 16, 16, GREY, spot_bands),
        write_png("alpha-rings.png", 16, 16, RGBA, alpha_rings),
        write_png("no-alpha-rgb.png", 16, 16, RGB, no_alpha_rgb),
        write_png("one-spot.png", 16, 16, GREY, one_spot),
    ]
    for name, base, a, b, notch in CUBE_FACES:
        written.append(write_png(name, 8, 8, GREY, cube_face(base, a, b, notch)))
    for path in written:
        print(os.path.relpath(path))


if __name__ == "__main__":
    main()
