#!/usr/bin/env python3
"""docs/cli.md documents the whole command line: every subcommand and every
option that `lightcts --help-all` prints (and each nested subcommand's
--help) appears in the section of docs/cli.md headed by that subcommand
("## `lightcts run`"; a heading may name several), and every option that
docs/cli.md names exists on some lightcts subcommand, so neither can drift
from the other.

    check_cli_documented.py LIGHTCTS CLI_MD

Exit 0 when both directions hold; 1 otherwise, listing each difference.
"""
import re
import subprocess
import sys

OPTION = re.compile(r'(?<![\w-])(--[a-z][a-z0-9-]*)')
# Options docs/cli.md names that belong to other programs it shows beside
# lightcts, each with the program.
OTHER_PROGRAMS = {
    '--preset': 'cmake and ctest',
    '--output-junit': 'ctest',
    '--output-on-failure': 'ctest',
    '--benchmark_filter': 'Google Benchmark',
}


def help_text(lightcts, *words):
    done = subprocess.run([lightcts, *words], capture_output=True, text=True, timeout=60)
    if done.returncode != 0:
        sys.exit(f'FAIL: {" ".join([lightcts, *words])} exited {done.returncode}: {done.stderr.strip()}')
    return done.stdout


def options_of(block):
    """The long options of one subcommand's block of help text."""
    found = set()
    for line in block.splitlines():
        m = re.match(r'\s+(?:-\w,)?(--[a-z][a-z0-9-]*)', line)
        if m and m.group(1) not in ('--help', '--help-all'):
            found.add(m.group(1))
    return found


def commands(lightcts):
    """{'run': {'--backend', ...}, 'run compare': {...}, ...} from --help-all."""
    text = help_text(lightcts, '--help-all')
    body = text.split('\nSubcommands:\n', 1)[1]
    result = {}
    # A subcommand's block starts with its name at the start of a line.
    for block in re.split(r'\n(?=[a-z])', body.strip('\n')):
        name = block.split('\n', 1)[0].strip()
        result[name] = options_of(block.split('  Subcommands:')[0])
        if '  Subcommands:' in block:
            for line in block.split('  Subcommands:', 1)[1].splitlines():
                m = re.match(r'\s+([a-z][a-z-]*)\s', line)
                if m:
                    nested = f'{name} {m.group(1)}'
                    result[nested] = options_of(help_text(lightcts, name, m.group(1), '--help'))
    return result


def sections(cli_md):
    """[(set of subcommands a heading names, its text)] of docs/cli.md."""
    out = []
    for part in re.split(r'\n(?=## )', open(cli_md, encoding='utf-8').read()):
        heading = part.split('\n', 1)[0]
        named = set(re.findall(r'`lightcts ([a-z][a-z -]*?)`', heading)) if heading.startswith('## ') else set()
        out.append((named, part))
    return out


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    lightcts, cli_md = sys.argv[1:]
    known = commands(lightcts)
    every_option = set().union(*known.values()) | {'--help', '--help-all'}
    parts = sections(cli_md)
    problems = []
    for command, options in sorted(known.items()):
        texts = [text for named, text in parts if command in named]
        if not texts:
            problems.append(f'`lightcts {command}` has no section of docs/cli.md (a heading "## `lightcts {command}`")')
            continue
        mentioned = set(OPTION.findall('\n'.join(texts)))
        for option in sorted(options - mentioned):
            problems.append(f'`lightcts {command} {option}` is not in its section of docs/cli.md')
    for named, text in parts:
        for option in sorted(set(OPTION.findall(text)) - every_option - set(OTHER_PROGRAMS)):
            where = ', '.join(f'`lightcts {n}`' for n in sorted(named)) or 'its introduction'
            problems.append(f'docs/cli.md names {option} (in the section of {where}), which no lightcts subcommand has')
    for p in problems:
        print('FAIL:', p)
    if not problems:
        print(f'ok: {len(known)} subcommands, {sum(len(o) for o in known.values())} options, each in docs/cli.md; '
              'every option docs/cli.md names exists')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
