#!/usr/bin/python3
"""Prints one line 'N passed, N failed[, N skipped]' from meson's test logs.

    count_results.py LOGDIR [LOGDIR ...] [--extra NAME=EXITCODE ...]

GoogleTest executables count each test case (from the JUnit log); any other meson test counts
once. A test executable that failed without a failing case counts one failure. One that did not run
to its end (a timeout, or killed by a signal) counts one failure and none of its cases: it wrote no
XML of its own, so any cases meson found are an earlier run's. A log directory without results
counts one failure (the build or the run did not happen). Each --extra counts one test: passed
when its exit code is 0.
"""
import json
import sys
import xml.etree.ElementTree as ET


def count(logs):
    """(passed, failed, skipped) of one meson build's test run."""
    try:
        runs = [json.loads(line) for line in open(f'{logs}/testlog.json') if line.strip()]
        suites = ET.parse(f'{logs}/testlog.junit.xml').getroot().iter('testsuite')
    except (OSError, ValueError, ET.ParseError) as e:
        print(f'no test results in {logs} ({e})', file=sys.stderr)
        return 0, 1, 0
    cases = {}  # meson test name -> [passed, failed, skipped] from its GoogleTest cases
    names = {run['name'] for run in runs}
    for suite in suites:
        # meson names a GoogleTest suite '<project>.<test name>.<GoogleTest suite>'.
        name = suite.get('name', '')
        test = next((t for t in names if name.startswith(f'{t.split(":")[0]}.{t}.')), None)
        if test is None:
            continue  # meson's own per-test suite, counted from testlog.json below
        c = cases.setdefault(test, [0, 0, 0])
        for case in suite.iter('testcase'):
            if case.find('failure') is not None or case.find('error') is not None:
                c[1] += 1
            elif case.find('skipped') is not None or case.get('status') == 'notrun':
                c[2] += 1
            else:
                c[0] += 1
    passed = failed = skipped = 0
    for run in runs:
        ok = run['result'] in ('OK', 'EXPECTEDFAIL')
        skip = run['result'] == 'SKIP'
        unfinished = run['result'] == 'TIMEOUT' or (run.get('returncode') or 0) < 0
        if run['name'] in cases and not unfinished:
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
    return passed, failed, skipped


def main(argv):
    dirs, extras = [], []
    args = iter(argv)
    for a in args:
        if a == '--extra':
            name, _, code = next(args).partition('=')
            extras.append((name, code))
        else:
            dirs.append(a)
    total = [0, 0, 0]
    for d in dirs or ['build/meson-logs']:
        for i, n in enumerate(count(d)):
            total[i] += n
    for name, code in extras:
        total[0 if code == '0' else 1] += 1
        if code != '0':
            print(f'{name} failed (exit code {code})', file=sys.stderr)
    passed, failed, skipped = total
    print(f'{passed} passed, {failed} failed' + (f', {skipped} skipped' if skipped else ''))


main(sys.argv[1:])
