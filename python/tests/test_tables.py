"""Contact tables from Python (docs/tables.md): mhcontact.Table over the C interface, its lookup
and lookup_many against each other and against the table's nodes, and its errors."""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import pytest

import mhcontact

SRC = os.environ.get("MHCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MHCONTACT_BINARY", "mhcontact")


@pytest.fixture(scope="module")
def table_path():
    d = tempfile.mkdtemp()
    path = os.path.join(d, "table.csv")
    rc = subprocess.run([BINARY, "table", os.path.join(SRC, "cases", "s1002-60e1-table.json"), "-o", path, "-q",
                         "--threads", "2"]).returncode
    assert rc in (0, 1)
    return path


def test_table_lookup(table_path):
    t = mhcontact.Table(table_path)
    h = json.loads(t.header)
    assert h["schema"] == "mhcontact.table/2"
    assert t.range == pytest.approx((-4e-3, 10e-3, 20e3, 140e3))
    # At a node the table gives the node's values (the file's rows).
    with open(table_path) as f:
        f.readline()
        names = f.readline().strip().split(",")
        rows = [dict(zip(names, l.strip().split(","))) for l in f]
    node = [r for r in rows if float(r["tY_mm"]) == 2 and float(r["Q_kN"]) == 60 and r["present"] == "1"]
    a = t.lookup(2e-3, 60e3)
    assert a["status"] == "ok"
    assert a["n_contacts"] == len(node) == 1
    assert a["contacts"][0]["N_N"] == pytest.approx(float(node[0]["N_kN"]) * 1e3, rel=1e-12)
    assert a["contacts"][0]["p_max_Pa"] == pytest.approx(float(node[0]["pmax_MPa"]) * 1e6, rel=1e-12)
    # lookup_many equals lookup.
    tY = np.linspace(-4e-3, 10e-3, 997)
    Q = np.full_like(tY, 73e3)
    m = t.lookup_many(tY, Q)
    for i in range(0, len(tY), 37):
        one = t.lookup(tY[i], Q[i])
        assert mhcontact.STATUS_NAMES[m["status"][i]] == one["status"]
        assert m["n_contacts"][i] == one["n_contacts"]
        assert m["Fy_N"][i] == one["Fy_N"]
        for k, c in enumerate(one["contacts"]):
            assert m["N_N"][i, k] == c["N_N"] and m["track"][i, k] == c["track"]
            assert m["dN_dtY_N_per_m"][i, k] == c["d_dtY"]["N_N"]
    assert (m["n_contacts"] > 1).any()  # two-point contact near flange onset
    # Outside: out_of_range, no contact.
    assert t.lookup(11e-3, 60e3)["status"] == "out_of_range"
    # The cost of lookup_many (printed, not asserted: the machine is shared).
    tY = 6e-3 * np.sin(np.linspace(0, 10 * np.pi, 10000)) + 3e-3
    # CPU time of the thread, best of 5: the first calls also fault in the output arrays' pages.
    dt = []
    for _ in range(5):
        t0 = time.thread_time()
        m = t.lookup_many(tY, np.full_like(tY, 60e3))
        dt.append(time.thread_time() - t0)
    dt = min(dt)
    print(f"lookup_many: {dt / len(tY) * 1e6:.3f} us a point, {dt / max(1, m['n_contacts'].sum()) * 1e6:.3f} us a contact")


