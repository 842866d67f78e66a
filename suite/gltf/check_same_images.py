#!/usr/bin/python3
"""Whether two EXR images hold the same pixels, bit for bit.

Usage: check_same_images.py A.exr B.exr [A2.exr B2.exr ...]
Compares each pair's size, channels and every float's bits (NaN included),
read with OpenImageIO's Python module; the file headers may differ (a
scene's name is not a pixel). Exit 0 when every pair is identical, 1 with the
first differing pixels listed, 2 on bad usage or an unreadable file.
"""
import sys

import numpy as np
import OpenImageIO as oiio


def read(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        print(f"cannot read {path}: {oiio.geterror()}")
        sys.exit(2)
    spec = image.spec()
    pixels = image.read_image(oiio.FLOAT)
    image.close()
    return spec, np.ascontiguousarray(pixels, dtype=np.float32)


def main():
    paths = sys.argv[1:]
    if not paths or len(paths) % 2:
        print(__doc__)
        return 2
    different = 0
    for a, b in zip(paths[0::2], paths[1::2]):
        spec_a, pixels_a = read(a)
        spec_b, pixels_b = read(b)
        if pixels_a.shape != pixels_b.shape or spec_a.channelnames != spec_b.channelnames:
            print(f"DIFFERENT {a} {b}: {pixels_a.shape} {spec_a.channelnames} against {pixels_b.shape} {spec_b.channelnames}")
            different += 1
            continue
        bits_a, bits_b = pixels_a.view(np.uint32), pixels_b.view(np.uint32)
        where = np.argwhere(bits_a != bits_b)
        if len(where):
            different += 1
            print(f"DIFFERENT {a} {b}: {len(where)} of {bits_a.size} values")
            for y, x, c in where[:10]:
                print(f"  pixel ({x}, {y}) channel {c}: {pixels_a[y, x, c]!r} against {pixels_b[y, x, c]!r}")
        else:
            print(f"same {a} {b}: {pixels_a.shape[1]}x{pixels_a.shape[0]}x{pixels_a.shape[2]}, every bit")
    return 1 if different else 0


if __name__ == "__main__":
    sys.exit(main())
