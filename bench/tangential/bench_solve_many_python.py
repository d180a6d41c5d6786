"""Pair.solve_many with creep forces from Python (docs/tangential.md "Cost", issue 33 §5: 25 µs per
multi-Hertzian case with tangential forces): 400 cases on the Manchester pair of
cases/manchester-tangential.json, t_Y -6 ... 10 mm x Q 10 ... 150 kN (20 x 20), mu 0.3, 30 m/s,
yaw 2.4 mrad per mm of t_Y, with the vertical equilibrium on (the default) and off. CPU time of
the calling thread (threads=1), per case, median of 5.

    PYTHONPATH=build/python python3 bench/tangential/bench_solve_many_python.py [CASE_FILE]
"""
import sys
import time

import numpy as np

import mhcontact

pair = mhcontact.Pair.from_case_file(sys.argv[1] if len(sys.argv) > 1 else "cases/manchester-tangential.json")
tY, Q = np.meshgrid(np.linspace(-6e-3, 10e-3, 20), np.linspace(10e3, 150e3, 20))
tY, Q = tY.ravel(), Q.ravel()
for label, eq in (("vertical equilibrium on", True), ("vertical equilibrium off", False)):
    pair.set_tangential({"mu": 0.3, "speed_m_s": 30, "yaw_rad_per_m": 2.4, "vertical_equilibrium": eq})
    t = []
    for _ in range(5):
        t0 = time.thread_time()
        pair.solve_many(tY, Q_N=Q, threads=1)
        t.append((time.thread_time() - t0) / tY.size * 1e6)
    print("Pair.solve_many, %d cases with creep forces, %s: %.1f us per case (median of 5)" % (tY.size, label, sorted(t)[2]))
