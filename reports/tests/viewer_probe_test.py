#!/usr/bin/env python3
"""Drives the evidence viewer (viewer.html) in headless Chromium and checks
what a reader would see: the keys switch layers, the swipe line follows a
drag, zooming works, and the pixel probe shows each pixel's float values as
the EXR files hold them.

    viewer_probe_test.py [--no-network] [--expected-json FILE] EVIDENCE_DIR [EVIDENCE_DIR...]
    viewer_probe_test.py --sample TEMPLATE [--no-network]
    viewer_probe_test.py --report RUN/report/index.html [--no-network]

Each EVIDENCE_DIR holds viewer.html, viewer-data.js and result.exr,
reference.exr (A = mask) and tolerance.exr.

The expected values come by a path independent of the page: the EXR files
read with OpenImageIO's Python module (Debian's python3-openimageio, which
gives every float32 exactly), else `oiiotool --dumpdata` on them, and/or an
expected-values.json (written by reports/viewer/make_sample_evidence.py)
given with --expected-json. oiiotool prints values with 9 decimals (`{:.9f}`), which pins a float32 exactly only
from about 0.016 up; below that a probe value must lie within half a unit of
the last printed digit, and the ratio within the interval those values allow.
The JSON holds every float32 exactly, so there every value must be equal.

--no-network: as well as the probe's checks, in the same browser: Chromium's
Network domain records every request while the page loads and is used; each
must be file:// (or data:/blob:). The browser runs with every network access
failing, and the probe must still show values. The page's source is checked
for URLs as well. Where nothing independent gives the expected values, the
network checks run alone (a note says so).

--sample TEMPLATE: writes two synthetic evidence folders with
make_sample_evidence.py (beside TEMPLATE) into a temporary folder (37 x 23,
and 64 x 48 with a tolerance scale of 1.5) and checks those, each with its
JSON (and with oiiotool on its EXRs, where oiiotool is installed).

The browser is driven over the DevTools protocol on a pipe
(--remote-debugging-pipe: commands on its fd 3, replies on its fd 4, each a
JSON text ended by a NUL byte), standard library only.

Exit: 0 every check passed; 1 a check failed, or the test could not run;
2 usage; 77 chromium (or every source of expected values) is missing: a
ctest skip, never a pass.
"""

import argparse
import base64
import fcntl
import html.parser
import json
import math
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib
from decimal import Decimal
import urllib.parse
from urllib.parse import quote

SKIP = 77
OVERALL_TIMEOUT_S = 60     # for the first folder; each further one adds PER_FOLDER_S
PER_FOLDER_S = 30
COMMAND_TIMEOUT_S = 20
WINDOW = (1400, 900)
ZOOM_FOR_PROBING = 16      # screen pixels per image pixel while hovering pixels
RANDOM_SEED = 20240607     # fixed: a failure names pixels that fail again


class Fatal(Exception):
    """The test cannot go on (no page, no reply); reported as a failure."""


# ---------------------------------------------------------------- reporting
class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what, detail=''):
        if ok:
            self.passed += 1
            print('PASS: %s' % what, flush=True)
        else:
            self.failed += 1
            print('FAIL: %s%s' % (what, (': ' + detail) if detail else ''), flush=True)
        return ok

    def note(self, text):
        print('      %s' % text, flush=True)


# ---------------------------------------------------------------- chromium
def find_chromium():
    for name in ('chromium', 'chromium-browser'):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One Chromium, driven over --remote-debugging-pipe."""

    def __init__(self, chromium, extra_flags):
        self.profile = tempfile.mkdtemp(prefix='lightcts-viewer-probe-')
        self.log_path = os.path.join(self.profile, 'chromium.log')
        self.next_id = 0
        self.replies = {}
        self.events = []
        self.lock = threading.Condition()
        self.closed = False

        # Parent writes commands into to_child, reads replies from from_child.
        child_in, self.to_child = os.pipe()
        self.from_child, child_out = os.pipe()
        # Above 10, so that moving them to 3 and 4 in the child can't clobber either.
        high_in = fcntl.fcntl(child_in, fcntl.F_DUPFD, 10)
        high_out = fcntl.fcntl(child_out, fcntl.F_DUPFD, 10)
        os.close(child_in)
        os.close(child_out)

        def to_fds_3_and_4():
            os.dup2(high_in, 3)
            os.dup2(high_out, 4)

        flags = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage',
                 '--no-first-run', '--no-default-browser-check', '--disable-extensions',
                 '--disable-background-networking', '--disable-component-update', '--disable-sync',
                 '--force-device-scale-factor=1', '--hide-scrollbars',
                 '--window-size=%d,%d' % WINDOW, '--user-data-dir=' + self.profile,
                 '--remote-debugging-pipe'] + extra_flags + ['about:blank']
        self.log = open(self.log_path, 'wb')
        # Its own session: the whole process group (renderers, GPU process) goes at close.
        self.process = subprocess.Popen([chromium] + flags, stdin=subprocess.DEVNULL, stdout=self.log,
                                        stderr=subprocess.STDOUT, pass_fds=(3, 4),
                                        preexec_fn=to_fds_3_and_4, start_new_session=True)
        os.close(high_in)
        os.close(high_out)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        buffer = b''
        while True:
            try:
                chunk = os.read(self.from_child, 1 << 16)
            except OSError:
                chunk = b''
            if not chunk:
                with self.lock:
                    self.closed = True
                    self.lock.notify_all()
                return
            buffer += chunk
            while b'\0' in buffer:
                message, buffer = buffer.split(b'\0', 1)
                try:
                    parsed = json.loads(message.decode('utf-8'))
                except ValueError:
                    continue
                with self.lock:
                    if 'id' in parsed:
                        self.replies[parsed['id']] = parsed
                    else:
                        self.events.append(parsed)
                    self.lock.notify_all()

    def send(self, method, params=None, session=None, timeout=COMMAND_TIMEOUT_S):
        with self.lock:
            self.next_id += 1
            command_id = self.next_id
        message = {'id': command_id, 'method': method, 'params': params or {}}
        if session:
            message['sessionId'] = session
        data = json.dumps(message).encode('utf-8') + b'\0'
        try:
            while data:
                data = data[os.write(self.to_child, data):]
        except OSError as e:
            raise Fatal('cannot send %s to chromium: %s' % (method, e))
        deadline = time.monotonic() + timeout
        with self.lock:
            while command_id not in self.replies:
                left = deadline - time.monotonic()
                if self.closed:
                    raise Fatal('chromium closed the pipe while waiting for %s' % method)
                if left <= 0:
                    raise Fatal('no reply to %s within %d s' % (method, timeout))
                self.lock.wait(left)
            reply = self.replies.pop(command_id)
        if 'error' in reply:
            raise Fatal('%s failed: %s' % (method, reply['error'].get('message', reply['error'])))
        return reply.get('result', {})

    def wait_event(self, method, session, start, timeout=COMMAND_TIMEOUT_S):
        """The first event `method` of `session` at index >= start of the event list."""
        deadline = time.monotonic() + timeout
        with self.lock:
            while True:
                for event in self.events[start:]:
                    if event.get('method') == method and event.get('sessionId') == session:
                        return event
                left = deadline - time.monotonic()
                if self.closed:
                    raise Fatal('chromium closed the pipe while waiting for %s' % method)
                if left <= 0:
                    raise Fatal('no %s within %d s' % (method, timeout))
                self.lock.wait(left)

    def event_count(self):
        with self.lock:
            return len(self.events)

    def events_since(self, start):
        with self.lock:
            return list(self.events[start:])

    def log_tail(self, lines=15):
        try:
            with open(self.log_path, 'rb') as f:
                text = f.read().decode('utf-8', 'replace')
        except OSError:
            return ''
        return '\n'.join(text.splitlines()[-lines:])

    def close(self):
        try:
            if self.process.poll() is None:
                try:
                    self.send('Browser.close', timeout=5)
                except Fatal:
                    pass
                try:
                    self.process.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    pass
        finally:
            kill_group(self.process)
            for fd in (self.to_child, self.from_child):
                try:
                    os.close(fd)
                except OSError:
                    pass
            self.log.close()
            shutil.rmtree(self.profile, ignore_errors=True)


def kill_group(process):
    """Chromium's process group (it leads it: start_new_session), by its id."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        pass


