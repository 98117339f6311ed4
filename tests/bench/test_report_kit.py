#!/usr/bin/python3
"""bench/common/report_kit.py, what the three reports share: a verdict over a missing number
(None or NaN) reads "not measured" and never passes, in a claim's words and in a target's; the
number formats keep what each report writes (a dash or "not measured" where nothing was measured,
one more decimal for a small share where asked).

    test_report_kit.py REPORT_KIT_PY
"""
import math
import sys

from report_fixtures import load_generator

kit = load_generator(sys.argv[1], 'report_kit')
nan = math.nan

# Missing data never passes, nor fails; a function of the values is called only when measured.
assert kit.missing(None) and kit.missing(1.0, nan) and not kit.missing(0, 0.0, 1)
assert kit.verdict([1.0, None], True) == kit.MISSING
assert kit.verdict([nan], True, words=kit.TARGET) == kit.MISSING
assert kit.verdict([nan], lambda v: 1 / 0, words=kit.TARGET) == kit.MISSING
assert kit.verdict([], True) == 'holds'
# A claim holds, partly holds or fails; a target is met or not, never in part.
assert [kit.verdict([1.0], h, p) for h, p in [(True, False), (False, True), (False, False)]] == [
    'holds', 'partly', 'fails']
assert [kit.verdict([1.0], h, p, kit.TARGET) for h, p in [(True, False), (False, True)]] == [
    '**met**', '**not met**']
assert kit.verdict([2.0, 3.0], lambda a, b: a < b, words=kit.TARGET) == '**met**'
assert kit.verdict([3.0], lambda v: v <= 2, words=kit.TARGET) == '**not met**'

# Numbers: what is not measured reads as the caller's word for it.
assert kit.fmt_num(2.345, 2) == '2.35' and kit.fmt_num(7.6) == '8'
assert kit.fmt_num(None) == kit.MISSING and kit.fmt_num(nan, 1, absent=kit.DASH) == '–'
assert kit.fmt_x(2.54) == '2.5×' and kit.fmt_x(None, kit.DASH) == '–'
assert kit.fmt_pct(0.256) == '26 %' and kit.fmt_pct(0.256, 1) == '25.6 %'
assert kit.fmt_pct(nan, 1, kit.DASH) == '–' and kit.fmt_pct(None) == kit.MISSING
# A small share gets one more decimal only where asked, so it does not read as 0 % or as on a
# threshold; 0 itself stays 0 %.
assert kit.fmt_pct(0.025) == '2 %' and kit.fmt_pct(0.025, finer_under=0.1) == '2.5 %'
assert kit.fmt_pct(0.0, finer_under=0.1) == '0 %' and kit.fmt_pct(0.5, finer_under=0.1) == '50 %'
assert kit.fmt_pct_g(0.25) == '25 %' and kit.fmt_pct_g(0.025) == '2.5 %'

# Spans: one value when both ends read the same; "not measured" over nothing or a missing value.
assert kit.span([3, 1, 2], str) == '1–3' and kit.span([1.01, 0.99], lambda v: f'{v:.0f}') == '1'
assert kit.span([0.2, 0.4], lambda v: f'{100 * v:.0f}', ' %') == '20–40 %'
assert kit.span([], str) == kit.MISSING and kit.span([1.0, nan], str) == kit.MISSING

assert kit.frame_size('1920x1080') == (1920, 1080) and kit.fmt_res('640x480') == '640×480'
print('report kit: ok')
