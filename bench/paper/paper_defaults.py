"""The defaults chosen from the sweep, and auto acquisition's section (a part of
bench/paper/report.py's Report)."""
import math
import os
from collections import defaultdict

from paper_data import TIE, abs_area_error, leak_rate, load, mean, med, num, pct, score, select
from report_kit import MISSING, fmt_pct_g, missing, span


class Defaults:
    def sweep_cells(self):
        """The sweep's rows per (parameter, value, method): one cell of its table per method."""
        cells = defaultdict(list)
        for r in self.sweep:
            cells[(r['parameter'], r['value'], r['method'])].append(r)
        return list(cells.values())

    def max_gap_rows(self):
        """Gap-tolerant filling at every max gap the sweep tries, from the element's defaults, on
        the runs' scenes with the most gaps (variants.csv), and that gap rate."""
        rows = select(self.variants, parameter='max_gap', base='defaults')
        return rows, max((r['gap_rate'] for r in rows), default=math.nan)

    def hold_grid_size(self, pick, cur, stats):
        """Held for speed: the element runs the default method on every frame."""
        px_cur = stats[cur][2] if cur in stats else math.nan
        px_pick = stats[pick][2]
        if missing(px_cur, px_pick):
            return None, 'speed'
        return px_cur < px_pick, (
            f'speed: the element runs the default method on every frame, and in the sweep an '
            f'estimate visits {num(px_cur, 0)} pixels (median) at {cur:g} against '
            f'{num(px_pick, 0)} at {pick:g}, {num(px_pick / px_cur, 1)}× as many; '
            'docs/performance.md measures the element\'s speed at the default')

    def hold_max_gap(self, pick, cur, stats):
        """Held for robustness: the sweep's gap rates stop short of the runs' highest."""
        rows, top = self.max_gap_rows()
        sweep_top = max((r['gap_rate'] for r in self.sweep), default=math.nan)
        leak = {v: leak_rate(select(rows, value=v)) for v in (pick, cur)}
        supported = None if missing(leak[pick], leak[cur]) else leak[cur] < leak[pick]
        if supported is None:
            return None, 'robustness at gap rates beyond the sweep\'s'
        return supported, (
            f'robustness: the sweep\'s scenes have at most {pct(sweep_top, 0)} of the contour '
            f'missing; on the runs\' scenes with {pct(top, 0)} missing, from the element\'s '
            f'defaults, the leak rate is {pct(leak[cur], 0)} at {cur:g} against '
            f'{pct(leak[pick], 0)} at {pick:g} (the table below)')

    def max_gap_table(self):
        rows, top = self.max_gap_rows()
        if not rows:
            return
        w = self.w
        specks = {r['spurious'] for r in rows}
        resolutions = [res for res in self.resolutions if select(rows, resolution=res)]
        w(f'**max_gap at {pct(top, 0)} gaps**: gap-tolerant filling from the element\'s defaults '
          'at every max gap the sweep tries, on the runs\' scenes with that many gaps and the '
          f'same inner points ({", ".join(resolutions)}; '
          + ('with and without specks' if len(specks) > 1 else
             'with specks' if 1.0 in specks else 'no specks') + ').')
        w()
        w('| max gap | estimates | leak rate: sphere | hand | median \\|area error\\|: sphere | '
          'hand |')
        w('|---|---|---|---|---|---|')
        for v in sorted({r['value'] for r in rows}):
            by = {o: select(rows, value=v, object=o) for o in ['sphere', 'hand']}
            w(f'| {v:g} | {len(select(rows, value=v))} | '
              + ' | '.join(pct(leak_rate(by[o]), 0) for o in by) + ' | '
              + ' | '.join(pct(abs_area_error(by[o])) for o in by) + ' |')
        w()

    def choose_defaults(self):
        """Per parameter: the value with the lowest error score over the methods it affects;
        a cheaper value whose score is within TIE of the best wins the tie. Cheaper means fewer
        pixels visited (median): a count, so the choice does not depend on a noisy clock."""
        choice = {}
        for p in ['grid_size', 'max_gap', 'block_size', 'rays', 'recursion', 'max_iterations',
                  'convergence']:
            rows = select(self.sweep, parameter=p)
            if not rows:
                continue
            vals = sorted({r['value'] for r in rows})
            stats = {v: (score(select(rows, value=v)),
                         med([r['time_us'] for r in select(rows, value=v)]),
                         med([r['pixels_visited'] for r in select(rows, value=v)]))
                     for v in vals}
            best = min(vals, key=lambda v: stats[v][0])
            near = [v for v in vals if stats[v][0] <= stats[best][0] * (1 + TIE)]
            pick = min(near, key=lambda v: (stats[v][2], v))
            choice[p] = (pick, stats, best)
        return choice

    def acquisition_section(self):
        path = os.path.join(self.dir, 'acquisition.csv')
        if not os.path.exists(path):
            return
        rows = load(path)
        w = self.w
        w('## Automatic acquisition: the original rule against ours')
        w()
        frames = sorted({r['frames'] for r in rows})
        w(f'{" or ".join(frames)} frames of a moving object, no inner point given '
          '(`acquisition=auto`). The original system seeded at the centroid of the changed pixels '
          '(*motion-centroid*); ours tries that point and '
          f'{self.setting("acquisition", "candidates")} changed pixels as seeds and keeps the most '
          'compact closed region holding the most motion (*compact-moving-region*). Acquired: the '
          'first frame the track starts (frame differencing needs two); correct: that first '
          'estimate is sane (centroid within '
          f'{self.setting("acquisition", "sane_centroid", fmt_pct_g)} of √area, area '
          f'within {self.setting("acquisition", "sane_area", fmt_pct_g)}); kept: the '
          'share of later frames tracked sanely.')
        w()
        strategies = ['motion-centroid', 'compact-moving-region']
        w('| sequence | ' + ' | '.join(f'{s}: acquired at (mean frame), correct, kept'
                                       for s in strategies) + ' |')
        w('|---|' + '---|' * len(strategies))
        seqs = sorted({r['sequence'] for r in rows}, key=[r['sequence'] for r in rows].index)
        totals = {s: [] for s in strategies}
        for seq in seqs:
            cells = []
            for s in strategies:
                rs = select(rows, sequence=seq, strategy=s)
                got = [r for r in rs if r['acquired_frame'] >= 0]
                totals[s] += rs
                cells.append(f'{num(mean([r["acquired_frame"] for r in got]))}, '
                             f'{pct(mean([r["correct"] for r in rs]), 0)}, '
                             f'{pct(mean([r["sane_after"] for r in rs]), 0)}'
                             + ('' if len(got) == len(rs) else f' ({len(rs) - len(got)} never)'))
            w(f'| {seq} | ' + ' | '.join(cells) + ' |')
        correct = {s: mean([r['correct'] for r in totals[s]]) for s in strategies}
        kept = {s: mean([r['sane_after'] for r in totals[s]]) for s in strategies}
        score = {s: correct[s] + kept[s] for s in strategies}
        default = self.meta.get('acquisition', {}).get('default_strategy')
        w()
        w('Over all sequences: ' + '; '.join(f'{s} correct {pct(correct[s], 0)}, kept '
                                             f'{pct(kept[s], 0)}' for s in strategies)
          + f'. Each sequence has {span([len(select(rows, sequence=q, strategy=s)) for q in seqs for s in strategies], str)} '
          'instances and the runs are deterministic, so these are small samples. '
          + self.acquisition_verdict(score, default))
        w()

    @staticmethod
    def acquisition_verdict(score, default):
        """Which strategy did better (correct + kept), against the one the code defaults to."""
        if default is None:
            code = 'the code\'s default was not recorded'
        else:
            code = f'the code\'s default (`TrackerParams::strategy`) is {default}'
        if missing(*score.values()):
            return f'Which is better: {MISSING}; {code}.'
        best = max(score.values())
        better = [s for s in score if score[s] == best]
        if len(better) > 1:
            return f'The two do equally well; {code}.'
        if better[0] == default:
            return (f'The better, **{better[0]}**, is the code\'s default for `acquisition=auto` '
                    '(`TrackerParams::strategy`).')
        if default is None:
            return f'The better is **{better[0]}**; {code}.'
        return (f'The better is **{better[0]}**, but {code}: change it in include/projtrack/tracker.hpp, or say '
                'why not.')


# Parameters whose default may be held away from the sweep's accuracy-only choice: each rule says
# why and whether the runs bear the reason out (True), contradict it (False) or did not measure
# it (None). A hold the data does not bear out is reported as a default to update.
HOLDS = {'grid_size': Defaults.hold_grid_size, 'max_gap': Defaults.hold_max_gap}