# ---------------------------------------------------------------- one page
KEYS = {
    # name: (key, code, Windows virtual key code, text, shift)
    '1': ('1', 'Digit1', 49, '1', False), '2': ('2', 'Digit2', 50, '2', False),
    '3': ('3', 'Digit3', 51, '3', False), '4': ('4', 'Digit4', 52, '4', False),
    'Tab': ('Tab', 'Tab', 9, '', False), 'Space': (' ', 'Space', 32, ' ', False),
    's': ('s', 'KeyS', 83, 's', False), 'c': ('c', 'KeyC', 67, 'c', False),
    'm': ('m', 'KeyM', 77, 'm', False), 'e': ('e', 'KeyE', 69, 'e', False),
    'E': ('E', 'KeyE', 69, 'E', True), 'f': ('f', 'KeyF', 70, 'f', False),
    '0': ('0', 'Digit0', 48, '0', False), '+': ('+', 'Equal', 187, '+', True),
    '-': ('-', 'Minus', 189, '-', False), 'n': ('n', 'KeyN', 78, 'n', False),
    'Shift+2': ('@', 'Digit2', 50, '@', True),
}


class Page:
    def __init__(self, browser, network=False):
        self.browser = browser
        target = browser.send('Target.createTarget', {'url': 'about:blank'})['targetId']
        self.session = browser.send('Target.attachToTarget', {'targetId': target, 'flatten': True})['sessionId']
        self.target = target
        self.network_start = None
        self.events_start = browser.event_count()
        self.send('Page.enable')
        self.send('Runtime.enable')
        if network:
            self.network_start = browser.event_count()
            self.send('Network.enable')
        self.send('Emulation.setDeviceMetricsOverride',
                  {'width': WINDOW[0], 'height': WINDOW[1], 'deviceScaleFactor': 1, 'mobile': False})

    def send(self, method, params=None, timeout=COMMAND_TIMEOUT_S):
        return self.browser.send(method, params, self.session, timeout)

    def script_errors(self):
        """Uncaught exceptions in the page since it opened (NaN and infinity must not throw)."""
        errors = []
        for event in self.browser.events_since(self.events_start):
            if event.get('sessionId') == self.session and event.get('method') == 'Runtime.exceptionThrown':
                details = event['params']['exceptionDetails']
                errors.append(details.get('exception', {}).get('description') or details.get('text', '?'))
        return errors

    def close(self):
        try:
            self.browser.send('Target.closeTarget', {'targetId': self.target})
        except Fatal:
            pass

    def navigate(self, url):
        start = self.browser.event_count()
        reply = self.send('Page.navigate', {'url': url})
        if reply.get('errorText'):
            raise Fatal('cannot open %s: %s' % (url, reply['errorText']))
        self.browser.wait_event('Page.loadEventFired', self.session, start)

    def evaluate(self, expression):
        reply = self.send('Runtime.evaluate', {'expression': expression, 'returnByValue': True})
        if 'exceptionDetails' in reply:
            details = reply['exceptionDetails']
            text = details.get('exception', {}).get('description') or details.get('text')
            raise Fatal('page script failed: %s: %s' % (expression[:80], text))
        return reply.get('result', {}).get('value')

    def state(self):
        return json.loads(self.evaluate('JSON.stringify(Object.assign({}, document.body.dataset))'))

    def key(self, name):
        key, code, vk, text, shift = KEYS[name]
        params = {'key': key, 'code': code, 'windowsVirtualKeyCode': vk, 'nativeVirtualKeyCode': vk,
                  'modifiers': 8 if shift else 0}
        if text:
            params.update(type='keyDown', text=text, unmodifiedText=text)
        else:
            params.update(type='rawKeyDown')
        self.send('Input.dispatchKeyEvent', params)
        self.send('Input.dispatchKeyEvent', {'type': 'keyUp', 'key': key, 'code': code,
                                             'windowsVirtualKeyCode': vk, 'nativeVirtualKeyCode': vk,
                                             'modifiers': 8 if shift else 0})

    def mouse(self, kind, x, y, pressed=False, **extra):
        params = {'type': kind, 'x': x, 'y': y, 'button': 'left' if (pressed or kind != 'mouseMoved') else 'none',
                  'buttons': 1 if pressed else 0, 'modifiers': 0}
        if kind in ('mousePressed', 'mouseReleased'):
            params['clickCount'] = 1
        params.update(extra)
        self.send('Input.dispatchMouseEvent', params)

    def drag(self, x0, y0, x1, y1, steps=8):
        self.mouse('mouseMoved', x0, y0)
        self.mouse('mousePressed', x0, y0, pressed=True)
        for i in range(1, steps + 1):
            t = i / steps
            self.mouse('mouseMoved', x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, pressed=True)
        self.mouse('mouseReleased', x1, y1)

    def click(self, x, y):
        self.mouse('mouseMoved', x, y)
        self.mouse('mousePressed', x, y, pressed=True)
        self.mouse('mouseReleased', x, y)

    def screen_of(self, x, y):
        p = self.evaluate('window.lightctsViewer.screenOf(%d, %d)' % (x, y))
        return p['x'], p['y']

    def view_rect(self):
        return self.evaluate('window.lightctsViewer.viewRect()')

    def screenshot(self, x, y, width, height):
        reply = self.send('Page.captureScreenshot', {
            'format': 'png', 'clip': {'x': x, 'y': y, 'width': width, 'height': height, 'scale': 1}})
        return decode_png(base64.b64decode(reply['data']))


