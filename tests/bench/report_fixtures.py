"""What the report generators' fixture tests share: the generator loaded as a module (its
functions are tested one by one), and the library's table of methods as projtrack-bench lists it,
which the fixtures write beside their data as methods.csv, as the benchmark tools do."""
import csv
import importlib.util
import os
import subprocess


def load_generator(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class MethodTable:
    def __init__(self, bench):
        self.csv = subprocess.run([bench, '--list-methods'], check=True, capture_output=True,
                                  text=True, timeout=60).stdout
        self.rows = list(csv.DictReader(self.csv.splitlines()))
        self.names = [m['method'] for m in self.rows]

    def write(self, results_dir):
        with open(os.path.join(results_dir, 'methods.csv'), 'w') as f:
            f.write(self.csv)
