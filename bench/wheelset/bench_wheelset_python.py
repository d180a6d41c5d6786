"""The wheelset call from Python, vectorised over N wheelsets (default 10,000), against the C loop
of the same steps (build/mhcontact_bench_wheelset_step N, its first line): docs/performance.md
"The wheelset call". The same steps as the C benchmark: S1002/60E1 1:40, mu 0.3, V 30 m/s,
50 kN per wheel, y = 6 mm sin, yaw 2 mrad sin. CPU time of the calling thread (threads=1: the
steps run on it, the GIL released), per step, median of 5.

    PYTHONPATH=build/python python3 bench/wheelset/bench_wheelset_python.py [N]
"""
import sys
import time

import numpy as np

import mhcontact

n = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
pair = mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                      {"rail_inclination": "1:40"})
ws = mhcontact.Wheelset(pair, pair, mu=0.3)
s = np.sin(2 * np.pi * np.arange(n) / n)
times = []
for _ in range(5):
    t0 = time.thread_time()
    out = ws.step(6e-3 * s, Q_left_N=50e3, Q_right_N=50e3, yaw_rad=2e-3 * s, V_m_per_s=30.0, threads=1)
    times.append((time.thread_time() - t0) / n * 1e6)
print("Wheelset.step over %d wheelsets, 1 thread: %.2f us per step (median of 5); ok: %d"
      % (n, sorted(times)[2], int(np.sum(out["status"] == "ok"))))
