#!/usr/bin/env python3
"""The cost of the Dask route against the local run, per case (docs/cluster.md#cost): the fleet
of cases/fleet.json (4 pairs) with a finer t_Y step, run (1) by `mhcontact run` in one process
on every core, (2) by mhcontact.fleet on a LocalCluster on 127.0.0.1 (one worker process per core,
one thread each; the cluster started before the clock), merged into a directory, (3) locally
again; the merged files compared with the local run's byte for byte. Wall times.

    PYTHONPATH=build/python /usr/bin/python3 scripts/bench_dask.py [tY step mm, default 0.01] [method]

THREADS=T sets fleet()'s threads (each shard's threads; default 1); SPLIT=pairs cuts the fleet
into one shard per pair (as before --shard-by cases), SPLIT=cases SHARDS=S into S slices of the
cases; default fleet()'s own plan (plan_shards); SIZES=equal|tapered the slices' sizes (default
fleet()'s: tapered with two shards or more a worker thread). Besides the wall times it
prints the CPU time (user + sys) of the local runs and of the route (the workers' processes and
this one, the client's merge included), which other jobs on a shared machine stretch less, and
Dask's own CPU time over the same wall time with nothing to compute (a sleeping task per worker).
DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED=False turns the workers' statistical profiler off
(Dask's own setting, read by the workers it starts; docs/cluster.md#dask); Dask's idle cost is
set by its intervals too (DASK_DISTRIBUTED__ADMIN__TICK__INTERVAL=1s,
DASK_DISTRIBUTED__ADMIN__SYSTEM_MONITOR__INTERVAL=5s,
DASK_DISTRIBUTED__WORKER__MEMORY__MONITOR_INTERVAL=1s), printed with the figures. The workers'
CPU includes their nannies'.
"""
import filecmp
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

import dask
import mhcontact
from dask.distributed import Client, LocalCluster, get_task_stream

src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = os.path.realpath(os.environ.get("MHCONTACT", os.path.join(src, "build", "mhcontact")))
step = sys.argv[1] if len(sys.argv) > 1 else "0.01"
method = sys.argv[2] if len(sys.argv) > 2 else "multi-hertzian"


