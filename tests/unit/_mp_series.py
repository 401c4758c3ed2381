"""mpmath references (50 digits where the caller sets mp.dps) of the exp chart's scalar
functions of s = t^2 (hpgen.groups.series): closed forms, d_* by mpmath's numerical
derivative. Shared by the series tests."""
from __future__ import annotations

import mpmath as mp

BASE = {
    "sinc": lambda s: mp.sin(mp.sqrt(s)) / mp.sqrt(s),
    "cosc": lambda s: (1 - mp.cos(mp.sqrt(s))) / s,
    "sinc3": lambda s: (mp.sqrt(s) - mp.sin(mp.sqrt(s))) / s**mp.mpf(1.5),
    "dexpinv_c": lambda s: (1 - mp.sqrt(s) / 2 * mp.cot(mp.sqrt(s) / 2)) / s,
}


def mp_series_function(name):
    """name ('sinc', ..., or 'd_' + one of them) -> f(s) in mpmath."""
    if name in BASE:
        return BASE[name]
    return lambda s, b=BASE[name[2:]]: mp.diff(b, s)