# ---------------------------------------------------------------- numbers
def f32(v):
    return struct.unpack('<f', struct.pack('<f', v))[0]


def parse_probe(text):
    """A probe field's text as a float: Python reads "NaN", "Infinity", "-Infinity" too."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def close_relative(a, b, rel):
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    if math.isinf(a) or math.isinf(b):
        return a == b
    return abs(a - b) <= rel * max(abs(a), abs(b)) or a == b


def ratio_rule(diff, bound):
    """SPEC 7's tightness rule (0/0 is 0, x/0 is infinite); NaN anywhere stays NaN."""
    if math.isnan(diff) or math.isnan(bound):
        return math.nan
    if bound > 0:
        return diff / bound
    return math.inf if diff > 0 else 0.0


class Expected:
    """What an independent source knows of one channel value: exactly a float32,
    or only an interval (a decimal printed with few digits), or a non-finite kind."""

    def __init__(self, exact=None, lo=None, hi=None, text=None, nonfinite=None):
        self.exact, self.lo, self.hi, self.text, self.nonfinite = exact, lo, hi, text, nonfinite

    @staticmethod
    def from_json(v):
        if isinstance(v, str):
            return Expected(nonfinite={'nan': 'nan', 'inf': '+inf', '-inf': '-inf'}[v], text=v)
        return Expected(exact=f32(float(v)), text=repr(v))

    @staticmethod
    def from_dump(text):
        t = text.strip().lower()
        if t in ('nan', '-nan'):
            return Expected(nonfinite='nan', text=text)
        if t in ('inf', '+inf', '-inf'):
            # oiiotool prints "inf" for either sign.
            return Expected(nonfinite='-inf' if t == '-inf' else 'inf', text=text)
        d = Decimal(text)
        half = Decimal(1).scaleb(d.as_tuple().exponent) / 2
        lo, hi = d - half, d + half
        # The interval pins one float32 when rounding both ends gives the same one.
        a, b = f32(float(lo)), f32(float(hi))
        if a == b and Decimal(a) >= lo and Decimal(a) <= hi:
            return Expected(exact=a, text=text)
        return Expected(lo=lo, hi=hi, text=text)

    def interval(self, scale):
        """(lo, hi) as floats, times scale; None when non-finite."""
        if self.nonfinite:
            return None
        if self.exact is not None:
            v = self.exact * scale
            return v, v
        a, b = float(self.lo) * scale, float(self.hi) * scale
        return min(a, b), max(a, b)

    def matches(self, probe, scale=1.0):
        """Does the probe's number (parsed) show this value, times scale?"""
        if self.nonfinite == 'nan':
            return math.isnan(probe)
        if self.nonfinite == 'inf':
            return math.isinf(probe)
        if self.nonfinite == '+inf':
            return probe == math.inf
        if self.nonfinite == '-inf':
            return probe == -math.inf
        if not math.isfinite(probe):
            return False
        if scale == 1.0:
            # The page prints 9 significant digits: enough to name its float32.
            p = f32(probe)
            if self.exact is not None:
                return p == self.exact
            return self.lo <= Decimal(p) <= self.hi
        # A scaled tolerance is a double, shown to 9 significant digits.
        lo, hi = self.interval(scale)
        slack = 1e-8 * max(abs(lo), abs(hi))
        return lo - slack <= probe <= hi + slack

    def describe(self, scale=1.0):
        if self.nonfinite:
            return self.text
        if self.exact is not None:
            return '%r%s' % (self.exact, '' if scale == 1.0 else ' x %r' % scale)
        return '%s (+-half a digit)%s' % (self.text, '' if scale == 1.0 else ' x %r' % scale)


def abs_difference_interval(a, b):
    lo, hi = a[0] - b[1], a[1] - b[0]
    if lo <= 0 <= hi:
        return 0.0, max(-lo, hi)
    return min(abs(lo), abs(hi)), max(abs(lo), abs(hi))


def ratio_interval(d, t):
    """The ratios |diff| / tolerance allows when |diff| lies in d and the tolerance in t."""
    if t[0] > 0:
        return d[0] / t[1], d[1] / t[0]
    if t[1] <= 0:   # a tolerance of exactly 0 (or below)
        if d[1] == 0:
            return 0.0, 0.0
        if d[0] > 0:
            return math.inf, math.inf
        return 0.0, math.inf
    return (d[0] / t[1] if d[0] > 0 else 0.0), math.inf


def in_interval(v, interval, rel=1e-6):
    lo, hi = interval
    if math.isnan(v):
        return False
    return lo - rel * abs(lo) <= v <= hi + rel * abs(hi) or (math.isinf(v) and v == hi)


# ---------------------------------------------------------------- sources of expected values
class JsonSource:
    name = 'expected-values.json'

    def __init__(self, path):
        with open(path) as f:
            data = json.load(f)
        self.width, self.height = data['width'], data['height']
        self.scale = data.get('tolerance_scale')
        self.pixels = {(p['x'], p['y']): p for p in data['pixels']}
        self.special = [((p['x'], p['y']), p['what']) for p in data.get('special_pixels', [])]

    def prepare(self):
        pass

    def load(self, wanted):
        pass

    def values(self, x, y):
        p = self.pixels[(x, y)]
        return {'result': [Expected.from_json(v) for v in p['result']],
                'reference': [Expected.from_json(v) for v in p['reference']],
                'tolerance': [Expected.from_json(v) for v in p['tolerance']],
                'mask': Expected.from_json(p['mask'])}