def main():
    tmp = tempfile.mkdtemp()
    try:
        text = open(os.path.join(src, "cases", "fleet.json")).read()
        text = text.replace('"step": 0.5', f'"step": {step}')
        text = text.replace('"model": "elastic",', f'"model": "elastic", "method": "{method}",')
        text = re.sub(r'"\.\./profiles/', f'"{src}/profiles/', text)
        case = os.path.join(tmp, "fleet.json")
        open(case, "w").write(text)
        ncores = os.cpu_count() or 1

        def children_cpu():
            r = resource.getrusage(resource.RUSAGE_CHILDREN)
            return r.ru_utime + r.ru_stime

        def own_cpu():
            r = resource.getrusage(resource.RUSAGE_SELF)
            return r.ru_utime + r.ru_stime

        cpu_local = []

        def local(name):
            t0, c0 = time.time(), children_cpu()
            rc = subprocess.run([binary, "run", case, "-o", os.path.join(tmp, name), "-q", "--threads", str(ncores)]).returncode
            assert rc in (0, 1), rc
            cpu_local.append(children_cpu() - c0)
            return time.time() - t0

        t_local1 = local("local1")
        cases = sum(1 for _ in open(os.path.join(tmp, "local1", "cases.csv"))) - 1
        with LocalCluster(n_workers=ncores, threads_per_worker=1, host="127.0.0.1", dashboard_address=None,
                          processes=True) as cluster, Client(cluster) as client:
            client.run(lambda: __import__("mhcontact") and 0)  # the module loaded in each worker

            def workers_cpu():  # the workers' processes and their nannies'
                own = lambda: sum(resource.getrusage(resource.RUSAGE_SELF)[:2])
                return sum(client.run(own).values()) + sum(client.run(own, nanny=True).values())

            w0, c0, t0 = workers_cpu(), own_cpu(), time.time()
            shards = int(os.environ["SHARDS"]) if os.environ.get("SHARDS") else None
            with get_task_stream(client) as stream:
                res = mhcontact.fleet(case, client, os.path.join(tmp, "dask"), threads=int(os.environ.get("THREADS", "1")),
                                      shards=shards, split=os.environ.get("SPLIT") or None, sizes=os.environ.get("SIZES") or None)
            t_dask = time.time() - t0
            # Each worker's shards: how long it computed and when it ended, against the route's start
            # (the spread of the ends is the time one worker waited for the other's last shard).
            busy, end, shard_s = {}, {}, {}
            for task in stream.data:
                for part in task["startstops"]:
                    if part["action"] == "compute":
                        w = task["worker"]
                        busy[w] = busy.get(w, 0) + part["stop"] - part["start"]
                        end[w] = max(end.get(w, 0), part["stop"] - t0)
                        m = re.match(r"mhcontact-shard-(\d+)-of-", str(task["key"]))
                        if m:
                            shard_s[int(m.group(1))] = part["stop"] - part["start"]
            workers = "; ".join(f"worker {i + 1}: {busy[w]:.2f} s computing, ended at {end[w]:.2f} s"
                                for i, w in enumerate(sorted(busy)))
            cpu_client = own_cpu() - c0
            cpu_workers = workers_cpu() - w0
            # Dask's own CPU with nothing to compute, over the same wall time: one sleeping task
            # per worker (the event loops, heartbeats, memory monitor and the statistical profiler
            # of each worker; the scheduler in this process).
            w0, c0, t0 = workers_cpu(), own_cpu(), time.time()
            client.gather([client.submit(time.sleep, t_dask, pure=False) for _ in range(ncores)])
            t_idle = time.time() - t0
            cpu_idle = workers_cpu() - w0 + own_cpu() - c0
        t_local2 = local("local2")
        a, b = os.path.join(tmp, "local1"), os.path.join(tmp, "dask")
        for root, _, files in os.walk(a):
            for f in files:
                if f == "run.json":
                    continue  # the command line and times differ
                rel = os.path.relpath(os.path.join(root, f), a)
                assert filecmp.cmp(os.path.join(a, rel), os.path.join(b, rel), shallow=False), rel
        mean_local = (t_local1 + t_local2) / 2
        profiler = "on" if dask.config.get("distributed.worker.profile.enabled") else "off"
        intervals = ", ".join(f"{k} {dask.config.get('distributed.' + k)}" for k in
                              ("admin.tick.interval", "admin.system-monitor.interval", "worker.memory.monitor-interval"))
        print(f"{method}, {cases} cases, {ncores} cores: local {t_local1:.2f} s and {t_local2:.2f} s "
              f"({1e6 * mean_local / cases:.1f} us a case); Dask {t_dask:.2f} s ({1e6 * t_dask / cases:.1f} us a case, "
              f"{res['shards']} shards, split {os.environ.get('SPLIT') or 'planned'}, sizes {res['sizes']}): {100 * (t_dask / mean_local - 1):+.1f} % over the mean local; the same bytes; "
              f"CPU s: local {cpu_local[0]:.2f} and {cpu_local[1]:.2f}, Dask workers {cpu_workers:.2f} + client {cpu_client:.2f} "
              f"({100 * ((cpu_workers + cpu_client) / (sum(cpu_local) / 2) - 1):+.1f} %); "
              f"Dask idle over {t_idle:.1f} s: {cpu_idle:.2f} s CPU ({100 * cpu_idle / (sum(cpu_local) / 2):.1f} % of the local CPU); "
              f"workers' profiler {profiler}; {intervals}")
        print(f"shards by worker: {workers}")
        print("each shard's compute time, s: " + ", ".join(f"{k} {shard_s[k]:.2f}" for k in sorted(shard_s)))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