def test_table_lookup_into(table_path):
    """lookup_into fills a reused TableResult whose views equal lookup's dicts at every point, the
    slots past n_contacts zero; the views taken once follow later lookups (docs/python.md)."""
    t = mhcontact.Table(table_path)
    r = mhcontact.TableResult()
    fields = mhcontact.TableResult.FIELDS
    assert fields[0] == "N_N" and len(fields) == 15
    values, d_dtY, d_dQ, track = r.values, r.d_dtY, r.d_dQ, r.track
    assert values.shape == (mhcontact.MAX_CONTACTS, len(fields))
    seen_two = False
    for tY in np.linspace(-4.2e-3, 10.1e-3, 301):
        for Q in (20e3, 47e3, 139e3):
            code = t.lookup_into(tY, Q, r)
            one = t.lookup(tY, Q)
            assert mhcontact.STATUS_NAMES[code] == r.status == one["status"]
            assert r.status_code == code
            assert (r.coarse, r.n_contacts) == (one["coarse"], one["n_contacts"])
            assert (r.Fz_N, r.Fy_N, r.dFy_dtY_N_per_m, r.dFy_dQ) == (
                one["Fz_N"], one["Fy_N"], one["dFy_dtY_N_per_m"], one["dFy_dQ"])
            assert (r.tY_m, r.Q_N) == (tY, Q)
            n = min(r.n_contacts, mhcontact.MAX_CONTACTS)
            seen_two = seen_two or n > 1
            for k, c in enumerate(one["contacts"]):
                assert track[k] == c["track"]
                for f, name in enumerate(fields):
                    assert values[k, f] == c[name]
                    assert d_dtY[k, f] == c["d_dtY"][name]
                    assert d_dQ[k, f] == c["d_dQ"][name]
            assert not values[n:].any() and not d_dtY[n:].any() and not track[n:].any()
    assert seen_two
    # The pattern of docs/python.md.
    N = r.values[:, 0]
    assert t.lookup_into(2e-3, 60e3, r) == 0
    assert N[:r.n_contacts].sum() == pytest.approx(t.lookup(2e-3, 60e3)["contacts"][0]["N_N"], rel=1e-15)
    # Outside the table: out_of_range, no contact.
    assert mhcontact.STATUS_NAMES[t.lookup_into(11e-3, 60e3, r)] == "out_of_range"
    assert r.n_contacts == 0 and not values.any()
    # The views keep the result alive.
    v = mhcontact.TableResult().values
    assert v.shape == (mhcontact.MAX_CONTACTS, len(fields)) and not v.any()
    with pytest.raises(TypeError):
        t.lookup_into(0.0, 60e3, None)


def test_table_lookup_many_out(table_path):
    """lookup_many(..., out=) writes into the caller's arrays (the same objects, the same memory)
    the values lookup_many returns freshly; arrays of another shape, dtype or layout are refused
    with the key and the rule (docs/python.md)."""
    t = mhcontact.Table(table_path)
    tY = np.linspace(-4.2e-3, 10.1e-3, 613)
    Q = np.full_like(tY, 58e3)
    fresh = t.lookup_many(tY, Q)
    out = mhcontact.Table.many_result(len(tY))
    assert sorted(out) == sorted(fresh)
    where = {k: v.__array_interface__["data"][0] for k, v in out.items()}
    ret = t.lookup_many(tY, Q, out=out)
    assert ret is out
    for k, v in fresh.items():
        assert out[k].dtype == v.dtype and out[k].shape == v.shape
        assert np.array_equal(out[k], v), k
        assert out[k].__array_interface__["data"][0] == where[k], k
    # Reused for other points: every slot rewritten (a slot emptied since is 0 again).
    t.lookup_many(tY[::-1].copy(), Q, out=out)
    again = t.lookup_many(tY[::-1].copy(), Q)
    for k, v in again.items():
        assert np.array_equal(out[k], v), k
    # A dict that lookup_many returned serves as out too.
    t.lookup_many(tY, Q, out=again)
    assert np.array_equal(again["N_N"], fresh["N_N"])
    with pytest.raises(ValueError, match=r'out\["status"\]: must be a writeable C-contiguous int8 array of shape \(612,\) for 612 points'):
        t.lookup_many(tY[:612], Q[:612], out=out)
    bad = mhcontact.Table.many_result(len(tY))
    bad["Fy_N"] = np.zeros(len(tY), dtype=np.float32)
    with pytest.raises(ValueError, match=r'out\["Fy_N"\]'):
        t.lookup_many(tY, Q, out=bad)
    bad = mhcontact.Table.many_result(len(tY))
    bad["track"] = np.zeros((6, len(tY)), dtype=np.int32).T
    with pytest.raises(ValueError, match=r'out\["track"\]'):
        t.lookup_many(tY, Q, out=bad)
    del bad["track"]
    with pytest.raises(ValueError, match="the key track is missing"):
        t.lookup_many(tY, Q, out=bad)
    # The cost with and without out= (printed, not asserted: the machine is shared), CPU time of
    # the thread, median of 15 calls on 10,000 points.
    tY = 6e-3 * np.sin(np.linspace(0, 10 * np.pi, 10000)) + 3e-3
    Q = np.full_like(tY, 60e3)
    out = mhcontact.Table.many_result(len(tY))
    for name, call in (("fresh arrays", lambda: t.lookup_many(tY, Q)), ("out=", lambda: t.lookup_many(tY, Q, out=out))):
        dt = []
        for _ in range(15):
            t0 = time.thread_time()
            call()
            dt.append(time.thread_time() - t0)
        print(f"lookup_many, {name}: {sorted(dt)[7] / len(tY) * 1e6:.3f} us a point (median of 15)")


