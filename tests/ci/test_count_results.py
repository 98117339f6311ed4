#!/usr/bin/python3
"""CI's closing count (.ci/count_results.py) on meson logs written here: GoogleTest cases are
counted one by one, and a test that timed out or was killed counts one failure and none of the
cases meson found for it (a stale XML from an earlier run).

    test_count_results.py COUNT_RESULTS_PY WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

script, work = sys.argv[1:3]


def junit_suite(test, suite, passed, failed):
    cases = ''.join(f'<testcase name="p{i}" classname="{suite}"/>' for i in range(passed))
    cases += ''.join(f'<testcase name="f{i}" classname="{suite}"><failure message="x"/></testcase>'
                     for i in range(failed))
    return f'<testsuite name="projtrack.{test}.{suite}">{cases}</testsuite>'


def logs(name, runs, suites):
    """A meson-logs folder: testlog.json (one run per line) and testlog.junit.xml."""
    d = os.path.join(work, name)
    os.makedirs(d)
    with open(os.path.join(d, 'testlog.json'), 'w') as f:
        for test, result, code in runs:
            f.write(json.dumps({'name': test, 'result': result, 'returncode': code}) + '\n')
    with open(os.path.join(d, 'testlog.junit.xml'), 'w') as f:
        f.write('<testsuites>' + ''.join(suites) + '<testsuite name="projtrack"/></testsuites>')
    return d


def count(*dirs):
    out = subprocess.run([script, *dirs], check=True, capture_output=True, text=True, timeout=60)
    return out.stdout.strip()


shutil.rmtree(work, ignore_errors=True)
GT, PY = 'projtrack:lib / test_a', 'projtrack:bench+python / b.quick'
# Finished runs: five cases of a GoogleTest executable, one Python test.
fresh = logs('fresh', [(GT, 'OK', 0), (PY, 'OK', 0)], [junit_suite(GT, 'A', 3, 0),
                                                        junit_suite(GT, 'B', 2, 0)])
assert count(fresh) == '6 passed, 0 failed', count(fresh)
# A failing case is one failure; the executable's own non-zero exit adds none.
failing = logs('failing', [(GT, 'FAIL', 1), (PY, 'FAIL', 1)], [junit_suite(GT, 'A', 4, 1)])
assert count(failing) == '4 passed, 2 failed', count(failing)
# Timed out or killed: whatever cases meson read are an earlier run's; one failure, no passes.
for result, code in [('TIMEOUT', -15), ('FAIL', -11), ('TIMEOUT', 0)]:
    stale = logs(f'stale{result}{-code}', [(GT, result, code)], [junit_suite(GT, 'A', 7, 0)])
    assert count(stale) == '0 passed, 1 failed', (result, code, count(stale))
# A test whose name shares a prefix with another's does not take its cases.
prefix = logs('prefix', [(GT, 'OK', 0), (GT + '_more', 'OK', 0)],
              [junit_suite(GT + '_more', 'A', 3, 0)])
assert count(prefix) == '4 passed, 0 failed', count(prefix)
# No results at all (the build failed): one failure; logs add up across folders.
assert count(os.path.join(work, 'missing')) == '0 passed, 1 failed'
assert count(fresh, failing) == '10 passed, 2 failed', count(fresh, failing)
print('count_results: ok')
