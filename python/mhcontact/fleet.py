"""Fleets and sweeps on a Dask cluster (docs/cluster.md).

    from dask.distributed import Client
    import mhcontact
    client = Client("tcp://scheduler:8786")            # or Client(LocalCluster(...))
    res = mhcontact.fleet("cases/fleet.json", client, "out/fleet")
    res["tables"]["cases"]["Fz_kN"]                     # the columns of out/fleet/cases.csv

The run is cut into shards as `mhcontact run --shard K/N` cuts it (slices of the cases; a
manifest's by default as `--shard-by cases`: slices of every pair's cases, plan_shards()); each shard is one Dask task that runs the command's
own job in the worker process (lib/jobs, through mhcontact._core) into OUT.shards/shardK and,
unless it shares the client's file system (it finds the client's token file there), sends its
files back for the client to write there; the client joins them with the command's merge. OUT then holds byte for byte what `mhcontact run` writes.
Workers read the case file and the profiles at the paths the client names (a shared file system,
as on a cluster); the output directory need not be shared.
"""
import collections.abc as _abc
import csv as _csv
import os as _os

import numpy as _np

from . import _core


def _shard_task(path, shard_dir, k, n, threads, digits, token=None, by_cases=False, sizes="equal"):
    """One shard on a worker: run it, return (k, exit code, standard error, {file: bytes}), or
    with files None when the worker shares the client's file system (it finds the client's
    `token` file beside shard_dir, so what it wrote is already where the client looks: nothing
    is sent back). by_cases: a manifest's shard is a slice of every pair's cases (--shard-by
    cases), not of its pairs. sizes: "equal" or "tapered" (--shard-sizes)."""
    rc, err = _core._run_shard(path, shard_dir, k, n, threads, digits, by_cases, sizes)
    if token is not None:
        try:
            with open(token[0], "rb") as f:
                if f.read() == token[1]:
                    return k, rc, err, None
        except OSError:
            pass
    files = {}
    for root, _, names in _os.walk(shard_dir):
        for name in names:
            p = _os.path.join(root, name)
            with open(p, "rb") as f:
                files[_os.path.relpath(p, shard_dir)] = f.read()
    return k, rc, err, files


class _Token:
    """A file of random bytes in directory d while the shards run: a worker that finds it (its
    path and bytes) shares the client's file system, writes its shard where the client reads it
    and sends nothing back (a shard's files are as large as its output)."""

    def __init__(self, d):
        _os.makedirs(d or ".", exist_ok=True)
        self.value = (_os.path.join(d or ".", ".mhcontact-client-token-" + _os.urandom(4).hex()), _os.urandom(16))

    def __enter__(self):
        with open(self.value[0], "wb") as f:
            f.write(self.value[1])
        return self

    def __exit__(self, *exc):
        _os.remove(self.value[0])


def _place(files, d):
    """Write a shard's files into d (None: the worker wrote them there, a shared file system)."""
    if files is None:
        return
    for rel, data in files.items():
        p = _os.path.join(d, rel)
        _os.makedirs(_os.path.dirname(p), exist_ok=True)
        with open(p, "wb") as f:
            f.write(data)


def _column(values):
    """A CSV column as a float array (NaN for an empty cell) when every cell is a number, else
    an array of str."""
    try:
        return _np.array([float(v) if v != "" else _np.nan for v in values], dtype=float)
    except ValueError:
        return _np.array(values, dtype=object)


def read_tables(out_dir):
    """Every CSV table of a run's output directory: {name without .csv: {column: array}}."""
    t = _Tables(out_dir)
    return {name: t[name] for name in t}


class _Tables(_abc.Mapping):
    """read_tables(out_dir), each table read on first access (reading a table of 100,000 rows
    into numpy columns takes seconds in Python, more than running its cases)."""

    def __init__(self, out_dir):
        self._dir = out_dir
        self._names = sorted(n[:-4] for n in _os.listdir(out_dir) if n.endswith(".csv"))
        self._read = {}

    def __getitem__(self, name):
        if name not in self._names:
            raise KeyError(name)
        if name not in self._read:
            with open(_os.path.join(self._dir, name + ".csv"), newline="") as f:
                rows = list(_csv.reader(f))
            header, body = rows[0], rows[1:]
            self._read[name] = {c: _column([r[i] for r in body]) for i, c in enumerate(header)}
        return self._read[name]

    def __iter__(self):
        return iter(self._names)

    def __len__(self):
        return len(self._names)


def _worker_slots(client):
    """The tasks a Dask cluster runs at once: its workers' threads (1 without a client)."""
    if client is None:
        return 1
    return max(1, sum(w.get("nthreads", 1) for w in client.scheduler_info()["workers"].values()))


