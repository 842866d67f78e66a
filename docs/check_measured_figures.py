#!/usr/bin/env python3
"""Every measured figure README.md and docs/ state has its provenance, and a
figure the tree has outgrown is flagged.

Measured times live in two places: docs/measurements.md, one record per
measurement (scripts/measure.py writes them: figure, date, commit, machine,
load, command, and the suite's size where the figure depends on it), and
docs/performance.md, the bench's own page, whose every section that states
a time names its date. Elsewhere a time is quoted through a link to its
record, `[7.9 minutes](measurements.md#fresh-clone-6)`, or not at all.

The check fails when
- a record lacks a field, or its date is not YYYY-MM-DD;
- a record's suite (scenes, combinations, mutants) is not the tree's: the
  figure was measured on another suite and is to be measured again;
- a link names no record, or its text states a number its record's figure
  does not;
- a page other than those two states a time (seconds, ms, minutes) outside
  such a link; settings ("default 120 s", `--timeout`) and code are not
  measurements;
- a section of docs/performance.md states a time with no date.

    check_measured_figures.py SOURCE_DIR [--records PAGE] [FILE ...]

FILE ...: check these Markdown files instead of README.md and docs/.
--records PAGE: read the records from PAGE instead of SOURCE_DIR's
docs/measurements.md (the tree's counts are still SOURCE_DIR's).
Exit 0 when every figure has its provenance; 1 otherwise, naming each.
"""
import os
import re
import sys

import measurement_records
from check_doc_counts import tree_counts
from doc_pages import pages, shown

TIME = re.compile(r'(?<![\w.\-/√])(\d[\d,]*(?:\.\d+)?)(?:-\d+(?:\.\d+)?)?(?:\s|-)?'
                  r'(ms|us|µs|s|secs?|seconds?|mins?|minutes?|h|hours?)\b(?![-(]\w|\()')
# What introduces a setting or a limit, not a measurement ("default 120 s",
# "a budget of 10 minutes", "up to 5 bakes within about 1 s").
SETTING = re.compile(r'(?:default|timeout|budget of|limit of|at most|at least|\d+ \w+ within|once for)'
                     r'(?: about)?\s*$', re.IGNORECASE)
UNITS = {'ms': 'ms', 'us': 'us', 'µs': 'us', 's': 's', 'sec': 's', 'secs': 's', 'second': 's', 'seconds': 's',
         'min': 'min', 'mins': 'min', 'minute': 'min', 'minutes': 'min', 'h': 'h', 'hour': 'h', 'hours': 'h'}


def times(text):
    """The (number, unit) pairs a text states as times."""
    return {(m.group(1).replace(',', ''), UNITS[m.group(2)]) for m in TIME.finditer(text)}
LINK = re.compile(r'\[([^\]]*)\]\(([^)\s]*measurements\.md)#([a-z0-9-]+)\)')
DATE = re.compile(r'\b20\d\d-\d\d-\d\d\b')
OWN_PAGES = ('measurements.md', 'performance.md')


def prose(text):
    """The text with code blocks, inline code and indented blocks blanked,
    keeping every offset."""
    text = re.sub(r'```.*?```', lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text, flags=re.DOTALL)
    text = re.sub(r'`[^`\n]*`', lambda m: ' ' * len(m.group(0)), text)
    return re.sub(r'(?m)^    .*$', lambda m: ' ' * len(m.group(0)), text)


def check_records(root, records, problems, page):
    t = tree_counts(root)
    tree = f'{t["scenes"]} scenes, {t["combinations"]} combinations, {t["mutants"]} mutants'
    for name, record in records.items():
        where = f'{shown(page, root)}:{record["line"]}: {name}'
        missing = [f for f in measurement_records.REQUIRED if not record.get(f)]
        if missing:
            problems.append(f'{where} has no {", ".join(missing)}')
        if record.get('date') and not re.fullmatch(r'20\d\d-\d\d-\d\d', record['date']):
            problems.append(f'{where}: date "{record["date"]}" is not YYYY-MM-DD')
        if record.get('suite') and record['suite'] != tree:
            problems.append(f'{where} was measured with {record["suite"]}; the tree has {tree}: measure it again '
                            f'(scripts/measure.py)')


def check_page(path, root, records, problems):
    name = os.path.basename(path)
    with open(path, encoding='utf-8') as f:
        text = f.read()
    plain = prose(text)
    quoted = []
    for m in LINK.finditer(text):
        quoted.append((m.start(), m.end()))
        line = text.count('\n', 0, m.start()) + 1
        record = records.get(m.group(3))
        if record is None:
            problems.append(f'{shown(path, root)}:{line}: "{m.group(0)}" names no record of docs/measurements.md')
            continue
        # A time is held to the record's times, unit and all; any other number
        # to the record's numbers.
        figure_text = record.get('figure', '')
        figure_times, figure = times(figure_text), measurement_records.numbers(figure_text)
        stated_times = times(m.group(1))
        timed = {n for n, _ in stated_times}
        wrong = [f'{n} {u}' for n, u in sorted(stated_times - figure_times)]
        wrong += [n for n in measurement_records.numbers(m.group(1)) if n not in timed and n not in figure]
        for n in wrong:
            problems.append(f'{shown(path, root)}:{line}: "{m.group(1)}" states {n}; the record {m.group(3)} '
                            f'says "{figure_text}"')
    if name == 'measurements.md':
        return 0
    stated = 0
    sections = [(s.start(), s.group(0)) for s in re.finditer(r'(?ms)^#{1,4} .*?(?=^#{1,4} |\Z)', text)] or [(0, text)]
    for m in TIME.finditer(plain):
        if any(a <= m.start() < b for a, b in quoted) or SETTING.search(plain[max(0, m.start() - 40):m.start()]):
            continue
        stated += 1
        line = text.count('\n', 0, m.start()) + 1
        if name == 'performance.md':
            section = next((s for start, s in reversed(sections) if start <= m.start()), '')
            if not DATE.search(section):
                problems.append(f'{shown(path, root)}:{line}: "{m.group(0)}" is a measured time in a section with no '
                                f'date ({section.split(chr(10), 1)[0][:60]})')
        else:
            problems.append(f'{shown(path, root)}:{line}: "{m.group(0)}" is a time stated by hand: quote its record '
                            f'of docs/measurements.md (a link to measurements.md#ID) or leave it out')
    return stated


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root, given = sys.argv[1], sys.argv[2:]
    page = os.path.join(root, 'docs', 'measurements.md')
    if given[:1] == ['--records'] and len(given) > 1:
        page, given = given[1], given[2:]
    with open(page, encoding='utf-8') as f:
        records = measurement_records.parse(f.read())
    problems = []
    check_records(root, records, problems, page)
    stated = sum(check_page(path, root, records, problems) for path in pages(root, given))
    for p in problems:
        print('FAIL:', p)
    if not problems:
        print(f'ok: {len(records)} records in {shown(page, root)}, each with its provenance and the tree\'s suite; '
              f'{stated} times stated on docs/performance.md, each in a dated section; every other time quotes a '
              f'record')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
