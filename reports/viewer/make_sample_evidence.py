#!/usr/bin/env python3
"""Writes a synthetic evidence folder for the evidence viewer.

    make_sample_evidence.py TEMPLATE OUT_DIR [--width W] [--height H] [--tolerance-scale S]

OUT_DIR gets:
  viewer.html           a copy of TEMPLATE (reports/viewer/evidence_viewer.html)
  viewer-data.js        the data the viewer reads (README.md in this folder)
  summary.json          the summary, also inside viewer-data.js
  expected-values.json  every pixel's values as JSON numbers, for the probe
                        test to compare against without reading an EXR, and
                        the special pixels below by name (special_pixels)
  result.exr, reference.exr, tolerance.exr
                        the same values as uncompressed float EXRs (result
                        RGBA with A = 1, reference RGBA with A = mask,
                        tolerance RGB), the layout the comparison writes

The images are 37 x 23 by default (not square, odd sizes) and hold what a
viewer has to survive: HDR values above 1, a NaN, +Inf and -Inf in the
result, a masked (don't care) rectangle with a wrong result in it, failing
pixels, tolerances of 0 (one 0 / 0, one x / 0), and tolerances so small that
only nine significant digits tell the values apart. Features sit at the same
fraction of the image at any size. Standard library only.
"""

import argparse
import base64
import json
import math
import os
import shutil
import struct
import sys


def f32(v):
    """v rounded to the nearest float32 (kept as a Python float)."""
    return struct.unpack('<f', struct.pack('<f', v))[0]


def json_number(v):
    # JSON has no NaN or infinity: the comparison's summary writes them as strings.
    if math.isnan(v):
        return 'nan'
    if math.isinf(v):
        return 'inf' if v > 0 else '-inf'
    return v


