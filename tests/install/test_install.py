#!/usr/bin/python3
"""The installed library as an application sees it: installs the build into a staging folder
(meson install --destdir), checks which headers are installed (the include closure of
projtrack.hpp, nothing else) and what pkg-config says (one include folder, OpenCV private), then
builds consumer.cpp against the installed copy, statically and against the shared library when
there is one, and runs it. Usage: test_install.py BUILD_DIR SOURCE_DIR STAGE_DIR CXX [ARGS...]"""
import os
import re
import shutil
import subprocess
import sys

build, source, stage = sys.argv[1:4]
cxx = sys.argv[4:]
failures = []


def check(condition, what):
    print(('ok   ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


def run(cmd, **kw):
    print('$ ' + ' '.join(cmd))
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw).stdout


shutil.rmtree(stage, ignore_errors=True)
run(['meson', 'install', '-C', build, '--no-rebuild', '--quiet', '--destdir', stage,
     '--tags', 'devel,runtime'])
intro = run(['meson', 'introspect', build, '--buildoptions'])
import json  # noqa: E402
options = {o['name']: o['value'] for o in json.loads(intro)}
prefix, libdir, includedir = options['prefix'], options['libdir'], options['includedir']
kind = options['default_library']
root = stage + prefix
pcdir = os.path.join(root, libdir, 'pkgconfig')

# The headers: exactly include/projtrack/, which is projtrack.hpp and what it includes, directly or
# not; no stage's internals (src/) among them.
public = os.path.join(source, 'include', 'projtrack')
shipped = set(os.listdir(public))
closure, todo = set(), ['projtrack.hpp']
while todo:
    h = todo.pop()
    if h not in closure:
        closure.add(h)
        todo += re.findall(r'#include "([^"]+)"', open(os.path.join(public, h)).read())
installed = set(os.listdir(os.path.join(root, includedir, 'projtrack')))
check(installed == shipped, f'installed headers are exactly include/projtrack/ ({len(installed)}; '
      f'extra {sorted(installed - shipped)}, missing {sorted(shipped - installed)})')
check(closure == shipped, f'include/projtrack/ is the include closure of projtrack.hpp '
      f'(not reached {sorted(shipped - closure)}, outside it {sorted(closure - shipped)})')
internal = {f for _, _, fs in os.walk(os.path.join(source, 'src')) for f in fs
            if f.endswith(('.hpp', '.def'))}
check(not (installed & internal), f'no internal header is installed: {sorted(installed & internal)}')

# projtrack.pc moved with the staging folder: its prefix line points there (pkg-config's
# --define-variable would move OpenCV's prefix too).
relocated = os.path.join(stage, 'pkgconfig')
os.makedirs(relocated, exist_ok=True)
pc = open(os.path.join(pcdir, 'projtrack.pc')).read()
with open(os.path.join(relocated, 'projtrack.pc'), 'w') as f:
    f.write(re.sub(r'^prefix=.*$', 'prefix=' + root, pc, count=1, flags=re.M))
env = dict(os.environ, PKG_CONFIG_PATH=relocated)


def pkgconfig(*args):
    return run(['pkg-config', *args, 'projtrack'], env=env).split()


cflags = pkgconfig('--cflags')
own = [f for f in cflags if f.startswith('-I' + root)]
check(own == ['-I' + os.path.join(root, includedir)],
      f'one include folder of ours, used as <projtrack/...>: {own}')
check(re.search(r'^Requires\.private:.*opencv4', pc, re.M) is not None
      and re.search(r'^Requires:.*opencv', pc, re.M) is None, 'OpenCV is Requires.private')

# Each installed header compiles alone, from the installed copy (it includes what it uses).
for h in sorted(installed):
    if h.endswith('.hpp'):
        r = subprocess.run(cxx + ['-std=c++17', '-fsyntax-only', '-x', 'c++', '-'] + cflags,
                           input=f'#include <projtrack/{h}>\n', capture_output=True, text=True)
        check(r.returncode == 0, f'<projtrack/{h}> compiles alone' + (': ' + r.stderr[:400]
                                                                      if r.returncode else ''))

consumer = os.path.join(source, 'tests', 'install', 'consumer.cpp')
builds = []
if kind in ('static', 'both'):
    # A static library: the libraries it needs come with --static; -Bstatic picks the .a when a
    # .so is installed beside it.
    libs = pkgconfig('--static', '--libs')
    libs = ['-Wl,-Bstatic' if f == '-lprojtrack' else f for f in libs]
    libs.insert(libs.index('-Wl,-Bstatic') + 1, '-lprojtrack')
    libs.insert(libs.index('-Wl,-Bstatic') + 2, '-Wl,-Bdynamic')
    builds.append(('static', libs))
if kind in ('shared', 'both'):
    libs = pkgconfig('--libs')
    check(not any(f.startswith('-lopencv') for f in libs),
          f'a shared consumer links no OpenCV library itself: {libs}')
    builds.append(('shared', libs))

for name, libs in builds:
    exe = os.path.join(stage, 'consumer-' + name)
    run(cxx + ['-std=c++17', consumer, '-o', exe] + cflags + libs)
    needs = run(['ldd', exe])
    check(('libprojtrack.so' in needs) == (name == 'shared'),
          f'the {name} consumer links libprojtrack {name}')
    out = subprocess.run([exe], capture_output=True, text=True,
                         env=dict(os.environ, LD_LIBRARY_PATH=os.path.join(root, libdir)))
    print(out.stdout, end='')
    check(out.returncode == 0, f'the {name} consumer tracks the disc')

print(f'{len(failures)} failures')
sys.exit(1 if failures else 0)
