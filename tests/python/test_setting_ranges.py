#!/usr/bin/python3
"""Python's keywords refuse what the element's properties refuse: for every keyword of
projtrack.Tracker that names a numeric property of the element, the property's minimum and maximum
are taken and the values just beyond them are a ValueError naming the keyword (issue 32: every bad
setting is a ValueError naming the setting and its range). Exit status 77 (skipped) without the
element."""
import math
import sys

import gi

import projtrack

gi.require_version('Gst', '1.0')
from gi.repository import GObject, Gst  # noqa: E402

NUMERIC = {GObject.TYPE_DOUBLE: float, GObject.TYPE_UINT: int, GObject.TYPE_INT: int}
# Settings that must agree with another (Canny's low threshold at most its high one): each is
# tried with its partner at the same limit, so that only the range is judged.
PARTNER = {'edge_threshold_low': 'edge_threshold_high',
           'edge_threshold_high': 'edge_threshold_low'}


def settings(keyword, value, limit):
    """The keywords that try `value` for `keyword`, its partner (if any) at `limit`."""
    given = {keyword: value}
    if keyword in PARTNER:
        given[PARTNER[keyword]] = type(value)(limit)
    return given


def beyond(value, kind, step):
    """The value just past `value` in the direction of `step` (+1 or -1)."""
    if kind is int:
        return value + step
    return value + step * max(1e-6, abs(value) * 1e-6)


def check(keyword, spec, kind):
    """What is wrong with the keyword's range against the property's, as a list of sentences."""
    wrong = []
    for limit in (spec.minimum, spec.maximum):
        try:
            projtrack.Tracker(**settings(keyword, kind(limit), limit))
        except ValueError as e:
            wrong.append(f'{keyword}={limit!r}: the element takes it, Python refuses it ({e})')
    for limit, step in ((spec.minimum, -1), (spec.maximum, +1)):
        value = beyond(limit, kind, step)
        if kind is int and not -2**63 < value < 2**64:
            continue
        try:
            projtrack.Tracker(**settings(keyword, kind(value), limit))
            wrong.append(f'{keyword}={value!r}: the element refuses it, Python takes it')
        except ValueError as e:
            if keyword not in str(e):
                wrong.append(f'{keyword}={value!r}: the ValueError does not name it ({e})')
    return wrong


def main():
    Gst.init(None)
    element = Gst.ElementFactory.make('projtrack')
    if element is None:
        print('no projtrack element (GST_PLUGIN_PATH): skipped')
        return 77
    wrong, checked = [], 0
    for keyword in projtrack.Tracker().settings:
        spec = element.find_property(keyword.replace('_', '-'))
        if spec is None or spec.value_type not in NUMERIC:
            continue
        if isinstance(spec.maximum, float) and math.isinf(spec.maximum):
            continue
        checked += 1
        wrong += check(keyword, spec, NUMERIC[spec.value_type])
    print(f'{checked} numeric keywords checked against the element\'s ranges')
    for w in wrong:
        print(w)
    if checked < 10:
        wrong.append(f'only {checked} keywords matched a numeric property')
    return 1 if wrong else 0


if __name__ == '__main__':
    sys.exit(main())
