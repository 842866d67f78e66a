#!/usr/bin/env python3
"""The docs checks can fail: each is run on a copy with one deliberately
wrong line, and must exit 1 naming it.

- check_doc_counts.py on a page that states one scene too many and six
  combinations;
- check_cli_documented.py on docs/cli.md with `--sharpness` renamed to
  `--sharpnes` (an undocumented option and a documented one that does not
  exist, both directions at once);
- check_measured_figures.py on a page that types a run's time by hand, one
  whose link to a record states another number and one another unit, and a
  record measured on a suite one scene smaller than the tree's.

    check_docs_catch_errors.py LIGHTCTS SOURCE_DIR

Exit 0 when every check fails as it must; 1 otherwise.
"""
import glob
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def expect_failure(what, command, must_say):
    done = subprocess.run(command, capture_output=True, text=True, timeout=120)
    said = done.stdout + done.stderr
    missing = [m for m in must_say if m not in said]
    if done.returncode != 1 or missing:
        print(f'FAIL: {what}: exit {done.returncode}, missing {missing} in:\n{said}')
        return False
    print(f'ok: {what}:\n{said.strip()}')
    return True


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    lightcts, root = sys.argv[1:]
    # The suite's size counted here, not taken from the check under test.
    scenes = len(glob.glob(os.path.join(root, 'suite', 'scenes', '*', '*.json')))
    with tempfile.TemporaryDirectory() as tmp:
        page = os.path.join(tmp, 'wrong.md')
        with open(page, 'w', encoding='utf-8') as f:
            f.write(f'{scenes + 1} scenes in all, so many tests on the six combinations.\n')
        ok = expect_failure('a count one too many', [sys.executable, os.path.join(HERE, 'check_doc_counts.py'), root,
                                                     page],
                            [f'states {scenes + 1} suite scenes', 'states 6 backend combinations'])
        cli = os.path.join(tmp, 'cli.md')
        with open(os.path.join(root, 'docs', 'cli.md'), encoding='utf-8') as f:
            text = f.read()
        with open(cli, 'w', encoding='utf-8') as f:
            f.write(text.replace('--sharpness', '--sharpnes'))
        ok = expect_failure('an option renamed in docs/cli.md',
                            [sys.executable, os.path.join(HERE, 'check_cli_documented.py'), lightcts, cli],
                            ['`lightcts run --sharpness` is not in its section', 'docs/cli.md names --sharpnes']) and ok
        records = os.path.join(tmp, 'measurements.md')
        with open(records, 'w', encoding='utf-8') as f:
            f.write('# Measured figures\n\n## whole-run\n\nThe whole run.\n\n| field | value |\n|---|---|\n'
                    '| figure | 94 s |\n| date | 2026-12-06 |\n| commit | 0000000 |\n| machine | 2 cores |\n'
                    f'| command | `time scripts/run.sh` |\n| suite | {scenes - 1} scenes, 7 combinations, 33 mutants |\n')
        by_hand = os.path.join(tmp, 'by-hand.md')
        with open(by_hand, 'w', encoding='utf-8') as f:
            f.write('## Cost\n\nThe whole run took 94 s on two cores (2026-12-06), '
                    'or [95 s](measurements.md#whole-run), or [94 min](measurements.md#whole-run).\n')
        ok = expect_failure('a time typed by hand, a wrong quote and a stale record',
                            [sys.executable, os.path.join(HERE, 'check_measured_figures.py'), root,
                             '--records', records, by_hand],
                            ['"94 s" is a time stated by hand', '"95 s" states 95 s; the record whole-run says "94 s"',
                             '"94 min" states 94 min; the record whole-run says "94 s"',
                             f'whole-run was measured with {scenes - 1} scenes, 7 combinations, 33 mutants; '
                             f'the tree has {scenes} scenes']) and ok
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
