"""The tables and plots of docs/benchmarks.md over the runs (a part of bench/paper/report.py's
Report)."""
import math
import os
from collections import defaultdict

import numpy as np

from paper_data import (PEERS, abs_area_error, area_spread, leak_rate, mean, med, num, pct, score,
                        select, spread)
from report_kit import plt


class Tables:
    def w(self, line=''):
        self.out.append(line)

    def setting(self, section, key, fmt=lambda v: f'{v:g}'):
        """A setting of the run as meta.json recorded it, formatted; 'not recorded' if absent."""
        v = self.meta.get(section, {}).get(key) if section else self.meta.get(key)
        return 'not recorded' if v is None else fmt(v)

    def gap_runs(self):
        """How long the deliberate gaps are, as meta.json recorded the scene model."""
        model = self.meta.get('scene_model', {})
        lo, hi = model.get('gap_run_min'), model.get('gap_run_max')
        if lo is None or hi is None:
            return 'a length not recorded'
        return f'{lo:g} px' if lo == hi else f'{lo:g}–{hi:g} px'

    def leak_factor(self):
        return self.setting(None, 'leak_factor', lambda v: f'{v:g}×')

    # --- tables -------------------------------------------------------------------------
    def clean(self, **kw):
        return select(self.runs, gap_rate=0.0, spurious=0.0, **kw)

    def accuracy_table(self, obj):
        self.w('| method | centroid error (median, px) | centroid error / √area (median, p90) '
               '| \\|area error\\| (median) | centroid spread across inner points '
               '| area spread across inner points | leak rate | iterations (mean) |')
        self.w('|---|---|---|---|---|---|---|---|')
        for m in self.contenders:
            rows = self.clean(object=obj, method=m)
            rel = [r['centroid_error_rel'] for r in rows if not math.isnan(r['centroid_error_rel'])]
            p90 = float(np.percentile(rel, 90)) if rel else math.nan
            self.w(f'| {m} | {num(med([r["centroid_error_px"] for r in rows]), 2)} | '
                   f'{pct(med(rel))}, {pct(p90)} | {pct(abs_area_error(rows))} | '
                   f'{pct(spread(rows))} | {pct(area_spread(rows))} | {pct(leak_rate(rows), 0)} | '
                   f'{num(mean([r["iterations"] for r in rows]))} |')

    def gap_table(self, obj, metric, fmt):
        self.w('| method | ' + ' | '.join(f'gaps {pct(g, 0)}' for g in self.rates) + ' |')
        self.w('|---|' + '---|' * len(self.rates))
        for m in self.contenders:
            cells = [fmt(metric(select(self.runs, object=obj, method=m, gap_rate=g, spurious=0.0)))
                     for g in self.rates]
            self.w(f'| {m} | ' + ' | '.join(cells) + ' |')

    def spurious_table(self):
        self.w('| method | object | centroid error / √area: clean → specks | '
               '\\|area error\\|: clean → specks | leak rate: clean → specks |')
        self.w('|---|---|---|---|---|')
        for obj in ['sphere', 'hand']:
            for m in self.contenders:
                a = select(self.runs, object=obj, method=m, gap_rate=0.0, spurious=0.0)
                b = select(self.runs, object=obj, method=m, gap_rate=0.0, spurious=1.0)
                if not b:
                    continue
                self.w(f'| {m} | {obj} | {pct(med([r["centroid_error_rel"] for r in a]))} → '
                       f'{pct(med([r["centroid_error_rel"] for r in b]))} | '
                       f'{pct(abs_area_error(a))} → {pct(abs_area_error(b))} | '
                       f'{pct(leak_rate(a), 0)} → {pct(leak_rate(b), 0)} |')

    def boundary_shortfall(self):
        """How far pixel-filling's area falls short of the truth on closed contours, per pixel of
        the object's boundary (median over scenes): the edge line it does not count."""
        boundary = {(s['resolution'], s['object'], s['instance'], s['scale']): s['contour_pixels']
                    for s in self.scenes if s['gap_rate'] == 0.0 and s['spurious'] == 0.0}
        per_scene = defaultdict(list)
        for r in self.clean(method='pixel-filling'):
            key = (r['resolution'], r['object'], r['instance'], r['scale'])
            if key in boundary and boundary[key] > 0:
                per_scene[key].append((r['true_area'] - r['area']) / boundary[key])
        return med([med(v) for v in per_scene.values()])

    def time(self, method, resolution):
        """Median time per call on closed contours (no gaps, no specks), where every method
        does its normal work; a leaked fill costs the whole frame and is reported apart."""
        return med([r['time_us'] for r in select(self.runs, method=method, resolution=resolution,
                                                  spurious=0.0, gap_rate=0.0, leak=0.0)])

    def leaked_time(self, method, resolution):
        return med([r['time_us'] for r in select(self.runs, method=method, resolution=resolution,
                                                  leak=1.0)])

    def time_table(self):
        self.w('| method | ' + ' | '.join(f'{res}: µs | × grid-filling | leaked: µs'
                                          for res in self.resolutions) + ' |')
        self.w('|---|' + '---|---|---|' * len(self.resolutions))
        for m in self.contenders:
            cells = []
            for res in self.resolutions:
                t, g = self.time(m, res), self.time('grid-filling', res)
                cells += [num(t, 0), num(t / g, 2), num(self.leaked_time(m, res), 0)]
            self.w(f'| {m} | ' + ' | '.join(cells) + ' |')
        for stage in ['canny', 'sobel', 'frame-copy']:
            cells = []
            for res in self.resolutions:
                t = self.edges.get((res, stage), math.nan)
                cells += [num(t, 0), num(t / self.time('grid-filling', res), 2), '']
            self.w(f'| *{stage} of the whole frame* | ' + ' | '.join(cells) + ' |')

    # --- plots --------------------------------------------------------------------------
    def plot_gaps(self):
        fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
        for col, obj in enumerate(['sphere', 'hand']):
            for m in self.contenders:
                rows = [select(self.runs, object=obj, method=m, gap_rate=g, spurious=0.0)
                        for g in self.rates]
                style = '--' if m in PEERS else '-'
                xs = [100 * g for g in self.rates]
                axes[0][col].plot(xs, [100 * leak_rate(r) for r in rows], style, marker='o',
                                  label=m)
                axes[1][col].plot(xs, [100 * abs_area_error(r) for r in rows], style,
                                  marker='o', label=m)
            axes[0][col].set_title(f'{obj}: leak rate (area > {self.leak_factor()} truth)')
            axes[1][col].set_title(f'{obj}: median |area error|')
            axes[1][col].set_yscale('log')
            axes[1][col].set_xlabel(f'contour pixels missing (%), in {self.gap_runs()} gaps')
            for a in axes[:, col]:
                a.set_ylabel('%')
                a.grid(alpha=0.3)
        axes[0][1].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(self.dir, 'figures', 'gap-rate.png'), dpi=90)
        plt.close(fig)

    def plot_time(self):
        fig, ax = plt.subplots(figsize=(10, 4.5))
        width = 0.8 / len(self.resolutions)
        for i, res in enumerate(self.resolutions):
            ts = [self.time(m, res) for m in self.contenders]
            ax.bar(np.arange(len(self.contenders)) + i * width, ts, width, label=res)
        for i, res in enumerate(self.resolutions):
            c = self.edges.get((res, 'canny'))
            if c:
                ax.axhline(c, color=f'C{i}', linestyle=':', label=f'Canny on the {res} frame')
        ax.set_yscale('log')
        ax.set_ylabel('µs per call (median, one thread)')
        ax.set_xticks(np.arange(len(self.contenders)) + width / 2)
        ax.set_xticklabels(self.contenders, rotation=25, ha='right', fontsize=8)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3, axis='y')
        fig.tight_layout()
        fig.savefig(os.path.join(self.dir, 'figures', 'time-resolution.png'), dpi=90)
        plt.close(fig)

    def plot_sweep(self, params):
        fig, axes = plt.subplots(2, len(params), figsize=(3.2 * len(params), 6))
        for col, p in enumerate(params):
            rows = select(self.sweep, parameter=p)
            for m in sorted({r['method'] for r in rows}, key=self.methods.index):
                vals = sorted({r['value'] for r in select(rows, method=m)})
                axes[0][col].plot(vals, [score(select(rows, method=m, value=v)) for v in vals],
                                  marker='o', label=m)
                axes[1][col].plot(vals, [med([r['time_us'] for r in select(rows, method=m, value=v)])
                                         for v in vals], marker='o', label=m)
            axes[0][col].set_title(p)
            axes[1][col].set_xlabel(p)
            axes[1][col].set_yscale('log')
            axes[0][col].grid(alpha=0.3)
            axes[1][col].grid(alpha=0.3)
        axes[0][0].set_ylabel('error score (lower is better)')
        axes[1][0].set_ylabel('µs per call')
        axes[0][-1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(self.dir, 'figures', 'sweep.png'), dpi=80)
        plt.close(fig)

