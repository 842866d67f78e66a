#!/usr/bin/env python3
"""Splits a `lightcts run`'s results.json into one file per test, for the
scene and mutant tests of ctest (suite/scene_tests.cmake,
suite/mutant_tests.cmake): OUT/<test>.txt holds one line, `<raw_verdict>
<test>: <message or numbers>`, then the evidence page of a failure; each
mutant of the run's mutation check gets OUT/mutants.<mutant>.<combination>.txt,
`<status> mutants.<mutant>.<combination>: killed by ... (killers ...)`. A
combination that is not here still has its results.json (`run` writes it
before it exits 3), each test and mutant NotSupported.

    scene_run_verdicts.py RUN_DIR OUT_DIR

Exit 0 when the files are written; 1 when the run left nothing to read.
"""
import os
import sys

import results_json


def line_of(test):
    metrics = test.get('metrics') or {}
    detail = test.get('message') or ''
    if not detail and metrics:
        detail = '%s failing of %s compared pixels (%s masked), max error %s, tightness %s' % (
            metrics.get('failing_pixels'), metrics.get('compared_pixels'), metrics.get('masked_pixels'),
            metrics.get('max_abs_error'), metrics.get('tightness'))
    text = '%s %s: %s\n' % (test.get('raw_verdict', 'Crash'), test['name'], detail)
    evidence = test.get('evidence') or {}
    if evidence.get('viewer'):
        text += 'evidence: %s\n' % evidence['viewer']
    return text


def mutant_line(name, mutant):
    text = '%s %s: killed by %s (its killers: %s)\n' % (
        mutant.get('status', 'Crash'), name, ', '.join(mutant.get('killed_by') or []) or 'none',
        ', '.join(mutant.get('killers') or []))
    evidence = mutant.get('evidence') or {}
    if evidence.get('viewer'):
        text += 'evidence: %s\n' % evidence['viewer']
    return text


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    run_dir, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    results_path = os.path.join(run_dir, 'results.json')
    if not os.path.exists(results_path):
        print('no results.json in %s: the run did not finish' % run_dir)
        return 1
    results = results_json.load(results_path)
    for test in results['tests']:
        with open(os.path.join(out_dir, test['name'] + '.txt'), 'w') as f:
            f.write(line_of(test))
    mutants = results.get('mutants') or []
    for mutant in mutants:
        name = 'mutants.%s.%s' % (mutant['mutant'], mutant['backend'])
        with open(os.path.join(out_dir, name + '.txt'), 'w') as f:
            f.write(mutant_line(name, mutant))
    print('%d verdicts and %d mutant statuses in %s' % (len(results['tests']), len(mutants), out_dir))
    return 0


if __name__ == '__main__':
    sys.exit(main())
