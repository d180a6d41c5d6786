#!/usr/bin/env python3
"""One shard of cases/fleet.json (4 pairs) with a finer t_Y step, run by the binary
(`mhcontact run --shard 1/1 --threads 1`, a child process) and by the Python module in this
process (`mhcontact._core._run_shard`, what a Dask worker runs), alternated; prints the user and
system CPU of each and their ratio, and the median ratio (docs/cluster.md, "Dask's own CPU").

    PYTHONPATH=build/python /usr/bin/python3 scripts/bench_module_shard.py [tY step mm, default 0.002] [method] [runs, default 3]
"""
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

import mhcontact

src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = os.path.realpath(os.environ.get("MHCONTACT", os.path.join(src, "build", "mhcontact")))
step = sys.argv[1] if len(sys.argv) > 1 else "0.002"
method = sys.argv[2] if len(sys.argv) > 2 else "multi-hertzian"
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3


def cpu(who):
    r = resource.getrusage(who)
    return r.ru_utime, r.ru_stime


def main():
    tmp = tempfile.mkdtemp()
    try:
        text = open(os.path.join(src, "cases", "fleet.json")).read().replace('"step": 0.5', f'"step": {step}')
        text = text.replace('"model": "elastic",', f'"model": "elastic", "method": "{method}",')
        text = re.sub(r'"\.\./profiles/', f'"{src}/profiles/', text)
        case = os.path.join(tmp, "fleet.json")
        open(case, "w").write(text)
        ratios = []
        for _ in range(runs):
            u0, s0 = cpu(resource.RUSAGE_CHILDREN)
            rc = subprocess.run([binary, "run", case, "--shard", "1/1", "--threads", "1", "-q", "-o",
                                 os.path.join(tmp, "b")]).returncode
            assert rc in (0, 1), rc
            u1, s1 = cpu(resource.RUSAGE_CHILDREN)
            shutil.rmtree(os.path.join(tmp, "b"))
            v0, t0 = cpu(resource.RUSAGE_SELF)
            mhcontact._core._run_shard(case, os.path.join(tmp, "m"), 1, 1, 1, 10, False)
            v1, t1 = cpu(resource.RUSAGE_SELF)
            shutil.rmtree(os.path.join(tmp, "m"), ignore_errors=True)
            ratios.append((v1 - v0) / (u1 - u0))
            print(f"{method}, t_Y step {step} mm: binary user {u1 - u0:.2f} s sys {s1 - s0:.2f} s; "
                  f"module user {v1 - v0:.2f} s sys {t1 - t0:.2f} s; user ratio {ratios[-1]:.3f}", flush=True)
        print(f"median user ratio, module over binary: {statistics.median(ratios):.3f} ({runs} runs)")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