def test_table_errors(tmp_path, table_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("tY_mm,Q_kN\n1,2\n")
    with pytest.raises(mhcontact.InputError, match="bad.csv:1"):
        mhcontact.Table(str(bad))
    with pytest.raises(ValueError, match="differ in length"):
        mhcontact.Table(table_path).lookup_many(np.zeros(3), np.zeros(2))


def test_bench_table_python_runs(table_path):
    """bench/tables/bench_table_python.py (docs/performance.md "Contact tables") runs as shown, on a
    short history: every way timed, the C lookup first with ratio 1."""
    import sys
    out = subprocess.run([sys.executable, os.path.join(SRC, "bench", "tables", "bench_table_python.py"), table_path, "500"],
                         capture_output=True, text=True, check=True).stdout
    rows = {l.split()[0]: l.split()[1:] for l in out.splitlines()[2:]}
    assert list(rows) == ["C", "lookup_into", "lookup", "lookup_many", "many_out", "loop"]
    assert float(rows["C"][2]) == 1.0 and all(float(v[0]) > 0 for v in rows.values())


def test_table_roll_axis(tmp_path):
    """A table with a roll axis (docs/tables.md "Roll"): lookup, lookup_into and lookup_many at a
    roll agree, d/droll is the interpolant's slope, and the roll-0 table answers at another roll
    with off_roll and outside_validity."""
    case = json.load(open(os.path.join(SRC, "tests", "data", "tables", "worn-table-roll.json")))
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "tests", "data", "tables", case[side]["profile"])
    case["sweep"] = {"tY_mm": [-1, 0, 1], "Q_kN": [40, 80], "roll_mrad": [-1, 0, 1, 2]}
    json.dump(case, open(tmp_path / "roll.json", "w"))
    path = str(tmp_path / "roll.csv")
    assert subprocess.run([BINARY, "table", str(tmp_path / "roll.json"), "-o", path, "-q", "--threads", "2",
                           "--refine", "0"]).returncode == 0
    t = mhcontact.Table(path)
    assert t.roll_range == pytest.approx((-1e-3, 2e-3, 4))
    a = t.lookup(0.4e-3, 60e3, roll_rad=0.7e-3)
    assert a["status"] == "ok" and not a["off_roll"] and a["n_contacts"] == 1
    h = 1e-8
    up, dn = t.lookup(0.4e-3, 60e3, roll_rad=0.7e-3 + h), t.lookup(0.4e-3, 60e3, roll_rad=0.7e-3 - h)
    slope = (up["contacts"][0]["p_max_Pa"] - dn["contacts"][0]["p_max_Pa"]) / (2 * h)
    assert a["contacts"][0]["d_droll"]["p_max_Pa"] == pytest.approx(slope, rel=1e-5)
    assert a["dFy_droll_N_per_rad"] == pytest.approx((up["Fy_N"] - dn["Fy_N"]) / (2 * h), rel=1e-5)
    r = mhcontact.TableResult()
    t.lookup_into(0.4e-3, 60e3, r, roll_rad=0.7e-3)
    assert r.roll_rad == 0.7e-3 and r.values[0, 6] == a["contacts"][0]["p_max_Pa"]
    assert r.d_droll[0, 0] == a["contacts"][0]["d_droll"]["N_N"]
    roll = np.linspace(-1e-3, 2e-3, 31)
    m = t.lookup_many(np.full_like(roll, 0.4e-3), np.full_like(roll, 60e3), roll_rad=roll)
    for i in range(0, 31, 5):
        one = t.lookup(0.4e-3, 60e3, roll_rad=roll[i])
        assert m["p_max_Pa"][i, 0] == one["contacts"][0]["p_max_Pa"]
        assert m["dN_droll_N_per_rad"][i, 0] == one["contacts"][0]["d_droll"]["N_N"]
        assert m["dFy_droll_N_per_rad"][i] == one["dFy_droll_N_per_rad"]
    assert t.lookup(0.4e-3, 60e3, roll_rad=2.1e-3)["status"] == "out_of_range"
    with pytest.raises(ValueError):
        t.lookup_many(np.zeros(3), np.full(3, 60e3), roll_rad=np.zeros(2))
    # The same pair without a roll axis, asked at a roll: its answer, marked.
    case["sweep"] = {"tY_mm": [-1, 0, 1], "Q_kN": [40, 80]}
    json.dump(case, open(tmp_path / "flat.json", "w"))
    flat = str(tmp_path / "flat.csv")
    assert subprocess.run([BINARY, "table", str(tmp_path / "flat.json"), "-o", flat, "-q", "--refine", "0"]).returncode == 0
    f = mhcontact.Table(flat)
    assert f.roll_range == pytest.approx((0.0, 0.0, 1))
    b = f.lookup(0.4e-3, 60e3, roll_rad=0.7e-3)
    assert b["off_roll"] and b["status"] == "outside_validity" and b["n_contacts"] == 1
    assert "d_droll" not in b["contacts"][0] and "dFy_droll_N_per_rad" not in b  # 0 without a roll axis
    assert f.lookup(0.4e-3, 60e3)["status"] == "ok"


