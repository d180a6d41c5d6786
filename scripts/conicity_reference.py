#!/usr/bin/env python3
"""Reference tan γe of a Δr table by the EN 15302 integral method in 30-digit arithmetic (mpmath),
independent of the library: S(y) = ∫ Δr (trapezoids, exact for Δr linear between rows), the turning
points y1 = y2 − 2ŷ with S(y1) = S(y2) by mpmath.findroot (the equilibrium y0 where Δr changes
sign from − to +, nearest y = 0, as docs/wheelset.md states), I = ∫ dy / √(S(y2) − S(y)) by
tanh–sinh on every table interval (S(y2) − S(y) taken from the nearer turning point), tan γe = π²/I².
Usage: conicity_reference.py DELTA_R.csv AMPLITUDE_mm... > reference.csv
DELTA_R.csv: columns y_mm, delta_r_mm (header line). Prints amplitude_mm,tan_gamma_e,
well_posed (0 where S rises above S(y2) between the turning points, by more than 1e-25 m²:
no oscillation exists)."""
import bisect, csv, sys
import mpmath as mp

mp.mp.dps = 30
rows = list(csv.DictReader(open(sys.argv[1])))
y = [mp.mpf(r['y_mm']) / 1000 for r in rows]
dr = [mp.mpf(r['delta_r_mm']) / 1000 for r in rows]
S = [mp.mpf(0)]
for k in range(1, len(y)):
    S.append(S[-1] + (dr[k] + dr[k - 1]) / 2 * (y[k] - y[k - 1]))


def interval(x):
    return min(max(bisect.bisect_right(y, x) - 1, 0), len(y) - 2)


def S_at(x, k=None):
    k = interval(x) if k is None else k
    t = x - y[k]
    return S[k] + dr[k] * t + (dr[k + 1] - dr[k]) / (y[k + 1] - y[k]) * t * t / 2


y0 = None
for k in range(1, len(y)):
    if dr[k - 1] <= 0 < dr[k]:
        c = y[k - 1] if dr[k - 1] == 0 else y[k - 1] + (y[k] - y[k - 1]) * (-dr[k - 1]) / (dr[k] - dr[k - 1])
        if y0 is None or abs(c) < abs(y0):
            y0 = c
print('amplitude_mm,tan_gamma_e,well_posed')
for a in sys.argv[2:]:
    A = mp.mpf(a) / 1000
    F = lambda t: S_at(t) - S_at(t - 2 * A)
    lo, hi = max(y0, y[0] + 2 * A), min(y0 + 2 * A, y[-1])
    y2 = mp.findroot(F, (lo, hi), solver='anderson')
    y1, m = y2 - 2 * A, y2 - A
    S1, S2 = S_at(y1), S_at(y2)
    pts = sorted(set([y1, m, y2] + [v for v in y if y1 < v < y2]))
    I, ok = mp.mpf(0), True
    for p, q in zip(pts[:-1], pts[1:]):
        k = interval((p + q) / 2)
        top = lambda x: S2 if x >= m else S1
        # S is one quadratic on the piece: its largest value is at an end or where Δr = 0. The
        # turning points themselves are where S meets the level by definition (a piece of zero
        # width at a turning point that is a table row has nothing inside).
        sl = (dr[k + 1] - dr[k]) / (y[k + 1] - y[k])
        cand = [x for x in (p, q) if x != y1 and x != y2]
        if sl != 0:
            v = y[k] - dr[k] / sl
            if p < v < q:
                cand.append(v)
        if any(top(x) - S_at(x, k) < -mp.mpf('1e-25') for x in cand):
            ok = False
        I += mp.quad(lambda x: (lambda d: 1 / mp.sqrt(d) if d > 0 else mp.mpf(0))(top(x) - S_at(x, k)), [p, q])
    print('%s,%s,%d' % (a, mp.nstr(mp.pi ** 2 / I ** 2, 20), ok))
