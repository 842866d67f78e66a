"""The records of docs/measurements.md: read and written by one module, so
the page's writer (scripts/measure.py) and its check
(check_measured_figures.py) agree on its form.

A record is a `## id` heading, a line that says what was measured, and a
two-column table of fields:

    ## fresh-clone

    `.ci/run` in a fresh clone, every cache empty.

    | field | value |
    |---|---|
    | figure | 15.4 min in all; build 470 s; ctest 457 s |
    | date | 2026-12-06 |
    ...

Prose elsewhere quotes a record through a link to its anchor,
`[N minutes](measurements.md#fresh-clone-6)`, and the check holds every
number of the link's text to the record's figure.
"""
import re

# The fields every record has, in the order they are written.
FIELDS = ['figure', 'labels', 'date', 'commit', 'machine', 'load', 'command', 'suite']
REQUIRED = ['figure', 'date', 'commit', 'machine', 'command']
HEADING = re.compile(r'^## ([a-z0-9][a-z0-9-]*)\s*$', re.MULTILINE)
ANY_HEADING = re.compile(r'^#{1,6} ', re.MULTILINE)


def record_end(text, start):
    """Where the record whose heading starts at `start` ends: at the next
    heading of any kind, so text under another heading is never taken."""
    following = ANY_HEADING.search(text, text.index('\n', start) + 1 if '\n' in text[start:] else len(text))
    return following.start() if following else len(text)
ROW = re.compile(r'^\| (\w+) \| (.*) \|\s*$')  # a value's own '|' is written '\|'


def parse(text):
    """{id: {'what': str, field: value, 'line': line number}}, in page order."""
    records = {}
    for head in HEADING.finditer(text):
        body = text[head.end():record_end(text, head.start())]
        record = {'line': text.count('\n', 0, head.start()) + 1, 'what': ''}
        for line in body.strip().split('\n'):
            row = ROW.match(line)
            if row and row.group(1) in FIELDS:
                record[row.group(1)] = row.group(2).strip().replace('\\|', '|')
            elif line and not line.startswith('|') and not record['what']:
                record['what'] = line.strip()
        records[head.group(1)] = record
    return records


def format_record(name, record):
    lines = [f'## {name}', '', record['what'], '', '| field | value |', '|---|---|']
    lines += [f'| {f} | {record[f].replace("|", chr(92) + "|")} |' for f in FIELDS if record.get(f)]
    return '\n'.join(lines) + '\n'


def replace_record(text, name, record):
    """The page with the record `name` replaced, or added at the end."""
    new = format_record(name, record)
    for head in HEADING.finditer(text):
        if head.group(1) == name:
            end = record_end(text, head.start())
            return text[:head.start()] + new + ('\n' if end < len(text) else '') + text[end:]
    return text.rstrip('\n') + '\n\n' + new


def numbers(text):
    """The numbers a text states, as written without thousands commas."""
    return [n.replace(',', '') for n in re.findall(r'\d[\d,]*(?:\.\d+)?', text)]