def _run_in_order(client, submit, n):
    """submit(k) for k = 1 ... n on `client`, at most as many running as the cluster has worker
    threads, the next submitted as one ends; returns the tasks' results (each a tuple whose first
    element is its k) in k's order. So the
    shards start in their order (tapered slices: the smallest last) whatever the scheduler's own
    queueing: Dask 2022.12 sends each one-thread worker a second task ahead of time
    (distributed.scheduler.worker-saturation 1.1), which let a large late shard wait behind
    another on a busy worker while the other went idle (docs/cluster.md#cost). A task's exception
    is raised here."""
    from dask.distributed import as_completed
    results = [None] * n
    k = 0
    running = as_completed()
    while k < min(n, _worker_slots(client)):
        k += 1
        running.add(submit(k))
    for future in running:
        r = future.result()
        results[r[0] - 1] = r
        if k < n:
            k += 1
            running.add(submit(k))
    return results


def plan_shards(unit, units, cases, method, slots):
    """(shards, by_cases): how fleet() cuts a run for `slots` tasks at once. Every shard is a
    slice of the cases (a manifest's: of every pair's cases, pair after pair), so shards of one
    run hold equal case counts whatever the pairs. The multi-Hertzian method costs about the
    same per case on every pair (tens of µs): one shard per slot, and the slots finish together
    with the least fixed cost (each shard reads its profiles and builds its pairs' geometry). The
    grid methods (milliseconds a case, and pairs that differ several-fold in cost): eight shards a
    slot, handed out as slots free up, so that a slot ends at most about an eighth of its share
    after the others (with four, the workers' ends were 7-19 % of the run apart; docs/cluster.md).
    At most one shard a case."""
    if unit == "case":
        # A case file: slices of its cases, as before (four a slot).
        return max(1, min(units, 4 * slots)), False
    per_slot = 1 if method == "multi-hertzian" else 8
    return max(1, min(cases, per_slot * slots)), True


def fleet(path, client=None, out_dir=None, shards=None, threads=1, digits=10, split=None, sizes=None):
    """Run a case file or batch manifest `path` as shards on the Dask `client` (None: one after
    the other in this process) and merge them into `out_dir` (required). `shards`: how many
    (default: one per pair of a manifest; a case file: four per worker, at most its case count);
    `threads`: worker threads of each shard (default 1: Dask runs one task per worker thread);
    `digits`: significant digits of the tables (0: shortest round-trip, as --digits max).
    `split` (a manifest): "cases" slices every pair's cases (a pair may be spread over shards,
    joined back by the merge), "pairs" gives each shard whole pairs; default: "cases" with the
    shard count of plan_shards() (docs/cluster.md), "pairs" with one shard per pair when
    `shards` is given without `split`.
    `sizes`: "equal" slices, or "tapered" (`--shard-sizes tapered`: shard K's share proportional to
    N - K + 1; Dask hands the shards out in order as workers free up, so the last to start are the
    smallest and the workers end together whatever the cases cost); default "tapered" on a
    client with at least two shards a worker thread, else "equal".
    Returns {"out_dir", "exit_code" (merge's: 0 every case ok, 1 some not), "shards",
    "tables" (read_tables(out_dir), each table read when first used)}. Bad input raises mhcontact.InputError with the command's
    message; a failed task raises its exception."""
    if out_dir is None:
        raise ValueError("out_dir: give the output directory of the merged run")
    path, out_dir = _os.path.abspath(path), _os.path.abspath(str(out_dir).rstrip("/"))
    unit, count, cases, method = _core._fleet_plan(path)
    if split not in (None, "cases", "pairs"):
        raise ValueError("split: \"cases\" or \"pairs\", not %r" % (split,))
    by_cases = False
    if unit == "pair":
        if split == "cases" or (split is None and shards is None):
            planned, by_cases = plan_shards(unit, count, cases, method, _worker_slots(client))
            shards = planned if shards is None else shards
        elif shards is None:
            shards = count
    elif shards is None:
        shards = plan_shards(unit, count, cases, method, _worker_slots(client))[0]
    shards = max(1, min(int(shards), max(1, cases if by_cases else count), 100000))
    if sizes is None:
        sizes = "tapered" if client is not None and shards >= 2 * _worker_slots(client) else "equal"
    if sizes not in ("equal", "tapered"):
        raise ValueError("sizes: \"equal\" or \"tapered\", not %r" % (sizes,))
    if shards == 1:  # no slices: one run straight into out_dir
        if client is None:
            k, rc, err, files = _shard_task(path, out_dir, 1, 1, threads, digits)
        else:
            with _Token(_os.path.dirname(out_dir)) as token:
                k, rc, err, files = client.submit(_shard_task, path, out_dir, 1, 1, threads, digits, token.value,
                                                  pure=False).result()
        _place(files, out_dir)
        return {"out_dir": out_dir, "exit_code": rc, "shards": 1, "sizes": "equal", "tables": _Tables(out_dir)}
    dirs = [_os.path.join(out_dir + ".shards", "shard%d" % k) for k in range(1, shards + 1)]
    if client is None:
        results = [_shard_task(path, dirs[k - 1], k, shards, threads, digits, None, by_cases, sizes) for k in range(1, shards + 1)]
    else:
        with _Token(out_dir + ".shards") as token:
            results = _run_in_order(client, lambda k: client.submit(
                _shard_task, path, dirs[k - 1], k, shards, threads, digits, token.value, by_cases, sizes, pure=False,
                key="mhcontact-shard-%d-of-%d-%s" % (k, shards, _os.urandom(4).hex())), shards)
    for k, rc, err, files in results:
        _place(files, dirs[k - 1])
    rc, err = _core._merge(dirs, out_dir)
    return {"out_dir": out_dir, "exit_code": rc, "shards": shards, "sizes": sizes, "tables": _Tables(out_dir)}


