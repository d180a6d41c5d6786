"""mhcontact.fleet on a Dask LocalCluster (127.0.0.1, two worker processes): the merged output
directory is byte for byte the command's, and the returned tables are its CSV tables
(docs/cluster.md, the Dask route)."""
import filecmp
import os
import subprocess

import numpy as np
import pytest
from dask.distributed import Client, LocalCluster

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")
FLEET = os.path.join(SRC, "cases", "fleet.json")
SWEEP = os.path.join(SRC, "cases", "manchester.json")


@pytest.fixture(scope="module")
def client():
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as c:
        yield c


def command_run(path, out):
    rc = subprocess.run([BINARY, "run", path, "-o", out, "-q"]).returncode
    assert rc in (0, 1), rc
    return rc


def same_files(a, b):
    """Every file of run a (as listed by its run.json's tree) is in b with the same bytes."""
    names = []
    for root, _, files in os.walk(a):
        names += [os.path.relpath(os.path.join(root, f), a) for f in files if f != "run.json"]
    assert names
    _, mismatch, errors = filecmp.cmpfiles(a, b, names, shallow=False)
    assert not mismatch and not errors, (mismatch, errors)
    return names


def same_tables(t, u):
    assert t.keys() == u.keys()
    for name in t:
        assert t[name].keys() == u[name].keys()
        for col in t[name]:
            np.testing.assert_array_equal(t[name][col], u[name][col], err_msg=name + "." + col)


def test_fleet_on_dask_equals_the_command(client, tmp_path):
    rc = command_run(FLEET, str(tmp_path / "single"))
    res = mhcontact.fleet(FLEET, client, tmp_path / "dask")
    # multi-Hertzian on 2 worker slots: one slice of the cases per slot (plan_shards)
    assert res["shards"] == 2 and res["exit_code"] == rc
    names = same_files(str(tmp_path / "single"), res["out_dir"])
    assert "cases.csv" in names and "pairs/3/geometry.json" in names
    same_tables(res["tables"], mhcontact.read_tables(str(tmp_path / "single")))
    cases = res["tables"]["cases"]
    assert len(cases["Fz_kN"]) == 4 * 33 * 3 and set(cases["pair"]) == {0, 1, 2, 3}


def test_fleet_pairs_cut_across_shards(client, tmp_path):
    # 3 slices of the 396 cases of 4 pairs (132 each: pairs 1 and 2 each cut between two shards),
    # and one shard per whole pair as before (split="pairs"): both the command's bytes.
    command_run(FLEET, str(tmp_path / "single"))
    res = mhcontact.fleet(FLEET, client, tmp_path / "cut", shards=3, split="cases")
    assert res["shards"] == 3 and res["sizes"] == "equal"  # fewer than two shards a worker slot
    assert '"unit": "pair_case"' in open(os.path.join(res["out_dir"] + ".shards", "shard2", "shard.json")).read()
    same_files(str(tmp_path / "single"), res["out_dir"])
    res = mhcontact.fleet(FLEET, client, tmp_path / "pairs", split="pairs")
    assert res["shards"] == 4
    same_files(str(tmp_path / "single"), res["out_dir"])
    # 8 slices on 2 slots: tapered by default (--shard-sizes tapered), the first 2/9 of the
    # cases (88), the last 1/36 (11); the same bytes.
    res = mhcontact.fleet(FLEET, client, tmp_path / "tapered", shards=8, split="cases")
    assert res["sizes"] == "tapered"
    shard = lambda k: open(os.path.join(res["out_dir"] + ".shards", "shard%d" % k, "cases.csv")).read().count("\n") - 1
    assert (shard(1), shard(8)) == (88, 11)
    same_files(str(tmp_path / "single"), res["out_dir"])
    with pytest.raises(ValueError, match="sizes"):
        mhcontact.fleet(FLEET, client, tmp_path / "bad", shards=8, split="cases", sizes="geometric")


