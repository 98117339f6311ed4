#!/usr/bin/python3
"""Prints one line 'N passed, N failed[, N skipped]' from meson's test logs.

GoogleTest executables count each test case (from the JUnit log); any other meson test counts
once. A test executable that failed without a failing case (a crash, a timeout) counts one failure.
"""
import json
import sys
import xml.etree.ElementTree as ET

logs = sys.argv[1] if len(sys.argv) > 1 else 'build/meson-logs'
passed = failed = skipped = 0
try:
    runs = [json.loads(line) for line in open(f'{logs}/testlog.json') if line.strip()]
    suites = ET.parse(f'{logs}/testlog.junit.xml').getroot().iter('testsuite')
except (OSError, ValueError, ET.ParseError) as e:
    print(f'no test results ({e})', file=sys.stderr)
    print('0 passed, 1 failed')
    sys.exit(0)

cases = {}  # meson test name -> [passed, failed, skipped] from its GoogleTest cases
for suite in suites:
    parts = suite.get('name', '').split('.')
    if len(parts) < 3:
        continue  # meson's own per-test suite, counted from testlog.json below
    count = cases.setdefault(parts[1], [0, 0, 0])
    for case in suite.iter('testcase'):
        if case.find('failure') is not None or case.find('error') is not None:
            count[1] += 1
        elif case.find('skipped') is not None or case.get('status') == 'notrun':
            count[2] += 1
        else:
            count[0] += 1

for run in runs:
    ok = run['result'] in ('OK', 'EXPECTEDFAIL')
    skip = run['result'] == 'SKIP'
    if run['name'] in cases:
        p, f, s = cases[run['name']]
        passed, failed, skipped = passed + p, failed + f, skipped + s
        if not ok and not skip and f == 0:
            failed += 1
    elif ok:
        passed += 1
    elif skip:
        skipped += 1
    else:
        failed += 1

line = f'{passed} passed, {failed} failed'
print(line + (f', {skipped} skipped' if skipped else ''))
