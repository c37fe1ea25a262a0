#!/usr/bin/env python3
"""Counts test cases in catkin's JUnit results and prints "N passed, N failed".

gtest 1.12 nests suites, so catkin_test_results counts each case twice; here every
(file, class, name) counts once. Failed cases are listed above the closing line.
"""
import pathlib
import sys
import xml.etree.ElementTree as ET


def main(results_dir):
    cases = {}
    broken = []
    for path in sorted(pathlib.Path(results_dir).rglob('*.xml')):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as error:
            broken.append(f'{path}: unreadable result file ({error})')
            continue
        for case in root.iter('testcase'):
            key = (path.name, case.get('classname', ''), case.get('name', ''))
            bad = case.find('failure') is not None or case.find('error') is not None
            skipped = case.find('skipped') is not None or case.get('status') == 'notrun'
            cases[key] = 'failed' if bad else ('skipped' if skipped else cases.get(key, 'passed'))
    counts = {state: sum(1 for s in cases.values() if s == state) for state in ('passed', 'failed', 'skipped')}
    for (name, cls, test), state in sorted(cases.items()):
        if state == 'failed':
            print(f'FAILED: {name} {cls}.{test}')
    for line in broken:
        print(f'FAILED: {line}')
    failed = counts['failed'] + len(broken)
    line = f"{counts['passed']} passed, {failed} failed"
    if counts['skipped']:
        line += f", {counts['skipped']} skipped"
    print(line)
    return 1 if failed or not cases else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else 'build/test_results'))