def _timed(k, seconds):
    import time
    start = time.time()
    time.sleep(seconds)
    return k, start, time.time()


def test_shards_start_in_their_order(client):
    # Shard 1 long (6 s: room for a loaded machine's scheduling), the rest short, on 2 one-thread
    # workers: shards 1 and 2 start together (in either order), every later one only when a
    # worker is free, in k's order (a worker sent shard 3 ahead of time would hold it behind
    # shard 1 while the other ran 4, 5, ...).
    from mhcontact.fleet import _run_in_order
    res = _run_in_order(client, lambda k: client.submit(_timed, k, 6.0 if k == 1 else 0.1, pure=False), 8)
    assert [r[0] for r in res] == list(range(1, 9))
    later = [r[1] for r in res[2:]]
    assert later == sorted(later) and later[0] >= max(res[0][1], res[1][1]), [r[1] for r in res]
    assert res[2][1] < res[0][2]  # shard 3 ran beside shard 1, not after it


def test_plan_shards():
    # A manifest: by cases; multi-Hertzian one shard a slot, grid methods eight; never more
    # shards than cases. A case file: four a slot, as before.
    from mhcontact.fleet import plan_shards
    assert plan_shards("pair", 4, 96012, "multi-hertzian", 2) == (2, True)
    assert plan_shards("pair", 4, 396, "strips", 2) == (16, True)
    assert plan_shards("pair", 4, 396, "half-space", 8) == (64, True)
    assert plan_shards("pair", 1, 3, "strips", 2) == (3, True)
    assert plan_shards("case", 99, 99, "multi-hertzian", 2) == (8, False)


def test_sweep_on_dask_in_slices_of_cases(client, tmp_path):
    command_run(SWEEP, str(tmp_path / "single"))
    res = mhcontact.fleet(SWEEP, client, tmp_path / "dask", shards=3)
    assert res["shards"] == 3
    same_files(str(tmp_path / "single"), res["out_dir"])


def test_without_a_client_and_bad_input(tmp_path):
    res = mhcontact.fleet(SWEEP, None, tmp_path / "local", shards=2)
    command_run(SWEEP, str(tmp_path / "single"))
    same_files(str(tmp_path / "single"), res["out_dir"])
    bad = tmp_path / "bad.json"
    bad.write_text('{"wheels": ["nothing-*.prw"], "rails": [{"standard": "60E1"}], "inclination": "1:40"}')
    with pytest.raises(mhcontact.InputError, match="nothing-"):
        mhcontact.fleet(str(bad), None, tmp_path / "bad")


def test_a_worker_that_shares_the_file_system_sends_nothing_back(tmp_path):
    # The worker's side of the token (python/mhcontact/fleet.py): the client's token file found
    # with its bytes means the shard is already where the client reads it (nothing sent); a
    # missing or different token, a worker on another file system: every file sent back, and
    # the client writes them as the shard wrote them.
    import sys
    fl = sys.modules["mhcontact.fleet"]
    shard = str(tmp_path / "w" / "shard1")
    token = (str(tmp_path / "token"), b"0123456789abcdef")
    with open(token[0], "wb") as f:
        f.write(token[1])
    k, rc, _, files = fl._shard_task(SWEEP, shard, 1, 3, 1, 10, token)
    assert (k, files) == (1, None) and rc in (0, 1)
    k, rc, _, files = fl._shard_task(SWEEP, shard + "b", 1, 3, 1, 10, (token[0], b"another client.."))
    assert files is not None and "cases.csv" in files and "shard.json" in files
    fl._place(files, str(tmp_path / "client" / "shard1"))
    names = same_files(shard, str(tmp_path / "client" / "shard1"))
    assert "cases.csv" in names


