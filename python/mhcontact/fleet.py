"""Fleets and sweeps on a Dask cluster (docs/cluster.md).

    from dask.distributed import Client
    import mhcontact
    client = Client("tcp://scheduler:8786")            # or Client(LocalCluster(...))
    res = mhcontact.fleet("cases/fleet.json", client, "out/fleet")
    res["tables"]["cases"]["Fz_kN"]                     # the columns of out/fleet/cases.csv

The run is cut into shards as `mhcontact run --shard K/N` cuts it (a manifest: one shard per
pair; a case file: slices of its cases); each shard is one Dask task that runs the command's
own job in the worker process (lib/jobs, through mhcontact._core) and sends its files back;
the client writes them to OUT.shards/shardK if the worker's file system is not its own, and
joins them with the command's merge. OUT then holds byte for byte what `mhcontact run` writes.
Workers read the case file and the profiles at the paths the client names (a shared file system,
as on a cluster); the output directory need not be shared.
"""
import csv as _csv
import os as _os

import numpy as _np

from . import _core


def _shard_task(path, shard_dir, k, n, threads, digits):
    """One shard on a worker: run it, return (k, exit code, standard error, {file: bytes})."""
    rc, err = _core._run_shard(path, shard_dir, k, n, threads, digits)
    files = {}
    for root, _, names in _os.walk(shard_dir):
        for name in names:
            p = _os.path.join(root, name)
            with open(p, "rb") as f:
                files[_os.path.relpath(p, shard_dir)] = f.read()
    return k, rc, err, files


def _place(files, d):
    """Write a shard's files into d unless d already holds them (a shared file system)."""
    if _os.path.exists(_os.path.join(d, "run.json")):
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
    tables = {}
    for name in sorted(_os.listdir(out_dir)):
        if not name.endswith(".csv"):
            continue
        with open(_os.path.join(out_dir, name), newline="") as f:
            rows = list(_csv.reader(f))
        header, body = rows[0], rows[1:]
        tables[name[:-4]] = {c: _column([r[i] for r in body]) for i, c in enumerate(header)}
    return tables


def fleet(path, client=None, out_dir=None, shards=None, threads=1, digits=10):
    """Run a case file or batch manifest `path` as shards on the Dask `client` (None: one after
    the other in this process) and merge them into `out_dir` (required). `shards`: how many
    (default: one per pair of a manifest; a case file: four per worker, at most its case count);
    `threads`: worker threads of each shard (default 1: Dask runs one task per worker thread);
    `digits`: significant digits of the tables (0: shortest round-trip, as --digits max).
    Returns {"out_dir", "exit_code" (merge's: 0 every case ok, 1 some not), "shards",
    "tables" (read_tables(out_dir))}. Bad input raises mhcontact.InputError with the command's
    message; a failed task raises its exception."""
    if out_dir is None:
        raise ValueError("out_dir: give the output directory of the merged run")
    path, out_dir = _os.path.abspath(path), _os.path.abspath(str(out_dir).rstrip("/"))
    unit, count = _core._fleet_units(path)
    if shards is None:
        if unit == "pair":
            shards = count
        else:
            workers = len(client.scheduler_info()["workers"]) if client is not None else 1
            shards = min(count, 4 * max(1, workers))
    shards = max(1, min(int(shards), max(1, count), 100000))
    if shards == 1:  # no slices: one run straight into out_dir
        k, rc, err, files = (client.submit(_shard_task, path, out_dir, 1, 1, threads, digits, pure=False).result()
                             if client is not None else _shard_task(path, out_dir, 1, 1, threads, digits))
        _place(files, out_dir)
        return {"out_dir": out_dir, "exit_code": rc, "shards": 1, "tables": read_tables(out_dir)}
    dirs = [_os.path.join(out_dir + ".shards", "shard%d" % k) for k in range(1, shards + 1)]
    if client is None:
        results = [_shard_task(path, dirs[k - 1], k, shards, threads, digits) for k in range(1, shards + 1)]
    else:
        futures = [client.submit(_shard_task, path, dirs[k - 1], k, shards, threads, digits, pure=False,
                                 key="mhcontact-shard-%d-of-%d-%s" % (k, shards, _os.urandom(4).hex()))
                   for k in range(1, shards + 1)]
        results = client.gather(futures)
    for k, rc, err, files in results:
        _place(files, dirs[k - 1])
    rc, err = _core._merge(dirs, out_dir)
    return {"out_dir": out_dir, "exit_code": rc, "shards": shards, "tables": read_tables(out_dir)}
