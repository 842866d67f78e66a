#!/usr/bin/env python3
"""Times commands and writes the result as a record of docs/measurements.md,
with the date, the commit, the machine, its load when the timing started, the
command and (with --suite) the suite's size, so that no figure in the docs is
typed by hand and a change to the suite flags it (docs.measured-figures-have-
provenance).

    scripts/measure.py ID --what TEXT [--step LABEL=COMMAND ...] [--repeat N]
                       [--total] [--note TEXT] [--suite] [--in DIR] [--into PAGE]

Each step is run with bash in DIR (default: here) in the order given and
timed by the wall clock; with --repeat N each step runs N times and its
median is kept. The figure is the steps' times (led by their total with
--total), then what ctest said of its tests when a step ran ctest ("2563
tests passed"), then the note; ctest's label summary, when a step printed
one, is the record's `labels` (process-seconds and tests per label). A step that fails stops the measurement and
writes nothing (exit 1). Exit 2 for bad arguments.

Example, a fresh clone's build and tests:

    git clone . /tmp/fresh && XDG_CACHE_HOME=$(mktemp -d) scripts/measure.py fresh-clone --suite --total \\
        --what '`.ci/run` in a fresh clone, every cache empty' --in /tmp/fresh \\
        --step 'setup, configure and build=bash scripts/build.sh' \\
        --step 'ctest=ctest --preset release -j2'
"""
import argparse
import datetime
import re
import os
import platform
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'docs'))
import measurement_records  # noqa: E402  (docs/ holds the page's form and the tree's counts)
from check_doc_counts import tree_counts  # noqa: E402


def shown_time(seconds):
    if seconds < 1:
        return f'{seconds * 1000:.3g} ms'
    if seconds < 10:
        return f'{seconds:.1f} s'
    if seconds < 300:
        return f'{seconds:.0f} s'
    return f'{seconds / 60:.1f} min ({seconds:.0f} s)'


def machine():
    def first(path, key):
        try:
            with open(path, encoding='utf-8') as f:
                for line in f:
                    if line.startswith(key):
                        return line.split(':', 1)[1].strip() if ':' in line else line.split('=', 1)[1].strip('"\n')
        except OSError:
            pass
        return '?'
    memory_kb = first('/proc/meminfo', 'MemTotal').split()[0]
    mesa = subprocess.run(['dpkg-query', '-W', '-f', '${Version}', 'libgl1-mesa-dri'],
                          capture_output=True, text=True).stdout.strip() or 'absent'
    gigabytes = round(int(memory_kb) / 1024 ** 2) if memory_kb.isdigit() else '?'
    return (f'{os.cpu_count()} cores, {first("/proc/cpuinfo", "model name")}, {gigabytes} GB, '
            f'{first("/etc/os-release", "PRETTY_NAME")}, Mesa {mesa}, {platform.machine()}')


def commit(directory):
    def git(*args):
        return subprocess.run(['git', '-C', directory, *args], capture_output=True, text=True).stdout.strip()
    head = git('rev-parse', '--short', 'HEAD') or 'not a git tree'
    return head + (' with uncommitted changes' if git('status', '--porcelain', '--untracked-files=no') else '')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('id')
    parser.add_argument('--what', required=True)
    parser.add_argument('--step', action='append', required=True, metavar='LABEL=COMMAND')
    parser.add_argument('--repeat', type=int, default=1)
    parser.add_argument('--note', default='')
    parser.add_argument('--total', action='store_true', help="lead the figure with the steps' total")
    parser.add_argument('--suite', action='store_true', help="record the suite's size, which the check holds to the tree")
    parser.add_argument('--in', dest='directory', default='.')
    parser.add_argument('--into', default=os.path.join(HERE, '..', 'docs', 'measurements.md'))
    args = parser.parse_args()
    steps = []
    for step in args.step:
        label, sep, command = step.partition('=')
        if not sep or not command:
            parser.error(f'--step {step!r} is not LABEL=COMMAND')
        steps.append((label, command))
    if args.repeat < 1:
        parser.error('--repeat must be at least 1')

    with open('/proc/loadavg', encoding='utf-8') as f:
        load = f.read().split()[0]
    started = datetime.datetime.now(datetime.timezone.utc)
    times, said, labels = [], [], []
    for label, command in steps:
        runs = []
        for _ in range(args.repeat):
            t0 = time.monotonic()
            process = subprocess.Popen(['bash', '-c', command], cwd=args.directory, stdout=subprocess.PIPE,
                                       stderr=subprocess.STDOUT, text=True)
            tests, skipped, step_labels = None, 0, []  # ctest's, of the last repetition
            for line in process.stdout:  # shown as it comes; ctest's summary lines are kept
                sys.stdout.write(line)
                skipped += '***Skipped' in line  # ctest counts a skip among the "tests passed"
                m = re.search(r'(\d+)% tests passed, (\d+) tests? failed out of (\d+)', line)
                if m:
                    total, failed = int(m.group(3)), int(m.group(2))
                    tests = f'{total - failed - skipped} of {total} tests passed, {skipped} skipped, {failed} failed'
                summary = re.match(r'^(\S+)\s+=\s+([\d.]+) sec\*proc \((\d+) tests?\)', line)
                if summary:
                    step_labels.append(f'{summary.group(1)} {float(summary.group(2)):.0f} ({summary.group(3)})')
            process.wait()
            runs.append(time.monotonic() - t0)
            if step_labels:  # a later step without ctest keeps the summary a ctest step left
                labels = step_labels
            if process.returncode != 0:
                print(f'measure.py: step "{label}" exited {process.returncode}; nothing written', file=sys.stderr)
                return 1
        times.append(statistics.median(runs))
        if tests:
            said.append(f'{label}: {tests}')

    parts = [f'{label} {shown_time(t)}' for (label, _), t in zip(steps, times)]
    figure = '; '.join(([f'{shown_time(sum(times))} in all'] if args.total else []) + parts)
    if args.repeat > 1:
        figure += f' (medians of {args.repeat})'
    if said:
        figure += '; ' + '; '.join(said)
    if args.note:
        figure += f'; {args.note}'
    record = {
        'what': args.what,
        'figure': figure,
        'date': started.strftime('%Y-%m-%d'),
        'commit': commit(args.directory),
        'machine': machine(),
        'labels': ('process-seconds (tests) per ctest label: ' + ', '.join(labels)) if labels else '',
        'load': f'{load} (one-minute load average when it started)',
        'command': '; '.join(f'`{c}`' for _, c in steps) + (f" in {args.directory}" if args.directory != '.' else ''),
    }
    if args.suite:
        t = tree_counts(args.directory)
        record['suite'] = f'{t["scenes"]} scenes, {t["combinations"]} combinations, {t["mutants"]} mutants'
    with open(args.into, encoding='utf-8') as f:
        text = f.read()
    new = measurement_records.replace_record(text, args.id, record)
    with open(args.into + '.tmp', 'w', encoding='utf-8') as f:
        f.write(new)
    os.replace(args.into + '.tmp', args.into)
    print(f'{args.id}: {figure}  -> {args.into}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
