"""Fleets and sweeps on a Dask cluster (docs/cluster.md).

    from dask.distributed import Client
    import mhcontact
    client = Client("tcp://scheduler:8786")            # or Client(LocalCluster(...))
    res = mhcontact.fleet("cases/fleet.json", client, "out/fleet")
    res["tables"]["cases"]["Fz_kN"]                     # the columns of out/fleet/cases.csv

The run is cut into shards as `mhcontact run --shard K/N` cuts it (a manifest: one shard per
pair; a case file: slices of its cases); each shard is one Dask task that runs the command's
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


def _shard_task(path, shard_dir, k, n, threads, digits, token=None):
    """One shard on a worker: run it, return (k, exit code, standard error, {file: bytes}), or
    with files None when the worker shares the client's file system (it finds the client's
    `token` file beside shard_dir, so what it wrote is already where the client looks: nothing
    is sent back)."""
    rc, err = _core._run_shard(path, shard_dir, k, n, threads, digits)
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


def fleet(path, client=None, out_dir=None, shards=None, threads=1, digits=10):
    """Run a case file or batch manifest `path` as shards on the Dask `client` (None: one after
    the other in this process) and merge them into `out_dir` (required). `shards`: how many
    (default: one per pair of a manifest; a case file: four per worker, at most its case count);
    `threads`: worker threads of each shard (default 1: Dask runs one task per worker thread);
    `digits`: significant digits of the tables (0: shortest round-trip, as --digits max).
    Returns {"out_dir", "exit_code" (merge's: 0 every case ok, 1 some not), "shards",
    "tables" (read_tables(out_dir), each table read when first used)}. Bad input raises mhcontact.InputError with the command's
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
        if client is None:
            k, rc, err, files = _shard_task(path, out_dir, 1, 1, threads, digits)
        else:
            with _Token(_os.path.dirname(out_dir)) as token:
                k, rc, err, files = client.submit(_shard_task, path, out_dir, 1, 1, threads, digits, token.value,
                                                  pure=False).result()
        _place(files, out_dir)
        return {"out_dir": out_dir, "exit_code": rc, "shards": 1, "tables": _Tables(out_dir)}
    dirs = [_os.path.join(out_dir + ".shards", "shard%d" % k) for k in range(1, shards + 1)]
    if client is None:
        results = [_shard_task(path, dirs[k - 1], k, shards, threads, digits) for k in range(1, shards + 1)]
    else:
        with _Token(out_dir + ".shards") as token:
            futures = [client.submit(_shard_task, path, dirs[k - 1], k, shards, threads, digits, token.value, pure=False,
                                     key="mhcontact-shard-%d-of-%d-%s" % (k, shards, _os.urandom(4).hex()))
                       for k in range(1, shards + 1)]
            results = client.gather(futures)
    for k, rc, err, files in results:
        _place(files, dirs[k - 1])
    rc, err = _core._merge(dirs, out_dir)
    return {"out_dir": out_dir, "exit_code": rc, "shards": shards, "tables": _Tables(out_dir)}
