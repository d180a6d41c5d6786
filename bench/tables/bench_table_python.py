"""A contact table's single-point lookup from Python against the C lookup in the same run
(docs/tables.md "From Python", docs/performance.md "Contact tables"). Figures printed, never
asserted (the machines are shared).

    PYTHONPATH=build/python python3 bench/tables/bench_table_python.py [TABLE.csv] [STEPS]

TABLE.csv: a table made by `mhcontact table` (default: that of cases/s1002-60e1-table.json, made
by build/mhcontact into a temporary directory). STEPS points (default 10,000) at
t_Y = 3 mm + 6 mm sin(2π·5·k/STEPS), Q = 60 kN (the steps of tests/test_tables.py), each way
timed as CPU time of the thread per lookup, median of 15 repeats:
  C            mhc_table_lookup in a C loop (Table._c_lookup_seconds: no Python in the loop);
  lookup_into  Table.lookup_into(tY, Q, result) in a Python loop, the result reused;
  lookup       Table.lookup(tY, Q) in a Python loop (a dict per call);
  lookup_many  Table.lookup_many over all points at once, per point (fresh output arrays);
  many_out     the same into output arrays made once (lookup_many(..., out=), no allocation);
  loop         the same Python loop calling nothing (its share of the two above).
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import mhcontact

here = os.path.dirname(os.path.abspath(__file__))
src = os.path.join(here, "..", "..")
if len(sys.argv) > 1 and sys.argv[1] != "-":
    path = sys.argv[1]
else:
    path = os.path.join(tempfile.mkdtemp(), "table.csv")
    binary = os.environ.get("MHCONTACT_BINARY", os.path.join(src, "build", "mhcontact"))
    rc = subprocess.run([binary, "table", os.path.join(src, "cases", "s1002-60e1-table.json"), "-o", path, "-q"]).returncode
    if rc not in (0, 1):
        sys.exit("mhcontact table failed (exit %d)" % rc)
steps = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
REPEATS = 15

t = mhcontact.Table(path)
tY = 3e-3 + 6e-3 * np.sin(2 * np.pi * 5 * np.arange(steps) / steps)
Q = np.full_like(tY, 60e3)
pts = list(zip(tY.tolist(), Q.tolist()))
res = mhcontact.TableResult()


def timed(fn):
    per = []
    for _ in range(REPEATS):
        t0 = time.thread_time()
        fn()
        per.append((time.thread_time() - t0) / steps)
    return sorted(per)[REPEATS // 2]


def loop_into():
    into = t.lookup_into
    for a, b in pts:
        into(a, b, res)


def loop_dict():
    look = t.lookup
    for a, b in pts:
        look(a, b)


def loop_empty():
    f = float
    for a, b in pts:
        f(a)


c = sorted(t._c_lookup_seconds(tY, Q, REPEATS))[REPEATS // 2]
into = timed(loop_into)
dct = timed(loop_dict)
many = timed(lambda: t.lookup_many(tY, Q))
out = mhcontact.Table.many_result(steps)
many_out = timed(lambda: t.lookup_many(tY, Q, out=out))
empty = timed(loop_empty)
contacts = t.lookup_many(tY, Q)["n_contacts"].sum() / steps
print("mhcontact %s: table %s, %d steps, %.2f contacts a step; CPU time of the thread per lookup, median of %d"
      % (mhcontact.__version__, path, steps, contacts, REPEATS))
print("%-12s %8s %8s %10s" % ("way", "us/call", "us/cont.", "x C"))
for name, s in (("C", c), ("lookup_into", into), ("lookup", dct), ("lookup_many", many), ("many_out", many_out), ("loop", empty)):
    print("%-12s %8.3f %8.3f %10.1f" % (name, s * 1e6, s * 1e6 / contacts, s / c))