class OiiotoolSource:
    """`oiiotool --dumpdata FILE`: "    Pixel (x, y): v v v v", values "{:.9f}", "nan", "inf".

    Each file is dumped once into `scratch` and read twice: first for pixels
    worth probing in any evidence (masked, zero tolerance, NaN, infinity),
    then for the values of the pixels chosen."""
    name = 'oiiotool --dumpdata'
    PIXEL = re.compile(r'^\s*Pixel \((-?\d+), (-?\d+)\):\s*(.*)$')

    def __init__(self, oiiotool, folder, scratch):
        self.oiiotool, self.folder, self.scratch = oiiotool, folder, scratch
        self.data = {}
        self.channels = {}
        self.special = []

    def channel_names(self, path):
        out = subprocess.run([self.oiiotool, '--info', '-v', path], capture_output=True, text=True, timeout=60)
        match = re.search(r'channel list:\s*(.*)', out.stdout)
        return [c.strip() for c in match.group(1).split(',')] if match else None

    def dump_path(self, name):
        return os.path.join(self.scratch, name + '.dump')

    def pixels(self, name):
        with open(self.dump_path(name)) as f:
            for line in f:
                m = self.PIXEL.match(line)
                if m:
                    yield (int(m.group(1)), int(m.group(2))), m.group(3).split()

    def prepare(self):
        os.makedirs(self.scratch, exist_ok=True)
        for name in ('result', 'reference', 'tolerance'):
            path = os.path.join(self.folder, name + '.exr')
            self.channels[name] = self.channel_names(path)
            with open(self.dump_path(name), 'w') as out:
                done = subprocess.run([self.oiiotool, '--dumpdata', path], stdout=out, stderr=subprocess.PIPE,
                                      text=True, timeout=60)
            if done.returncode != 0:
                raise Fatal('oiiotool --dumpdata %s failed: %s' % (path, done.stderr.strip()))
        def rgb(name, values):
            return [float(self.pick(name, values, c)) for c in 'RGB']
        wanted = {
            'result': [('NaN in the result', lambda v: any(math.isnan(t) for t in rgb('result', v))),
                       ('infinity in the result', lambda v: any(math.isinf(t) for t in rgb('result', v)))],
            'reference': [('masked (mask 0)', lambda v: float(self.pick('reference', v, 'A')) == 0)],
            'tolerance': [('tolerance printed as 0', lambda v: any(t == 0 for t in rgb('tolerance', v)))],
        }
        for name, tests in wanted.items():
            left = list(tests)
            for where, values in self.pixels(name):
                for test in list(left):
                    if test[1](values):
                        self.special.append((where, test[0]))
                        left.remove(test)
                if not left:
                    break

    def load(self, wanted):
        for name in ('result', 'reference', 'tolerance'):
            self.data[name] = {where: values for where, values in self.pixels(name) if where in wanted}

    def pick(self, name, values, channel):
        names = self.channels.get(name)
        if names and channel in names:
            return values[names.index(channel)]
        return values['RGBA'.index(channel)]

    def values(self, x, y):
        out = {}
        for name in ('result', 'reference', 'tolerance'):
            values = self.data[name].get((x, y))
            if values is None:
                raise Fatal('oiiotool printed no pixel (%d, %d) of %s.exr' % (x, y, name))
            out[name] = [Expected.from_dump(self.pick(name, values, c)) for c in 'RGB']
        out['mask'] = Expected.from_dump(self.pick('reference', self.data['reference'][(x, y)], 'A'))
        return out


class OiioModuleSource:
    """The EXR files read with OpenImageIO's Python module: every channel's
    float32 exactly, so every probe value must be equal to it. Special pixels
    as OiiotoolSource finds them (masked, zero tolerance, NaN, infinity)."""
    name = 'OpenImageIO (python3-openimageio)'

    def __init__(self, oiio, folder):
        self.oiio, self.folder = oiio, folder
        self.images = {}
        self.special = []

    def read(self, name):
        path = os.path.join(self.folder, name + '.exr')
        image = self.oiio.ImageInput.open(path)
        if image is None:
            raise Fatal('OpenImageIO cannot open %s: %s' % (path, self.oiio.geterror()))
        try:
            spec = image.spec()
            pixels = image.read_image('float')
        finally:
            image.close()
        return list(spec.channelnames), pixels

    def prepare(self):
        for name in ('result', 'reference', 'tolerance'):
            self.images[name] = self.read(name)
        finds = [('NaN in the result', 'result', lambda v: any(math.isnan(t) for t in v[:3])),
                 ('infinity in the result', 'result', lambda v: any(math.isinf(t) for t in v[:3])),
                 ('masked (mask 0)', 'reference', lambda v: v[3] == 0),
                 ('tolerance 0', 'tolerance', lambda v: any(t == 0 for t in v[:3]))]
        for what, name, test in finds:
            names, pixels = self.images[name]
            order = [names.index(c) for c in 'RGBA' if c in names]
            found = next(((x, y) for y in range(pixels.shape[0]) for x in range(pixels.shape[1])
                          if test([float(pixels[y][x][i]) for i in order])), None)
            if found:
                self.special.append((found, what))

    def load(self, wanted):
        pass

    def channel(self, name, x, y, c):
        names, pixels = self.images[name]
        value = float(pixels[y][x][names.index(c)])
        if math.isnan(value):
            return Expected(nonfinite='nan', text='nan')
        if math.isinf(value):
            return Expected(nonfinite='+inf' if value > 0 else '-inf', text=repr(value))
        return Expected(exact=f32(value), text=repr(value))

    def values(self, x, y):
        out = {name: [self.channel(name, x, y, c) for c in 'RGB'] for name in ('result', 'reference', 'tolerance')}
        out['mask'] = self.channel('reference', x, y, 'A')
        return out


def oiio_module():
    try:
        import OpenImageIO
        return OpenImageIO
    except ImportError:
        return None


# ---------------------------------------------------------------- PNG (screenshots)
def decode_png(data):
    """8-bit RGB or RGBA PNG -> (width, height, rows of (r, g, b) tuples)."""
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise Fatal('the screenshot is not a PNG')
    pos, idat = 8, b''
    width = height = colour = None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise Fatal('screenshot PNG of an unexpected kind (depth %d, colour %d)' % (depth, colour))
        elif kind == b'IDAT':
            idat += body
        elif kind == b'IEND':
            break
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous, pos = [], bytearray(stride), 0
    for _ in range(height):
        kind = raw[pos]
        line = bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, channels)])
        previous = line
    return width, height, rows


# ---------------------------------------------------------------- the checks
PROBE_IDS = (['probe-x', 'probe-y', 'probe-mask', 'probe-status']
             + ['probe-%s-%s' % (row, c) for row in ('result', 'reference', 'tolerance', 'diff', 'ratio')
                for c in 'rgb'])


def read_probe(page):
    return page.evaluate('(() => { const o = {}; for (const id of %s) { const e = document.getElementById(id); '
                         'o[id] = e ? e.textContent : null; o[id + ".fail"] = !!(e && e.classList.contains("fail")); } '
                         'return o; })()' % json.dumps(PROBE_IDS))


def wait_ready(page):
    deadline = time.monotonic() + COMMAND_TIMEOUT_S
    while time.monotonic() < deadline:
        state = page.state()
        if state.get('error'):
            raise Fatal('the viewer reports: %s' % state['error'])
        if state.get('ready') == '1':
            return state
        time.sleep(0.05)
    raise Fatal('the viewer did not become ready (body data-ready="1")')


def file_url(path):
    return 'file://' + quote(os.path.abspath(path))


def open_viewer(browser, folder, network=False):
    page = Page(browser, network=network)
    page.navigate(file_url(os.path.join(folder, 'viewer.html')))
    wait_ready(page)
    return page


def zoom_to(page, x, y):
    """As a reader would: fit the image, point at pixel (x, y), zoom in with
    the wheel about the pointer, then drag the pixel well into the view."""
    page.key('f')
    sx, sy = page.screen_of(x, y)
    for _ in range(16):
        if float(page.state()['zoom']) >= ZOOM_FOR_PROBING:
            break
        page.send('Input.dispatchMouseEvent', {'type': 'mouseWheel', 'x': sx, 'y': sy, 'deltaX': 0, 'deltaY': -240})
        sx, sy = page.screen_of(x, y)
    return bring_into_view(page, x, y)


