#!/usr/bin/env python3
"""Every "SPEC x" and "SPEC x.y" the tree cites names a section of
docs/specification.md, and no file of the tree points outside it to a
specification (a path through ../shared): a reader of a message or a comment
has the text to open in the clone.

    check_spec_citations.py SOURCE_DIR

Exit 0 when every citation resolves; 1 otherwise, listing each one that does
not, with its file and line.
"""
import os
import re
import sys

SKIP_DIRS = {'.git', 'build', 'lightcts-evidence'}
TEXT = ('.cpp', '.h', '.glsl', '.frag', '.vert', '.cmake', '.txt', '.md', '.py', '.sh', '.json', '.def', '.html',
        '.js', '.in', '.yml', '.yaml')


def sections(spec_path):
    numbers = set()
    with open(spec_path, encoding='utf-8') as f:
        for line in f:
            m = re.match(r'#{2,3} (\d+(?:\.\d+)?)\.? ', line)
            if m:
                numbers.add(m.group(1))
    return numbers


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    known = sections(os.path.join(root, 'docs', 'specification.md'))
    if not known:
        print('FAIL: docs/specification.md has no numbered sections')
        return 1
    citation = re.compile(r'\bSPEC (\d+(?:\.\d+)?)\b')
    outside = re.compile(r'\.\./shared\b|shared/SPEC\.md')
    problems, cited = [], 0
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith('build')]
        for name in files:
            if not name.endswith(TEXT) and name not in ('CMakeLists.txt', 'README'):
                continue
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            try:
                with open(path, encoding='utf-8') as f:
                    lines = f.readlines()
            except (UnicodeDecodeError, OSError):
                continue
            for number, line in enumerate(lines, 1):
                if rel != os.path.join('docs', 'check_spec_citations.py') and outside.search(line):
                    problems.append('%s:%d: points outside the tree: %s' % (rel, number, line.strip()[:100]))
                for m in citation.finditer(line):
                    cited += 1
                    if m.group(1) not in known:
                        problems.append('%s:%d: SPEC %s is no section of docs/specification.md' %
                                        (rel, number, m.group(1)))
    for p in problems:
        print('FAIL: ' + p)
    print('%d citations of %d sections checked, %d problems' % (cited, len(known), len(problems)))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
