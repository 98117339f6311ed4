#!/usr/bin/python3
"""./run as a user meets it: `./run help` names every command, every demo option, every build
option and every environment variable the script reads; each command installs only what it
needs (`./run packages <command>`). Usage: test_run.py SOURCE_DIR"""
import os
import re
import subprocess
import sys

source = sys.argv[1]
run = os.path.join(source, 'run')
failures = []


def check(condition, what):
    print(('ok   ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


def output(*args):
    return subprocess.run([run, *args], check=True, capture_output=True, text=True).stdout


help_text = output('help')
script = open(run).read()
commands = re.findall(r'^  ([a-z]+)(?: \| [^)]*)?\) shift;|^  ([a-z]+)\) packages_for', script, re.M)
commands = {a or b for a, b in commands}
check(len(commands) >= 6, f'the commands: {sorted(commands)}')
for c in sorted(commands):
    check(re.search(rf'^  {c}\b', help_text, re.M) is not None, f'help names the command {c}')
demo = open(os.path.join(source, 'examples', 'demo.py')).read()
for option in re.findall(r"add_argument\('(--[a-z-]+)'", demo):
    check(option in help_text, f'help names the demo option {option}')
for option in re.findall(r"^option\('([a-z_-]+)'", open(os.path.join(source, 'meson_options.txt')).read(), re.M):
    check('-D' + option in help_text, f'help names the build option -D{option}')
for variable in sorted(set(re.findall(r'\$\{([A-Z_]+):-', script))):
    check(variable in help_text, f'help names the environment variable {variable}')

packages = {c: set(output('packages', c).split())
            for c in ['build', 'test', 'demo', 'fuzz', 'bench', 'real', 'speed', 'davis']}
heavy = {'clang', 'libclang-rt-14-dev', 'python3-matplotlib', 'libgtest-dev', 'opencv-doc'}
check(not packages['demo'] & heavy, f'the demo installs none of {sorted(heavy)}: '
      f'{sorted(packages["demo"] & heavy)}')
check(not packages['build'] & heavy, 'a build installs none of them either')
real = set(re.search(r'^REAL_PACKAGES=\(([^)]*)\)', script, re.M).group(1).split())
check(real and real <= packages['test'] and real <= packages['real'],
      'the tests and bench --real install REAL_PACKAGES')
check({'libgtest-dev', 'python3-evdev'} <= packages['test'], 'the tests install GoogleTest, evdev')
davis = {'python3-opencv', 'python3-matplotlib'}
check(davis <= packages['davis'] and davis <= packages['test'] and packages['build'] <= packages['davis'],
      'bench --davis and its quick test install OpenCV\'s Python bindings, matplotlib and the build')
check('clang' in packages['fuzz'] and 'clang' not in packages['test'], 'only fuzzing needs clang')
check(re.search(r'apt-get install[^\n]*-q', script) and 'apt.log' in script,
      'apt runs quietly, its log kept in the build folder')

print(f'{len(failures)} failures')
sys.exit(1 if failures else 0)