def bring_into_view(page, x, y):
    """Pans by dragging until pixel (x, y) lies well inside the view."""
    for _ in range(40):
        rect = page.view_rect()
        sx, sy = page.screen_of(x, y)
        margin = ZOOM_FOR_PROBING
        left, top = rect['left'] + margin, rect['top'] + margin
        right, bottom = rect['left'] + rect['width'] - margin, rect['top'] + rect['height'] - margin
        if left <= sx <= right and top <= sy <= bottom:
            return sx, sy
        cx, cy = rect['left'] + rect['width'] / 2, rect['top'] + rect['height'] / 2
        dx = max(-0.45 * rect['width'], min(0.45 * rect['width'], cx - sx))
        dy = max(-0.45 * rect['height'], min(0.45 * rect['height'], cy - sy))
        page.drag(cx - dx / 2, cy - dy / 2, cx + dx / 2, cy + dy / 2, steps=4)
    raise Fatal('could not pan pixel (%d, %d) into view' % (x, y))


def check_probe_values(checks, label, probe, x, y, scale, sources):
    """The probe at (x, y) against each independent source."""
    ok_where = probe['probe-x'] == str(x) and probe['probe-y'] == str(y)
    checks.check(ok_where, '%s: pointer in the bottom-right of pixel (%d, %d) probes it' % (label, x, y),
                 'it shows (%s, %s)' % (probe['probe-x'], probe['probe-y']))
    if not ok_where:
        return
    shown = {}
    for row in ('result', 'reference', 'tolerance', 'diff', 'ratio'):
        shown[row] = [parse_probe(probe['probe-%s-%s' % (row, c)]) for c in 'rgb']
    mask_shown = parse_probe(probe['probe-mask'])
    unreadable = [k for k in PROBE_IDS[4:] if parse_probe(probe[k]) is None]
    if not checks.check(not unreadable and mask_shown is not None,
                        '%s: every probe field at (%d, %d) reads as a number' % (label, x, y),
                        ', '.join('%s=%r' % (k, probe[k]) for k in unreadable)):
        return

    # The page's arithmetic on the values it shows: |diff| and the ratio rule.
    # Each shown result and reference names a float32: subtracting the 9-digit
    # decimals instead would cancel away most of a small difference's digits.
    problems = []
    for c, ch in enumerate('rgb'):
        diff = abs(f32(shown['result'][c]) - f32(shown['reference'][c]))
        if not close_relative(shown['diff'][c], diff, 1e-6):
            problems.append('%s: |diff| %r, expected %r' % (ch, shown['diff'][c], diff))
        tolerance = f32(shown['tolerance'][c]) if scale == 1.0 else shown['tolerance'][c]
        ratio = ratio_rule(diff, tolerance)
        if not close_relative(shown['ratio'][c], ratio, 1e-6):
            problems.append('%s: ratio %r, expected %r' % (ch, shown['ratio'][c], ratio))
        failing = not (shown['ratio'][c] <= 1)
        if probe['probe-ratio-%s.fail' % ch] != failing:
            problems.append('%s: ratio %r %s highlighted as failing' % (
                ch, shown['ratio'][c], 'is not' if failing else 'is'))
    checks.check(not problems, '%s: (%d, %d) |diff| and ratio follow from the values shown' % (label, x, y),
                 '; '.join(problems))

    for source in sources:
        expected = source.values(x, y)
        problems, inexact = [], 0
        for row, row_scale in (('result', 1.0), ('reference', 1.0), ('tolerance', scale)):
            for c, ch in enumerate('rgb'):
                e = expected[row][c]
                inexact += e.exact is None and e.nonfinite is None
                if not e.matches(shown[row][c], row_scale):
                    problems.append('%s %s: page %s, %s has %s' % (
                        row, ch, probe['probe-%s-%s' % (row, ch)], source.name, e.describe(row_scale)))
        if not expected['mask'].matches(mask_shown):
            problems.append('mask: page %s, %s has %s' % (probe['probe-mask'], source.name,
                                                          expected['mask'].describe()))
        # The ratio the source's values allow (a point where they are exact).
        for c, ch in enumerate('rgb'):
            r, ref, tol = expected['result'][c], expected['reference'][c], expected['tolerance'][c]
            if r.nonfinite or ref.nonfinite or tol.nonfinite:
                continue   # the non-finite values were matched above; the rule was checked on them
            d = abs_difference_interval(r.interval(1.0), ref.interval(1.0))
            allowed = ratio_interval(d, tol.interval(scale))
            if not in_interval(shown['ratio'][c], allowed):
                problems.append('ratio %s: page %s, %s allows [%r, %r]' % (
                    ch, probe['probe-ratio-%s' % ch], source.name, allowed[0], allowed[1]))
            if not in_interval(shown['diff'][c], d):
                problems.append('|diff| %s: page %s, %s allows [%r, %r]' % (
                    ch, probe['probe-diff-%s' % ch], source.name, d[0], d[1]))
        note = '' if not inexact else ' (%d of 9 values pinned only to its printed digits)' % inexact
        checks.check(not problems, '%s: (%d, %d) matches %s%s' % (label, x, y, source.name, note),
                     '; '.join(problems))


def crisp_blocks(page, checks, label, x, y, width, height):
    """At high zoom each image pixel must be a uniform block (nearest neighbour)."""
    x = min(max(x, 1), width - 2)
    y = min(max(y, 1), height - 2)
    sx, sy = zoom_to(page, x, y)
    page.mouse('mouseMoved', sx, sy)   # the probe's outline on this block's edge, not inside a neighbour
    z = float(page.state()['zoom'])
    left, top = sx - 1.5 * z, sy - 1.5 * z
    shot_x, shot_y = int(math.floor(left)), int(math.floor(top))
    # The layer's name sits over the view's top-left corner, where a pixel at
    # the image's corner lands when the view cannot pan further: hidden for
    # the shot, since it is a label, not the image.
    page.evaluate('document.getElementById("layer-badge").style.visibility = "hidden"')
    try:
        w, h, rows = page.screenshot(shot_x, shot_y, int(math.ceil(3 * z)) + 2, int(math.ceil(3 * z)) + 2)
    finally:
        page.evaluate('document.getElementById("layer-badge").style.visibility = ""')
    colours, mixed = [], []
    inset = 4   # grid line, probe outline (2 px and its antialiasing): all near the block's edge
    for j in range(3):
        for i in range(3):
            x0 = left + i * z - shot_x + inset
            y0 = top + j * z - shot_y + inset
            block = set()
            for yy in range(int(math.ceil(y0)), int(math.floor(y0 + z - 2 * inset))):
                for xx in range(int(math.ceil(x0)), int(math.floor(x0 + z - 2 * inset))):
                    if 0 <= yy < h and 0 <= xx < w:
                        block.add(rows[yy][xx])
            if len(block) != 1:
                mixed.append('(%d, %d): %d colours' % (x - 1 + i, y - 1 + j, len(block)))
            colours.append(next(iter(block)) if block else None)
    checks.check(not mixed, '%s: at zoom %.4g every pixel around (%d, %d) is one sharp block of colour' % (
        label, z, x, y), '; '.join(mixed))
    return len(set(colours))