def test_wheelset_table(tmp_path):
    """A wheelset table (docs/tables.md "A wheelset table"): both wheels placed from the wheelset's
    y and roll by the placement in its header (computed here from the header's numbers), each
    wheel's answer its pair table's at that point, the forces in the track frame, lookup_into as
    lookup."""
    case = json.load(open(os.path.join(SRC, "tests", "data", "tables", "worn-table-roll.json")))
    for side in ("wheel", "rail"):
        case[side]["profile"] = os.path.join(SRC, "tests", "data", "tables", case[side]["profile"])
    case["sweep"] = {"tY_mm": [-2, -1, 0, 1, 2], "Q_kN": [40, 80], "roll_mrad": [-2, 0, 2]}
    json.dump(case, open(tmp_path / "roll.json", "w"))
    pair, ws = str(tmp_path / "pair.csv"), str(tmp_path / "wheelset.csv")
    assert subprocess.run([BINARY, "table", str(tmp_path / "roll.json"), "-o", pair, "-q", "--threads", "2",
                           "--refine", "0"]).returncode == 0
    assert subprocess.run([BINARY, "table-wheelset", pair, pair, "-o", ws, "-q"]).returncode == 0
    t, w = mhcontact.Table(pair), mhcontact.WheelsetTable(ws)
    h = json.loads(w.header)
    assert h["schema"] == "mhcontact.wheelset-table/1"
    place = h["left"]["wheelset_placement"]
    a, H = place["a_mm"] * 1e-3, place["axle_height_mm"] * 1e-3
    assert w.pair_range(1)[:2] == pytest.approx((-2e-3, 2e-3))
    out = mhcontact.WheelsetTableResult()
    for y, roll in ((-0.7e-3, 1.3e-3), (0.4e-3, -0.9e-3)):
        d = w.lookup(y, roll, 50e3, 70e3)
        assert d["status"] == "ok"
        for s, (name, Q) in enumerate((("left", 50e3), ("right", 70e3))):
            sigma = 1 if s == 0 else -1
            delta = sigma * roll
            tY = sigma * y + a * (np.cos(delta) - 1) + H * np.sin(delta)
            e = d[name]
            assert e["tY_m"] == pytest.approx(tY, abs=1e-12) and e["roll_rad"] == delta
            p = t.lookup(tY, Q, roll_rad=delta)
            assert e["contacts"][0]["p_max_Pa"] == pytest.approx(p["contacts"][0]["p_max_Pa"], rel=1e-12)
            assert e["Fy_N"] == pytest.approx(-sigma * p["Fy_N"], rel=1e-12)
            assert e["Fz_N"] == pytest.approx(Q, rel=0.01)
        assert d["Fy_N"] == pytest.approx(d["left"]["Fy_N"] + d["right"]["Fy_N"], rel=1e-12)
        assert w.lookup_into(y, roll, 50e3, 70e3, out) == 0
        assert out.Fy_N == d["Fy_N"] and out.Mx_Nm == d["Mx_Nm"] and out.wheel_tY_m[1] == d["right"]["tY_m"]
        # Every number of the dict is the C result's (lookup_into reads the same struct).
        assert out.status == d["status"] and out.Fz_N == d["Fz_N"]
        assert out.dFy_dy_N_per_m == d["dFy_dy_N_per_m"] and out.dFy_droll_N_per_rad == d["dFy_droll_N_per_rad"]
        for s, name in enumerate(("left", "right")):
            e = d[name]
            assert (out.wheel_tY_m[s], out.wheel_Fy_N[s], out.wheel_Fz_N[s], out.wheel_dFy_dQ[s]) == \
                (e["tY_m"], e["Fy_N"], e["Fz_N"], e["dFy_dQ"])
            assert e["n_contacts"] == len(e["contacts"]) and e["coarse"] is False and e["off_roll"] is False
            assert e["Mx_Nm"] != 0 and e["dFy_dy_N_per_m"] != 0 and set(e["contacts"][0]) >= {"track", "d_dtY", "d_dQ", "d_droll"}
    assert w.lookup(3e-3, 0.0, 50e3, 70e3)["status"] == "out_of_range"
    with pytest.raises(mhcontact.InputError, match="one pair's table"):
        mhcontact.WheelsetTable(pair)
    # scripts/check_table.py (docs/tables.md "Checking a table at random points"): the table
    # against direct solves of its own case at random points; exit 0 (all within tolerance) or 1.
    script = os.path.join(SRC, "scripts", "check_table.py")
    run = subprocess.run([sys.executable, script, pair, str(tmp_path / "roll.json"), "--points", "12", "--seed", "3"],
                         capture_output=True, text=True)
    assert run.returncode in (0, 1), run.stderr
    lines = run.stdout.splitlines()
    assert lines[0].startswith(f"check_table.py: {pair}: 12 random points (seed 3) over t_Y -2 ... 2 mm, Q 40 ... 80 kN, "
                               "roll -2 ... 2 mrad")
    assert lines[1].startswith("ok: direct ") and lines[2].startswith("pmax: median ")
    assert any(x.startswith("ok answers beyond a tolerance: ") for x in lines)
    bad = subprocess.run([sys.executable, script, ws, str(tmp_path / "roll.json")], capture_output=True, text=True)
    assert bad.returncode == 2 and "a wheelset table" in bad.stderr
