"""Python solve_many over 1,000,000 cases (the grid of bench_capi.cpp item 3: 10,000 t_Y from
-6 to 10 mm times 100 Q from 10 to 100 kN, Manchester pair) on THREADS threads; compare with
item 3 of mhcontact_bench_capi. Figures printed, not asserted.
    PYTHONPATH=build/python python3 bench/capi/bench_python.py [SOURCE_DIR] [THREADS]"""
import sys
import time

import numpy as np

import mhcontact

src = sys.argv[1] if len(sys.argv) > 1 else "."
threads = int(sys.argv[2]) if len(sys.argv) > 2 else 2
pair = mhcontact.Pair.from_case_file(f"{src}/cases/manchester.json")
tY = np.linspace(-6e-3, 10e-3, 10000)[:, None]
Q = np.linspace(10e3, 100e3, 100)[None, :]
times = []
for rep in range(3):
    t0 = time.perf_counter()
    cols = pair.solve_many(tY, Q_N=Q, threads=threads)
    times.append(time.perf_counter() - t0)
print(f"python solve_many, 1,000,000 cases on {threads} threads: median {sorted(times)[1]:.2f} s "
      f"({np.sum(cols['status'] == 'ok')} ok)")