def check_folder(browser, folder, checks, sources, rng):
    label = os.path.basename(os.path.normpath(folder))
    page = open_viewer(browser, folder)
    try:
        info = page.evaluate('(() => { const d = window.LIGHTCTS_EVIDENCE; return {width: d.width, height: d.height,'
                             ' scale: d.tolerance_scale, test: d.test, worst: (d.summary && d.summary.worst || [])'
                             '.map(w => [w.x, w.y])}; })()')
        width, height, scale = info['width'], info['height'], float(info['scale'])
        checks.note('%s: %s, %d x %d, tolerance scale %r' % (label, info['test'], width, height, scale))
        summary_path = os.path.join(folder, 'summary.json')
        if os.path.exists(summary_path):
            with open(summary_path) as f:
                on_disk = json.load(f)
            checks.check(on_disk.get('test') == info['test'] and float(on_disk.get('tolerance_scale', 1)) == scale,
                         '%s: viewer-data.js names the test and tolerance scale of summary.json' % label,
                         'summary.json: %r, %r' % (on_disk.get('test'), on_disk.get('tolerance_scale')))
        for source in sources:
            if isinstance(source, JsonSource):
                checks.check((source.width, source.height) == (width, height) and
                             (source.scale is None or float(source.scale) == scale),
                             '%s: %s describes an image of the same size and scale' % (label, source.name))

        # -- layers, by key
        state = page.state()
        checks.check(state['layer'] == 'result', '%s: opens on the result layer' % label, state['layer'])
        for key, layer in (('2', 'reference'), ('3', 'tolerance'), ('4', 'error'), ('1', 'result'),
                           ('Space', 'reference'), ('Space', 'result')):
            page.key(key)
            state = page.state()
            shown = page.evaluate('document.getElementById("layer-name").textContent')
            checks.check(state['layer'] == layer and shown.startswith({'error': 'error mask'}.get(layer, layer)),
                         '%s: key %s shows the %s layer' % (label, key, layer),
                         'data-layer %r, shown %r' % (state['layer'], shown))

        # -- exposure and false colour
        page.key('e')
        page.key('e')
        checks.check(page.state()['exposure'] == '1', '%s: e e raises the exposure to +1 stop' % label,
                     page.state()['exposure'])
        page.key('E')
        checks.check(page.state()['exposure'] == '0.5', '%s: E lowers it by half a stop' % label,
                     page.state()['exposure'])
        page.key('4')
        page.key('c')
        state = page.state()
        legend_drawn = page.evaluate('(() => { const c = document.getElementById("legend"); if (c.closest("[hidden]"))'
                                     ' return false; const d = c.getContext("2d").getImageData(0, 0, c.width, c.height)'
                                     '.data; let n = 0; for (let i = 3; i < d.length; i += 4) n += d[i] > 0; '
                                     'return n > c.width * 10; })()')
        checks.check(state['falseColour'] == '1' and state['legend'] == 'ratio' and legend_drawn,
                     '%s: c on the error mask shows the ratio in false colour with a drawn legend' % label,
                     'falseColour %s, legend %s, drawn %s' % (state['falseColour'], state['legend'], legend_drawn))
        page.key('3')
        checks.check(page.state()['legend'] == 'tolerance',
                     '%s: the tolerance layer in false colour has its own legend' % label, page.state()['legend'])
        page.key('c')
        page.key('1')
        checks.check(page.state()['falseColour'] == '0' and page.state()['legend'] == 'none',
                     '%s: c again turns false colour off' % label)

        # -- swipe: the line follows a drag; a drag elsewhere pans instead
        page.key('s')
        state = page.state()
        checks.check(state['swipeMode'] == 'on' and state['layer'] == 'result' and state['swipeRight'] == 'reference',
                     '%s: s turns swiping on, result left of the line, reference right' % label,
                     'mode %s, %s | %s' % (state['swipeMode'], state['layer'], state['swipeRight']))
        rect = page.view_rect()
        zoom = float(state['zoom'])
        line_x = page.evaluate('window.lightctsViewer.swipeClientX()')
        mid_y = rect['top'] + rect['height'] / 2
        before_swipe, before_pan = float(state['swipe']), float(state['panX'])
        page.drag(line_x, mid_y, line_x - 150, mid_y + 20)
        state = page.state()
        moved = float(state['swipe']) - before_swipe
        checks.check(abs(moved - (-150 / zoom)) <= 1 / zoom and float(state['panX']) == before_pan,
                     '%s: dragging the swipe line 150 px left moves it %.3g image pixels, the view stays' % (
                         label, 150 / zoom),
                     'moved %r image pixels, pan %r -> %s' % (moved, before_pan, state['panX']))
        page.key('Shift+2')
        page.key('1')
        checks.check(page.state()['swipeRight'] == 'reference' and page.state()['layer'] == 'result',
                     '%s: Shift+2 puts the reference right of the line' % label)
        page.key('Space')
        state = page.state()
        checks.check(state['layer'] == 'reference' and state['swipeRight'] == 'result',
                     '%s: Space in swipe mode swaps the sides' % label,
                     '%s | %s' % (state['layer'], state['swipeRight']))
        page.key('Space')
        line_x = page.evaluate('window.lightctsViewer.swipeClientX()')
        start_x = rect['left'] + 60 if line_x > rect['left'] + 200 else rect['left'] + rect['width'] - 60
        before_swipe, before_pan = float(state['swipe']), float(page.state()['panX'])
        page.drag(start_x, mid_y, start_x + 40, mid_y)
        state = page.state()
        checks.check(abs(float(state['panX']) - (before_pan + 40)) < 1e-6,
                     '%s: a drag away from the line pans by the drag (40 px)' % label,
                     'pan %r -> %s' % (before_pan, state['panX']))
        page.key('s')
        checks.check(page.state()['swipeMode'] == 'off', '%s: s turns swiping off' % label)

        # -- zoom by keys
        page.key('f')
        fit_zoom = float(page.state()['zoom'])
        page.key('+')
        page.key('+')
        z2 = float(page.state()['zoom'])
        page.key('-')
        z1 = float(page.state()['zoom'])
        page.key('0')
        z0 = float(page.state()['zoom'])
        checks.check(z2 == fit_zoom * 4 and z1 == fit_zoom * 2 and z0 == fit_zoom,
                     '%s: + + doubles the zoom twice, - halves it, 0 fits again (fit %.4g)' % (label, fit_zoom),
                     '%r, %r, %r' % (z2, z1, z0))
        while float(page.state()['zoom']) < ZOOM_FOR_PROBING:
            page.key('+')
        zoom = float(page.state()['zoom'])
        checks.check(zoom >= ZOOM_FOR_PROBING, '%s: zoomed in to %.4g screen pixels per image pixel' % (label, zoom))

        # -- the worst pixel's entry centres it and probes it
        worst = [tuple(w) for w in info['worst']]
        if worst:
            box = page.evaluate('(() => { const b = document.getElementById("worst-0"); b.scrollIntoView();'
                                ' const r = b.getBoundingClientRect(); return {x: r.left + r.width / 2,'
                                ' y: r.top + r.height / 2}; })()')
            page.click(box['x'], box['y'])
            state = page.state()
            sx, sy = page.screen_of(*worst[0])
            rect = page.view_rect()
            centred = (abs(sx - (rect['left'] + rect['width'] / 2)) <= zoom and
                       abs(sy - (rect['top'] + rect['height'] / 2)) <= zoom)
            checks.check((int(state['probeX']), int(state['probeY'])) == worst[0] and centred
                         and float(state['zoom']) >= ZOOM_FOR_PROBING,
                         '%s: clicking worst pixel (%d, %d) centres, zooms and probes it' % ((label,) + worst[0]),
                         'probe (%s, %s), screen (%.1f, %.1f)' % (state['probeX'], state['probeY'], sx, sy))

        # -- hover pixels and read the probe
        corners = [(0, 0), (width - 1, 0), (0, height - 1), (width - 1, height - 1)]
        randoms = [(rng.randrange(width), rng.randrange(height)) for _ in range(4)]
        for source in sources:
            source.prepare()
        special = [p for source in sources for p, _ in source.special]
        chosen = []
        for p in worst[:3] + corners + randoms + special:
            if p not in chosen:
                chosen.append(p)
        for source in sources:
            for p, what in source.special:
                checks.note('%s names (%d, %d): %s' % (source.name, p[0], p[1], what))
        for source in sources:
            source.load(set(chosen))
        for x, y in chosen:
            sx, sy = zoom_to(page, x, y)
            # Near two opposite corners of the pixel, not its centre: a probe that
            # rounds instead of taking the pixel the pointer is in shows a neighbour.
            quarter = 0.3 * float(page.state()['zoom'])
            page.mouse('mouseMoved', sx - quarter, sy - quarter)
            first = read_probe(page)
            checks.check((first['probe-x'], first['probe-y']) == (str(x), str(y)),
                         '%s: pointer in the top-left of pixel (%d, %d) probes it' % (label, x, y),
                         'it probes (%s, %s)' % (first['probe-x'], first['probe-y']))
            page.mouse('mouseMoved', sx + quarter, sy + quarter)
            check_probe_values(checks, label, read_probe(page), x, y, scale, sources)

        # -- nearest neighbour at high zoom, seen in a screenshot
        page.key('m')
        checks.check(page.state()['markers'] == '0', '%s: m hides the worst-pixel markers' % label)
        distinct = 0
        for x, y in (worst[:1] + randoms)[:3]:
            distinct = max(distinct, crisp_blocks(page, checks, label, x, y, width, height))
        # The synthetic evidence is made to vary there; a real frame may be one
        # colour where the check looks (a black result), which proves nothing
        # either way, so it is said, not failed.
        if any(isinstance(source, JsonSource) for source in sources):
            checks.check(distinct >= 2, '%s: the crisp-block check saw pixels of different colours' % label,
                         'every block it looked at had the same colour, so it proved little')
        elif distinct < 2:
            checks.note('%s: every block the crisp-block check looked at had one colour (a uniform frame there)' % label)
        errors = page.script_errors()
        checks.check(not errors, '%s: no uncaught script error in the page' % label, ' | '.join(errors))
    finally:
        page.close()


