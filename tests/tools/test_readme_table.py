#!/usr/bin/python3
"""bench/common/readme_table.py, the README's table of measured numbers: it runs on the committed
benchmark data and README.md holds exactly what it generates (so the README cannot drift from
the data); without data every number reads "not measured"; the README stays plain (no issue
numbers, no "new measure") and shows the two commands.

    test_readme_table.py SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

source, work = sys.argv[1:3]
script = os.path.join(source, 'bench', 'common', 'readme_table.py')
sys.path.insert(0, os.path.dirname(script))
import readme_table  # noqa: E402

failures = []


def check(condition, what):
    print(('ok   ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


# On the committed data: the block has its rows, and README.md holds it as generated.
block = readme_table.block(source)
rows = [line for line in block.splitlines() if line.startswith('| ')]
check(len(rows) >= 8, f'the table has its rows ({len(rows)})')
check(all(line.count('|') == 7 for line in rows), 'every row has six cells')
check(readme_table.MISSING not in ''.join(rows[2:6]),
      'the real-footage rows are measured in the committed data')
check(any(re.search(r'\| \d+\.\d \|', line) for line in rows if 'DAVIS' in line),
      'the DAVIS rows are measured in the committed data')
check('object model' in block, 'the note names the object model DAVIS measured')
done = subprocess.run([sys.executable, script, '--check', '--root', source], capture_output=True,
                      text=True, timeout=300)
print(done.stdout.strip())
check(done.returncode == 0, 'README.md holds the table generated from the committed data '
      '(bench/common/readme_table.py rewrites it)')

# A README whose table differs is caught; rewriting it makes the check pass.
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
stale = os.path.join(work, 'README.md')
with open(stale, 'w') as f:
    f.write(f'# x\n\n{readme_table.BEGIN}\n| typed | by | hand |\n{readme_table.END}\n')
args = [sys.executable, script, '--root', source, '--readme', stale]
check(subprocess.run(args + ['--check'], capture_output=True, timeout=300).returncode == 1,
      'a table typed by hand fails the check')
subprocess.run(args, check=True, capture_output=True, timeout=300)
check(subprocess.run(args + ['--check'], capture_output=True, timeout=300).returncode == 0,
      'after a rewrite the check passes')

# Without any data: every number reads "not measured", nothing fails.
empty = os.path.join(work, 'empty')
os.makedirs(os.path.join(empty, 'docs'))
none = readme_table.block(empty)
cells = [c.strip() for line in none.splitlines() if line.startswith('| ') and '---' not in line
         for c in line.strip('|').split('|')[2:]][4:]  # the cells, past the header's
check(cells and all(c in (readme_table.MISSING, readme_table.DASH) for c in cells),
      f'without data every cell reads "{readme_table.MISSING}" (or "{readme_table.DASH}")')

# The README itself: plain words, the two commands.
readme = open(os.path.join(source, 'README.md')).read()
check(not re.search(r'\bissues? #?\d|#\d+\b', readme), 'no issue numbers in README.md')
check('new measure' not in readme, 'no "new measure" in README.md')
check('./run demo' in readme and './run test' in readme, 'README.md shows ./run demo and ./run test')
check(len(readme.split()) <= 2000, f'README.md is at most 2000 words ({len(readme.split())})')

print(f'{len(failures)} failures')
sys.exit(1 if failures else 0)
