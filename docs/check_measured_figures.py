#!/usr/bin/env python3
"""Every measured figure README.md and docs/ state carries its provenance:
a section (a heading and what follows it up to the next heading) that says
something took, takes, costs or was measured in a time (seconds, ms,
minutes) names the date of that measurement (YYYY-MM-DD), beside the
machine and the command it was taken with. A figure without a date cannot
be told stale; write the date, or do not repeat the figure and point to the
section that has it.

    check_measured_figures.py SOURCE_DIR [FILE ...]

FILE ...: check these Markdown files instead of README.md and docs/.
Exit 0 when every such section has a date; 1 otherwise, naming each.
"""
import re
import sys

from doc_pages import pages, shown

# A time stated as what something took or costs; "default 120 s" and code
# blocks are settings and examples, not measurements.
MEASURED = re.compile(r'\b(?:took|takes|measured|ran in|costs?)\b[^.]*?(?<!default )\b\d+(?:\.\d+)?\s?'
                      r'(?:s|ms|minutes|seconds)\b', re.IGNORECASE)
DATE = re.compile(r'\b20\d\d-\d\d-\d\d\b')


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    problems, sections = [], 0
    for path in pages(root, sys.argv[2:]):
        with open(path, encoding='utf-8') as f:
            text = f.read()
        prose = re.sub(r'```.*?```', lambda m: '\n' * m.group(0).count('\n'), text, flags=re.DOTALL)
        offset = 0
        for section in re.split(r'\n(?=#{1,4} )', prose):
            lines = section.split('\n')
            if lines[0].startswith('#'):
                lines[0] = ''  # the heading names a subject ("Cost"), not a measurement
            body = '\n'.join('' if line.startswith('    ') else line for line in lines)
            m = MEASURED.search(body)
            if m:
                sections += 1
                if not DATE.search(section):
                    line = text.count('\n', 0, offset + m.start()) + 1
                    name = shown(path, root)
                    problems.append(f'{name}:{line}: "{m.group(0)}" is a measured time in a section with no date '
                                    f'({section.split(chr(10), 1)[0][:60]})')
            offset += len(section) + 1
    for p in problems:
        print('FAIL:', p)
    if not problems:
        print(f'ok: each of the {sections} sections of README.md and docs/ that state a measured time has a date')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