class LinkAttributes(html.parser.HTMLParser):
    """Every attribute of the page that can name something to load, as "name=value"."""
    NAMES = {'src', 'href', 'srcset', 'action', 'formaction', 'poster', 'data', 'background', 'manifest', 'ping'}

    def __init__(self):
        super().__init__()
        self.found = []

    def handle_starttag(self, tag, attrs):
        self.found += ['%s=%s' % (k, v) for k, v in attrs if k in self.NAMES]

    handle_startendtag = handle_starttag

    @staticmethod
    def of(text):
        parser = LinkAttributes()
        parser.feed(text)
        parser.close()
        return parser.found


def check_no_network(browser, folder, checks):
    label = os.path.basename(os.path.normpath(folder)) + ' (no network)'
    with open(os.path.join(folder, 'viewer.html'), encoding='utf-8') as f:
        source = f.read()
    urls = re.findall(r'(?i)\b(?:https?|wss?|ftp):', source)
    loaders = re.findall(r'\b(?:fetch|XMLHttpRequest|WebSocket|EventSource|importScripts|sendBeacon)\b|@import|url\(',
                         source)
    links = [a for a in LinkAttributes.of(source) if a not in ('src=viewer-data.js',) and not a.endswith('=#')]
    checks.check(not urls and not links and not loaders,
                 '%s: viewer.html names no URL and loads nothing but viewer-data.js' % label,
                 '; '.join(urls + links + loaders))

    page = Page(browser, network=True)
    try:
        page.navigate(file_url(os.path.join(folder, 'viewer.html')))
        wait_ready(page)
        # Use it: every layer, false colour, swipe, zoom by wheel, a worst pixel, hover.
        for key in ('2', '3', 'c', '4', 'c', 's', '1', 's', '+', 'n', 'e'):
            page.key(key)
        rect = page.view_rect()
        cx, cy = rect['left'] + rect['width'] / 2, rect['top'] + rect['height'] / 2
        page.send('Input.dispatchMouseEvent', {'type': 'mouseWheel', 'x': cx, 'y': cy, 'deltaX': 0, 'deltaY': -240})
        page.mouse('mouseMoved', cx, cy)
        page.drag(cx, cy, cx + 30, cy + 10)
        page.mouse('mouseMoved', cx + 5, cy + 5)
        probe = read_probe(page)
        state = page.state()
        shows = (probe['probe-x'] == state.get('probeX') and probe['probe-x'] not in (None, '', '\u2013')
                 and all(parse_probe(probe['probe-%s-%s' % (row, c)]) is not None
                         for row in ('result', 'reference', 'tolerance', 'ratio') for c in 'rgb'))
        checks.check(shows, '%s: with every network access failing the probe shows values at (%s, %s)' % (
            label, probe['probe-x'], probe['probe-y']), json.dumps(probe))
        time.sleep(0.3)   # let late requests, if any, be reported
        requests, failures = [], []
        for event in page.browser.events_since(page.network_start):
            if event.get('sessionId') != page.session:
                continue
            if event.get('method') == 'Network.requestWillBeSent':
                requests.append(event['params']['request']['url'])
            elif event.get('method') == 'Network.loadingFailed':
                failures.append(event['params'].get('errorText', '?'))
        schemes = sorted({u.split(':', 1)[0] for u in requests})
        others = [u for u in requests if u.split(':', 1)[0] not in ('file', 'data', 'blob')]
        names = {os.path.basename(u.split('?')[0]) for u in requests if u.startswith('file:')}
        checks.check(not others, '%s: all %d requests are file/data/blob (schemes seen: %s)' % (
            label, len(requests), ', '.join(schemes)), ' '.join(others))
        checks.check({'viewer.html', 'viewer-data.js'} <= names,
                     '%s: the Network domain saw viewer.html and viewer-data.js load' % label, ' '.join(sorted(names)))
        checks.check(not failures, '%s: no request failed' % label, ', '.join(failures))
        errors = page.script_errors()
        checks.check(not errors, '%s: no uncaught script error in the page' % label, ' | '.join(errors))
    finally:
        page.close()