def _table_task(path, k, n, points, threads, options):
    """One shard of one pass of making a contact table, on a worker: (k, exit code, standard
    error, the shard file's bytes). `points`: the bytes of the pass's points file, which the
    merge wrote on the client (None: the first round's points, the worker makes them itself)."""
    import tempfile
    points_path = ""
    if points is not None:
        fd, points_path = tempfile.mkstemp(prefix="mhcontact-table-points-", suffix=".json")
        with _os.fdopen(fd, "wb") as f:
            f.write(points)
    try:
        rc, err, data = _core._table_shard(path, k, n, points_path, threads, options)
    finally:
        if points_path:
            _os.remove(points_path)
    return k, rc, err, data


def make_table(path, client=None, out_path=None, shards=None, threads=1, options=None):
    """Make the contact table of case file `path` (docs/tables.md) with its solves as Dask tasks
    on `client` (None: one after the other in this process) and write it to `out_path`
    (required): each pass (the first round's points, then each refinement's) is `shards` tasks
    (default: four per worker thread), each solving its slice of the pass's points as
    `mhcontact table --shard K/N [--points NEXT]` does, in the worker process; this process
    merges them (`--merge ... --next`) until the table is made, byte for byte the one-process
    table. `options`: the command's options as a dict (refine, check, min_step_mm,
    min_Q_step_kN, min_roll_step_mrad, tol_N, tol_pmax). Workers read the case file and the
    profiles at the paths the client names; only the shard files travel back.
    Returns {"out_path", "exit_code" (the command's: 0, or 1 with coarse cells or nodes without
    an answer), "passes", "shards", "header" (the table's JSON header as a dict)}. Bad input
    raises mhcontact.InputError with the command's message; a task that fails raises
    RuntimeError naming its shard and pass."""
    import json
    import shutil
    if out_path is None:
        raise ValueError("out_path: give the table file to write")
    path, out_path = _os.path.abspath(path), _os.path.abspath(str(out_path))
    options = dict(options or {})
    shards = max(1, min(int(shards) if shards is not None else 4 * _worker_slots(client), 100000))
    parts_dir = out_path + ".parts"
    next_path = out_path + ".next.json"
    _os.makedirs(parts_dir, exist_ok=True)
    parts, points, passes = [], None, 0
    try:
        while True:
            if client is None:
                results = [_table_task(path, k, shards, points, threads, options) for k in range(1, shards + 1)]
            else:
                # In order, no more at once than the worker threads (as fleet(): _run_in_order).
                tag = _os.urandom(4).hex()
                results = _run_in_order(client, lambda k: client.submit(
                    _table_task, path, k, shards, points, threads, options, pure=False,
                    key="mhcontact-table-pass%d-shard-%d-of-%d-%s" % (passes, k, shards, tag)), shards)
            for k, rc, err, data in results:
                if rc != 0:
                    raise RuntimeError("table shard %d/%d of pass %d: exit %d: %s" % (k, shards, passes, rc, err.strip()))
                part = _os.path.join(parts_dir, "pass%d-%d.json" % (passes, k))
                with open(part, "wb") as f:
                    f.write(data)
                parts.append(part)
            rc, err = _core._table_merge(path, parts, next_path, out_path, threads, options)
            passes += 1
            if rc != 5:
                break
            with open(next_path, "rb") as f:
                asked = f.read()
            if asked == points:  # the pass's parts did not hold its points: a loop, not progress
                raise RuntimeError("table merge: pass %d's points asked again (%s)" % (passes, next_path))
            points = asked
    finally:
        shutil.rmtree(parts_dir, ignore_errors=True)
        if _os.path.exists(next_path):
            _os.remove(next_path)
    if rc not in (0, 1):
        raise RuntimeError("table merge: exit %d: %s" % (rc, err.strip()))
    with open(out_path) as f:
        header = json.loads(f.readline()[2:])
    return {"out_path": out_path, "exit_code": rc, "passes": passes, "shards": shards, "header": header}
