"""The pages the docs checks read (check_doc_counts.py,
check_measured_figures.py): README.md and docs/*.md, or the files a check
was given instead. The specification is left out: its numbers are the
model's (4 directional lights, 64 others), not counts or measurements of
the tree."""
import glob
import os


def pages(root, given):
    if given:
        return list(given)
    paths = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))
    return [p for p in paths if not p.endswith('specification.md')]


def shown(path, root):
    """A page's name in a message: relative to the tree when inside it."""
    return os.path.relpath(path, root) if os.path.abspath(path).startswith(os.path.abspath(root)) else path