def report_viewer_folders(index_html):
    """The folders of the viewer pages that a run's report links to (an <a
    href> or an <iframe src> ending in viewer.html), in page order, once each:
    the test starts from the report a reader opens, not from a folder it knows."""
    class Links(html.parser.HTMLParser):
        def __init__(self):
            super().__init__()
            self.found = []

        def handle_starttag(self, tag, attrs):
            for key, value in attrs:
                if key in ('href', 'src') and value and value.split('#')[0].endswith('viewer.html'):
                    self.found.append(value.split('#')[0])
    links = Links()
    with open(index_html, encoding='utf-8') as f:
        links.feed(f.read())
    base = os.path.dirname(os.path.abspath(index_html))
    folders = []
    for link in links.found:
        folder = os.path.dirname(os.path.normpath(os.path.join(base, urllib.parse.unquote(link))))
        if folder not in folders:
            folders.append(folder)
    return folders


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('folders', nargs='*', metavar='EVIDENCE_DIR')
    parser.add_argument('--no-network', action='store_true', help='check that the page makes no network request')
    parser.add_argument('--expected-json', help='expected-values.json for the (single) EVIDENCE_DIR')
    parser.add_argument('--sample', metavar='TEMPLATE', help='check a synthetic sample made from TEMPLATE')
    parser.add_argument('--report', metavar='INDEX_HTML',
                        help="check every evidence viewer a run's report links to (report/index.html)")
    args = parser.parse_args()
    if args.report:
        viewers = report_viewer_folders(args.report)
        if not viewers:
            print('FAIL: %s links to no evidence viewer (viewer.html)' % args.report)
            return 1
        print('%s links to %d evidence viewer(s)' % (args.report, len(viewers)))
        args.folders = list(args.folders) + viewers
    if not args.folders and not args.sample:
        parser.error('give at least one EVIDENCE_DIR, or --sample TEMPLATE')
    if args.expected_json and len(args.folders) != 1:
        parser.error('--expected-json goes with exactly one EVIDENCE_DIR')

    chromium = find_chromium()
    if not chromium:
        print('NotSupported: chromium not installed (apt-get install chromium; scripts/setup.sh installs it)')
        return SKIP

    scratch = tempfile.mkdtemp(prefix='lightcts-viewer-sample-')
    browser = None
    checks = Checks()
    timer = None
    try:
        jobs = []   # (folder, expected-values.json or None)
        if args.sample:
            # Two: odd sizes with the tolerance as it is, and a tolerance scale of
            # 1.5, which the probe must apply (real evidence mostly has 1).
            maker = os.path.join(os.path.dirname(os.path.abspath(args.sample)), 'make_sample_evidence.py')
            for name, options in (('sample-37x23', []),
                                  ('sample-64x48-scale-1.5', ['--width', '64', '--height', '48',
                                                              '--tolerance-scale', '1.5'])):
                folder = os.path.join(scratch, name)
                subprocess.run([sys.executable, maker, args.sample, folder] + options, check=True, timeout=60)
                jobs.append((folder, os.path.join(folder, 'expected-values.json')))
        for folder in args.folders:
            jobs.append((folder, args.expected_json))
        for folder, _ in jobs:
            needed = ['viewer.html', 'viewer-data.js', 'result.exr', 'reference.exr', 'tolerance.exr']
            missing = [n for n in needed if not os.path.exists(os.path.join(folder, n))]
            if missing:
                print('FAIL: %s lacks %s' % (folder, ', '.join(missing)))
                return 1

        oiio = oiio_module()
        oiiotool = None if oiio else shutil.which('oiiotool')
        probes = True
        if not oiio and not oiiotool and not all(expected for _, expected in jobs):
            if not args.no_network:
                print('NotSupported: neither python3-openimageio nor oiiotool is installed, and no --expected-json: '
                      'nothing independent to compare the probe with')
                return SKIP
            print('note: neither python3-openimageio nor oiiotool is installed, and no --expected-json: '
                  'the network checks run alone')
            probes = False
        elif not oiio and not oiiotool:
            print('note: no OpenImageIO here; comparing with expected-values.json only')

        # A hard limit: whatever hangs, Chromium goes and the test fails.
        limit = OVERALL_TIMEOUT_S + PER_FOLDER_S * (len(jobs) - 1)

        def on_timeout():
            print('FAIL: timed out after %d s' % limit, flush=True)
            if browser:
                kill_group(browser.process)
                shutil.rmtree(browser.profile, ignore_errors=True)
            shutil.rmtree(scratch, ignore_errors=True)
            os._exit(1)
        timer = threading.Timer(limit, on_timeout)
        timer.daemon = True
        timer.start()

        started = time.monotonic()
        flags = (['--proxy-server=127.0.0.1:9', '--host-resolver-rules=MAP * ~NOTFOUND']
                 if args.no_network else [])
        browser = Browser(chromium, flags)
        browser.send('Target.setDiscoverTargets', {'discover': False})
        for folder, expected in jobs:
            if args.no_network:
                check_no_network(browser, folder, checks)
            if not probes:
                continue
            sources = []
            if oiio:
                sources.append(OiioModuleSource(oiio, folder))
            elif oiiotool:
                sources.append(OiiotoolSource(oiiotool, folder, tempfile.mkdtemp(dir=scratch)))
            if expected:
                sources.append(JsonSource(expected))
            check_folder(browser, folder, checks, sources, random.Random(RANDOM_SEED))
        print('chromium: %.1f s' % (time.monotonic() - started))
    except Fatal as e:
        checks.check(False, 'the test ran to the end', str(e))
        if browser:
            tail = browser.log_tail()
            if tail:
                print('chromium log (last lines):\n' + tail)
    except subprocess.CalledProcessError as e:
        checks.check(False, 'the sample evidence was written', str(e))
    finally:
        if browser:
            browser.close()
        if timer:
            timer.cancel()
        shutil.rmtree(scratch, ignore_errors=True)
    print('%d passed, %d failed' % (checks.passed, checks.failed))
    return 1 if checks.failed else 0


if __name__ == '__main__':
    sys.exit(main())