def test_the_documented_dask_settings_reach_the_workers():
    """docs/cluster.md's settings for CPU-bound shards (the export block of its Dask section): each
    a key of Dask's own configuration, and the workers of a LocalCluster started in that
    environment run with them (a misspelt key would be ignored by Dask without a word)."""
    import json
    import re
    import sys

    import dask
    text = open(os.path.join(SRC, "docs", "cluster.md")).read()
    block = re.search(r"```sh\n\s*(export DASK_.*?)```", text, re.S).group(1)
    env = dict(re.findall(r"(DASK_[A-Z_]+)=(\S+?)\s*\\?\n", block))
    assert len(env) == 4, env
    keys = {}
    for name, value in env.items():
        key = name[len("DASK_"):].lower().replace("__", ".").replace("_", "-")
        assert dask.config.get(key, default=None) is not None, (name, key)  # a key of Dask's defaults
        keys[key] = value
    probe = ("import json, dask\n"
             "from dask.distributed import Client, LocalCluster\n"
             "if __name__ == '__main__':\n"
             "    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host='127.0.0.1',\n"
             "                      dashboard_address=None) as cluster, Client(cluster) as c:\n"
             "        keys = %r\n"
             "        got = c.run(lambda: {k: str(dask.config.get(k)) for k in keys})\n"
             "        print(json.dumps(list(got.values())[0]))\n" % sorted(keys))
    out = subprocess.run([sys.executable, "-c", probe], env={**os.environ, **env}, capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout.strip().splitlines()[-1])
    assert got == keys, (got, keys)


def test_table_on_dask_equals_the_command(client, tmp_path):
    """mhcontact.make_table (docs/cluster.md "Dask: contact tables"): a table refined in Q, so made
    in several passes, each pass's solves as Dask tasks on the two workers, merged here: the file
    is byte for byte the command's; the same with options; a bad option named."""
    import json
    case = json.load(open(os.path.join(SRC, "tests", "data", "tables", "worn-table-q.json")))
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "tests", "data", "tables", case[side]["profile"])
    path = str(tmp_path / "q.json")
    json.dump(case, open(path, "w"))
    single = str(tmp_path / "single.csv")
    assert subprocess.run([BINARY, "table", path, "-o", single, "-q", "--threads", "1"]).returncode == 0
    res = mhcontact.make_table(path, client, tmp_path / "dask.csv", shards=3)
    assert res["exit_code"] == 0 and res["passes"] >= 2 and res["shards"] == 3
    assert filecmp.cmp(single, res["out_path"], shallow=False)
    assert res["header"]["Q_kN_nodes"] == json.loads(open(single).readline()[2:])["Q_kN_nodes"]
    assert not os.path.exists(res["out_path"] + ".parts") and not os.path.exists(res["out_path"] + ".next.json")
    # Options as the command's: no refinement.
    flat = str(tmp_path / "flat.csv")
    assert subprocess.run([BINARY, "table", path, "-o", flat, "-q", "--refine", "0"]).returncode == 1
    res = mhcontact.make_table(path, client, tmp_path / "dask-flat.csv", shards=2, options={"refine": 0})
    assert res["exit_code"] == 1 and res["passes"] == 1
    assert filecmp.cmp(flat, res["out_path"], shallow=False)
    # The validation points as the command's --validate (20 of them; 0: none in the header).
    val = str(tmp_path / "val.csv")
    assert subprocess.run([BINARY, "table", path, "-o", val, "-q", "--refine", "0", "--validate", "20"]).returncode == 1
    res = mhcontact.make_table(path, client, tmp_path / "dask-val.csv", shards=2, options={"refine": 0, "validate": 20})
    assert filecmp.cmp(val, res["out_path"], shallow=False)
    assert res["header"]["validation"]["points"] == 20
    res = mhcontact.make_table(path, client, tmp_path / "dask-noval.csv", shards=2, options={"refine": 0, "validate": 0})
    assert "validation" not in res["header"]
    with pytest.raises(TypeError, match="unknown key 'refines'"):
        mhcontact.make_table(path, client, tmp_path / "x.csv", options={"refines": 0})
    with pytest.raises(ValueError, match="validate must be"):
        mhcontact.make_table(path, client, tmp_path / "x.csv", options={"validate": -1})
