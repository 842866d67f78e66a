#!/usr/bin/env python3
"""Every count README.md and docs/ state about the tree agrees with the tree.

The counts are taken from the tree itself, not from lightcts: the scene
files per group (after configure, which writes the deferred variants), the
rows of backends/backend_combinations.def, of shaders/shader_interface.def
(mutants, admissible variants, G-buffer targets) and of the
expected-failures files. Each rule below is a phrase the docs use for one
count; every occurrence of it, in any file, must state the tree's number.
A measured figure that carries the suite's size ("measured with 164
scenes") is held to it too, so a change to the suite flags every
measurement it makes stale.

    check_doc_counts.py SOURCE_DIR [FILE ...]

FILE ...: check these Markdown files instead of README.md and docs/ (the
tree's counts are still SOURCE_DIR's).

Exit 0 when every stated count agrees; 1 otherwise, listing each with its
file, line, the stated and the tree's number.
"""
import glob
import os
import re
import sys

from doc_pages import pages, shown

WORDS = {'one': 1, 'two': 2, 'three': 3, 'four': 4, 'five': 5, 'six': 6, 'seven': 7, 'eight': 8, 'nine': 9,
         'ten': 10, 'eleven': 11, 'twelve': 12}
NUMBER = r'(?P<n>\d[\d,]*|' + '|'.join(WORDS) + ')'


def number(text):
    text = text.lower().replace(',', '')
    return WORDS[text] if text in WORDS else int(text)


def rows(path, macro):
    with open(path, encoding='utf-8') as f:
        return [line for line in f if line.startswith(macro + '(')]


def tree_counts(root):
    scenes = os.path.join(root, 'suite', 'scenes')
    groups = {g: len(glob.glob(os.path.join(scenes, g, '*.json')))
              for g in sorted(os.listdir(scenes)) if os.path.isdir(os.path.join(scenes, g))}
    combinations = [re.match(r'LIGHTCTS_COMBINATION\("([a-z0-9-]+)"', line).group(1)
                    for line in rows(os.path.join(root, 'backends', 'backend_combinations.def'), 'LIGHTCTS_COMBINATION')]
    interface = os.path.join(root, 'shaders', 'shader_interface.def')
    admissible = rows(interface, 'LIGHTCTS_ADMISSIBLE')
    expected = {c: 0 for c in combinations}
    for path in glob.glob(os.path.join(root, 'suite', 'expected-failures', '*.txt')):
        with open(path, encoding='utf-8') as f:
            for line in f:
                test = line.split('#', 1)[0].split(',', 1)[0].strip()
                if test and '@' not in test:
                    expected[test.rsplit('.', 1)[1]] = expected.get(test.rsplit('.', 1)[1], 0) + 1
    return {
        'groups': groups,
        'scenes': sum(groups.values()),
        'combinations': len(combinations),
        'combination names': combinations,
        'mutants': len(rows(interface, 'LIGHTCTS_MUTANT')),
        'admissible variants': len(admissible),
        'realised admissible variants': sum(1 for line in admissible if ', none,' not in line),
        'g-buffer targets': sum(1 for line in rows(interface, 'LIGHTCTS_TEXTURE') if '(gbuffer' in line),
        'expected failures': expected,
    }


def rules(t):
    """(pattern, what it counts, the tree's number or a function of the match)."""
    out = [
        (NUMBER + r' scenes in all', 'suite scenes', t['scenes']),
        # In digits, "N scenes" is the suite's size; a part of it is written
        # otherwise ("two scenes", "60 of the scenes").
        (r'(?P<n>\d[\d,]*) (?:suite )?scenes\b', 'suite scenes', t['scenes']),
        (NUMBER + r' tests on the \w+ combinations', 'scene tests (scenes x combinations)',
         t['scenes'] * t['combinations']),
        # The combinations in all: in digits anywhere, in words after "all",
        # "on", "the", "in" or "over" ("these two combinations" is a part).
        (r'\b(?P<n>\d+) (?:backend )?combinations\b', 'backend combinations', t['combinations']),
        (r'(?<!these )\b(?:all|on|the|in|over) ' + NUMBER + r' (?:backend )?combinations\b', 'backend combinations',
         t['combinations']),
        (NUMBER + r' (?:deliberately wrong variants|mutants)\b', 'mutants', t['mutants']),
        (r'\b' + NUMBER + r'/\d+ \|', 'mutants killed (the status table)', t['mutants']),
        (r'\b\d+/' + NUMBER + r' \|', 'mutants (the status table)', t['mutants']),
        (NUMBER + r' admissible variants\b', 'admissible variants', t['admissible variants']),
        (NUMBER + r' realised\b', 'realised admissible variants', t['realised admissible variants']),
        (NUMBER + r' (?:RGBA32F )?(?:G-buffer )?targets\b', 'G-buffer targets', t['g-buffer targets']),
    ]
    for group, count in t['groups'].items():
        # The README's group table: group | scenes | what it checks.
        out.append((r'^\| `' + re.escape(group) + r'` \| ' + NUMBER + r' \| [A-Za-z]', f'scenes of the {group} group',
                    count))
    for name in t['combination names']:
        ef = t['expected failures'].get(name, 0)
        # The README's status table: combination | API | driver | scenes | mutants killed.
        row = r'^\| `' + re.escape(name) + r'` \|[^|]*\|[^|]*\| '
        out.append((row + NUMBER + r' Pass[^|]*\| \d+/\d+ \|$',
                    f'scenes {name} passes (scenes less its expected failures)', t['scenes'] - ef))
        out.append((row + r'[^|]*?' + NUMBER + r' ExpectedFail[^|]*\| \d+/\d+ \|$', f'expected failures of {name}', ef))
    return out


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    t = tree_counts(root)
    checks = [(re.compile(p, re.IGNORECASE | re.MULTILINE), what, n) for p, what, n in rules(t)]
    problems, checked = [], 0
    for path in pages(root, sys.argv[2:]):
        with open(path, encoding='utf-8') as f:
            text = f.read()
        seen = set()
        for pattern, what, expected in checks:
            for m in pattern.finditer(text):
                if m.start('n') in seen:
                    continue  # a more specific rule above took this number
                seen.add(m.start('n'))
                checked += 1
                stated = number(m.group('n'))
                if stated != expected:
                    line = text.count('\n', 0, m.start()) + 1
                    problems.append(f'{shown(path, root)}:{line}: "{m.group(0).strip()}" states {stated} '
                                    f'{what}; the tree has {expected}')
    for p in problems:
        print('FAIL:', p)
    if not problems:
        print(f'ok: {checked} counts in README.md and docs/ agree with the tree '
              f'({t["scenes"]} scenes, {t["combinations"]} combinations, {t["mutants"]} mutants)')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
