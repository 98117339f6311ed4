#!/usr/bin/python3
"""Turns projtrack-bench's CSVs into docs/benchmarks.md, its plots and the verdicts.

    bench/paper/report.py RESULTS_DIR MARKDOWN_FILE

RESULTS_DIR holds methods.csv, runs.csv, scenes.csv, sweep.csv, variants.csv, edges.csv,
acquisition.csv, meta.json and figures/ (written by projtrack-bench); the plots are written to
RESULTS_DIR/figures too. Every number in the markdown is computed here from those files or read from meta.json; a
verdict whose numbers are missing reads "not measured", never "holds".

The page's parts, each a class Report is made of: paper_tables.py (tables and plots),
paper_verdicts.py (the claims' verdicts), paper_defaults.py (the defaults from the sweep,
acquisition), paper_page.py (the page, section by section); paper_data.py holds the thresholds
and the statistics they share.
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'common'))
sys.path.insert(0, HERE)  # its parts, also when loaded from elsewhere (tests/bench)
# MISSING, verdict and PEERS: tests/bench/test_report.py reads them from this module.
from report_kit import MISSING, frame_size, load_meta, load_methods, verdict  # noqa: E402,F401
from paper_data import PEERS, load, select  # noqa: E402
from paper_defaults import Defaults  # noqa: E402
from paper_page import Page  # noqa: E402
from paper_tables import Tables  # noqa: E402
from paper_verdicts import Verdicts  # noqa: E402


class Report(Page, Defaults, Verdicts, Tables):
    def __init__(self, results):
        self.dir = results
        self.runs = load(os.path.join(results, 'runs.csv'))
        self.scenes = load(os.path.join(results, 'scenes.csv'))
        self.sweep = load(os.path.join(results, 'sweep.csv'))
        with open(os.path.join(results, 'edges.csv')) as f:
            self.edges = {(r['resolution'], r['stage']): float(r['time_us'])
                          for r in csv.DictReader(f)}
        self.meta = load_meta(results)
        variants = os.path.join(results, 'variants.csv')  # absent from older runs
        self.variants = load(variants) if any(
            os.path.exists(variants + ext) for ext in ('', '.gz')) else []
        self.resolutions = sorted({r['resolution'] for r in self.runs},
                                  key=lambda s: frame_size(s)[0])
        self.rates = sorted({r['gap_rate'] for r in self.runs})
        table = load_methods(results)
        self.methods = [m['method'] for m in table]
        self.ray_methods = [m['method'] for m in table if m['family'] == 'rays']
        self.iterative = [m['method'] for m in table if m['iterative'] == '1']
        self.ours = {m['method'] for m in table if m['from_paper'] == '0'}  # beyond the paper
        self.contenders = [m for m in self.methods + PEERS if select(self.runs, method=m)]
        self.out = []


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    report = Report(sys.argv[1])
    mismatches = report.write(sys.argv[2])
    print(f'wrote {sys.argv[2]}' + (f' (defaults to update: {", ".join(mismatches)})' if mismatches else ''))


if __name__ == '__main__':
    main()