class Sample:
    def __init__(self, width, height, tolerance_scale):
        self.w, self.h, self.scale = width, height, tolerance_scale
        n = width * height
        self.result = [[0.0] * 3 for _ in range(n)]
        self.reference = [[0.0] * 3 for _ in range(n)]
        self.tolerance = [[0.0] * 3 for _ in range(n)]
        self.mask = [1.0] * n
        self.make()

    def at(self, x, y):
        return y * self.w + x

    def px(self, fx, fy):
        """The pixel at fraction (fx, fy) of a 37 x 23 image, scaled to this size."""
        return (min(self.w - 1, int(fx * self.w / 37)), min(self.h - 1, int(fy * self.h / 23)))

    def make(self):
        w, h = self.w, self.h
        spot = self.px(12, 9)
        for y in range(h):
            for x in range(w):
                i = self.at(x, y)
                # A lit spot over a gentle ramp: HDR up to about 2.5, no two neighbours alike.
                d2 = ((x - spot[0]) * 37 / w) ** 2 + ((y - spot[1]) * 23 / h) ** 2
                light = 0.2 + 3.0 * math.exp(-d2 / 40.0)
                base = (0.8, 0.6, 0.4)
                ramp = (0.05 * x / max(1, w - 1), 0.1 * y / max(1, h - 1), 0.02)
                for c in range(3):
                    ref = f32(base[c] * light + ramp[c] + 0.001 * ((x * 7 + y * 13 + c * 5) % 11))
                    tol = f32(0.004 * ref + 2e-4)
                    # Inside the tolerance: a fixed pattern of at most 45% of it.
                    wobble = ((x * 31 + y * 17 + c * 7) % 19 - 9) / 20.0
                    self.reference[i][c] = ref
                    self.tolerance[i][c] = tol
                    self.result[i][c] = f32(ref + wobble * tol)

        # Tolerances far below the values: only 9 significant digits pin these.
        for y in range(*self.span(2, 6, self.h, 23)):
            for x in range(*self.span(28, 33, self.w, 37)):
                i = self.at(x, y)
                for c in range(3):
                    self.tolerance[i][c] = f32(3.7e-7 + 1e-9 * c)
                    self.result[i][c] = f32(self.reference[i][c] + 0.25 * self.tolerance[i][c])

        def set_pixel(fx, fy, **channels):
            x, y = self.px(fx, fy)
            i = self.at(x, y)
            for name, values in channels.items():
                target = getattr(self, name)
                for c, v in enumerate(values):
                    if v is not None:
                        target[i][c] = f32(v)
            return x, y

        # Pixels a probe test should look at, whatever it picks at random.
        self.special = {}
        self.special['tiny tolerance'] = self.px(30, 3)

        x, y = self.px(34, 3)   # 0 / 0: tolerance 0 and an exact match
        self.special['0 / 0'] = (x, y)
        i = self.at(x, y)
        self.tolerance[i] = [0.0, 0.0, 0.0]
        self.result[i] = list(self.reference[i])
        x, y = self.px(35, 3)   # x / 0: tolerance 0, off by a little in green
        self.special['x / 0'] = (x, y)
        i = self.at(x, y)
        self.tolerance[i] = [0.0, 0.0, 0.0]
        self.result[i] = [self.reference[i][0], f32(self.reference[i][1] + 1e-6), self.reference[i][2]]

        # Failing pixels: off by a few tolerances in one or all channels.
        for fx, fy, factors in ((20, 11, (0, 5, 0)), (21, 11, (-2.5, 0, 0)), (5, 4, (1.7, 1.7, 1.7)),
                                (30, 20, (0, 0, 40))):
            x, y = self.px(fx, fy)
            i = self.at(x, y)
            for c in range(3):
                if factors[c]:
                    self.result[i][c] = f32(self.reference[i][c] + factors[c] * self.tolerance[i][c] * self.scale)

        # Non-finite results: they fail even where masked.
        self.special['NaN'] = set_pixel(10, 2, result=(math.nan, None, None))
        self.special['+Inf'] = set_pixel(25, 17, result=(None, math.inf, None))
        self.special['-Inf'] = set_pixel(26, 17, result=(None, None, -math.inf))
        self.special['failing'] = self.px(20, 11)

        # A don't-care rectangle with a wildly wrong result, and one NaN in it.
        for y in range(*self.span(15, 21, self.h, 23)):
            for x in range(*self.span(2, 8, self.w, 37)):
                i = self.at(x, y)
                self.mask[i] = 0.0
                self.result[i] = [f32(3 * v + 0.5) for v in self.reference[i]]
        self.special['masked'] = self.px(5, 18)
        self.special['NaN where masked'] = set_pixel(3, 16, result=(None, None, math.nan))

    @staticmethod
    def span(a, b, size, base):
        return (min(size - 1, a * size // base), max(min(size, b * size // base), min(size, a * size // base + 1)))

    # -- the comparison's rules (comparison/image_comparison.cpp), restated here
    def compare(self):
        w, h, scale = self.w, self.h, self.scale
        error = [[0.0] * 3 for _ in range(w * h)]
        failing, non_finite, masked = [], 0, 0
        max_abs, tightness, squares, samples = 0.0, 0.0, 0.0, 0
        for y in range(h):
            for x in range(w):
                i = self.at(x, y)
                is_masked = self.mask[i] == 0.0
                masked += is_masked
                bad = any(not math.isfinite(v) for v in self.result[i])
                out_of_tolerance, excess = False, -math.inf
                for c in range(3):
                    diff = abs(self.result[i][c] - self.reference[i][c])
                    bound = self.tolerance[i][c] * scale
                    out_of_tolerance = out_of_tolerance or not (diff <= bound)
                    over = diff - bound
                    excess = math.inf if math.isnan(over) else max(excess, over)
                    if is_masked or bad:
                        continue
                    max_abs = max(max_abs, diff)
                    ratio = diff / bound if bound > 0 else (math.inf if diff > 0 else 0.0)
                    tightness = max(tightness, ratio)
                    squares += diff * diff
                    samples += 1
                if bad:
                    excess = math.inf
                    non_finite += 1
                    error[i] = [1.0, 0.0, 1.0]
                elif is_masked:
                    error[i] = [0.25, 0.25, 0.25]
                elif out_of_tolerance:
                    error[i] = [1.0, 0.0, 0.0]
                if bad or (not is_masked and out_of_tolerance):
                    failing.append((excess, x, y, bad))
        # Largest excess first; ties by row, then column.
        failing.sort(key=lambda f: (-f[0], f[2], f[1]))
        worst = []
        for excess, x, y, bad in failing[:10]:
            i = self.at(x, y)
            worst.append({
                'x': x, 'y': y,
                'result': [json_number(v) for v in self.result[i]],
                'reference': [json_number(v) for v in self.reference[i]],
                'tolerance': [json_number(v) for v in self.tolerance[i]],
                'allowed': [[json_number(self.reference[i][c] - self.tolerance[i][c] * scale),
                             json_number(self.reference[i][c] + self.tolerance[i][c] * scale)] for c in range(3)],
                'excess': json_number(excess),
                'non_finite': bad,
                'shadow_interval': None,
            })
        compared = w * h - masked
        passed = len(failing) == 0 and non_finite == 0
        summary = {
            'test': 'sample.viewer-self-check.synthetic',
            'verdict': 'PASS' if passed else 'FAIL',
            'comparison_passed': passed,
            'expect_fail': False,
            'width': w, 'height': h,
            'compared_pixels': compared,
            'masked_pixels': masked,
            'failing_pixels': len(failing),
            'non_finite_pixels': non_finite,
            'max_failing_pixels': 0,
            'tolerance_scale': json_number(scale),
            'max_abs_error': json_number(max_abs),
            'max_error_over_tolerance': json_number(tightness),
            'rmse': json_number(math.sqrt(squares / samples) if samples else 0.0),
            'shadowed_pixels': 0,
            'ambiguous_shadow_pixels': 0,
            'defective_scene': False,
            'worst': worst,
        }
        return error, summary


def base64_floats(rows, channels):
    flat = [v for row in rows for v in (row[:channels] if isinstance(row, list) else [row])]
    return base64.b64encode(struct.pack('<%df' % len(flat), *flat)).decode('ascii')


def write_exr(path, width, height, channels):
    """An uncompressed, scanline, single-part float EXR (OpenEXR's file layout).

    `channels` maps a channel name to its width * height values, row 0 at the top.
    """
    names = sorted(channels)   # the file stores channels in name order

    def attribute(name, kind, value):
        return name.encode() + b'\0' + kind.encode() + b'\0' + struct.pack('<i', len(value)) + value

    chlist = b''.join(n.encode() + b'\0' + struct.pack('<iB3xii', 2, 0, 1, 1) for n in names) + b'\0'
    box = struct.pack('<iiii', 0, 0, width - 1, height - 1)
    header = (struct.pack('<ii', 20000630, 2)
              + attribute('channels', 'chlist', chlist)
              + attribute('compression', 'compression', b'\0')
              + attribute('dataWindow', 'box2i', box)
              + attribute('displayWindow', 'box2i', box)
              + attribute('lineOrder', 'lineOrder', b'\0')
              + attribute('pixelAspectRatio', 'float', struct.pack('<f', 1.0))
              + attribute('screenWindowCenter', 'v2f', struct.pack('<ff', 0.0, 0.0))
              + attribute('screenWindowWidth', 'float', struct.pack('<f', 1.0))
              + b'\0')
    line_bytes = width * 4 * len(names)
    first = len(header) + 8 * height
    offsets = b''.join(struct.pack('<Q', first + y * (8 + line_bytes)) for y in range(height))
    lines = []
    for y in range(height):
        data = b''.join(struct.pack('<%df' % width, *channels[n][y * width:(y + 1) * width]) for n in names)
        lines.append(struct.pack('<ii', y, len(data)) + data)
    with open(path, 'wb') as out:
        out.write(header + offsets + b''.join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('template', help='reports/viewer/evidence_viewer.html')
    parser.add_argument('out_dir')
    parser.add_argument('--width', type=int, default=37)
    parser.add_argument('--height', type=int, default=23)
    parser.add_argument('--tolerance-scale', type=float, default=1.0)
    args = parser.parse_args()
    if args.width < 8 or args.height < 8:
        parser.error('the sample needs at least 8 x 8 pixels')

    sample = Sample(args.width, args.height, args.tolerance_scale)
    error, summary = sample.compare()
    os.makedirs(args.out_dir, exist_ok=True)
    shutil.copyfile(args.template, os.path.join(args.out_dir, 'viewer.html'))

    data = {
        'test': summary['test'],
        'width': sample.w, 'height': sample.h,
        'tolerance_scale': sample.scale,
        'images': {
            'result': {'channels': 3, 'data': base64_floats(sample.result, 3)},
            'reference': {'channels': 3, 'data': base64_floats(sample.reference, 3)},
            'tolerance': {'channels': 3, 'data': base64_floats(sample.tolerance, 3)},
            'mask': {'channels': 1, 'data': base64_floats(sample.mask, 1)},
            'error': {'channels': 3, 'data': base64_floats(error, 3)},
        },
        'summary': summary,
    }
    with open(os.path.join(args.out_dir, 'viewer-data.js'), 'w') as out:
        out.write('window.LIGHTCTS_EVIDENCE = ' + json.dumps(data, allow_nan=False) + ';\n')
    with open(os.path.join(args.out_dir, 'summary.json'), 'w') as out:
        json.dump(summary, out, indent=2, allow_nan=False)
        out.write('\n')

    # repr of a float32 held in a double reads back as that exact float32.
    pixels = []
    for y in range(sample.h):
        for x in range(sample.w):
            i = sample.at(x, y)
            pixels.append({'x': x, 'y': y,
                           'result': [json_number(v) for v in sample.result[i]],
                           'reference': [json_number(v) for v in sample.reference[i]],
                           'tolerance': [json_number(v) for v in sample.tolerance[i]],
                           'mask': sample.mask[i]})
    with open(os.path.join(args.out_dir, 'expected-values.json'), 'w') as out:
        json.dump({'width': sample.w, 'height': sample.h, 'tolerance_scale': sample.scale,
                   'special_pixels': [{'x': x, 'y': y, 'what': what} for what, (x, y) in sample.special.items()],
                   'pixels': pixels}, out, allow_nan=False, separators=(',', ':'))
        out.write('\n')

    def plane(rows, c):
        return [row[c] for row in rows]
    ones = [1.0] * (sample.w * sample.h)
    write_exr(os.path.join(args.out_dir, 'result.exr'), sample.w, sample.h,
              {'R': plane(sample.result, 0), 'G': plane(sample.result, 1), 'B': plane(sample.result, 2), 'A': ones})
    write_exr(os.path.join(args.out_dir, 'reference.exr'), sample.w, sample.h,
              {'R': plane(sample.reference, 0), 'G': plane(sample.reference, 1), 'B': plane(sample.reference, 2),
               'A': list(sample.mask)})
    write_exr(os.path.join(args.out_dir, 'tolerance.exr'), sample.w, sample.h,
              {'R': plane(sample.tolerance, 0), 'G': plane(sample.tolerance, 1), 'B': plane(sample.tolerance, 2)})

    print('wrote %s: %d x %d, %d failing of %d compared pixels, %d masked, %d non-finite' % (
        args.out_dir, sample.w, sample.h, summary['failing_pixels'], summary['compared_pixels'],
        summary['masked_pixels'], summary['non_finite_pixels']))
    return 0


if __name__ == '__main__':
    sys.exit(main())
