#!/usr/bin/python3
"""The Python module installed as a user installs it: `meson install` (its runtime tag) into a
staging folder puts projtrack in the interpreter's site folder under the prefix, where Debian's
Python imports it and tracks a frame; it carries the library (no libprojtrack.so needed).
Usage: test_install.py BUILD_DIR STAGE_DIR INSTALL_DIR"""
import glob
import os
import shutil
import subprocess
import sys

build, stage, install_dir = sys.argv[1:4]
shutil.rmtree(stage, ignore_errors=True)
subprocess.run(['meson', 'install', '-C', build, '--no-rebuild', '--quiet', '--destdir', stage,
                '--tags', 'runtime'], check=True, capture_output=True)
site = stage + install_dir
modules = glob.glob(os.path.join(site, 'projtrack*.so'))
assert len(modules) == 1, (site, os.listdir(stage))
needed = subprocess.run(['readelf', '-d', modules[0]], capture_output=True, text=True,
                        check=True).stdout
assert 'libprojtrack' not in needed, 'the module needs libprojtrack.so beside it'
probe = ('import numpy, projtrack; f = numpy.zeros((120, 160), numpy.uint8); '
         'f[40:80, 60:100] = 200; t = projtrack.Tracker(); print(projtrack.__file__, '
         't.init(f, (80, 60)), t.track(f).area)')
out = subprocess.run(['/usr/bin/python3', '-c', probe], capture_output=True, text=True, cwd='/',
                     env=dict(os.environ, PYTHONPATH=site), check=True).stdout.split()
assert out[0] == modules[0], out
assert out[1] == 'True' and abs(float(out[2]) - 1600) < 240, out
print('python install: ok')
