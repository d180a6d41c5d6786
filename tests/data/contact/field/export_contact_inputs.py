#!/usr/bin/env python3
"""Write the profiles of one trust.json pair as CONTACT reads them, placed as mhcontact places them.

    export_contact_inputs.py TRUST.json PAIR_NAME OUTDIR [--mhcontact build/mhcontact] [--surface points|contact]

Runs `mhcontact geometry` on the pair's case and writes, from its profiles.csv (the profiles in
mhcontact's canonical frame, after the reader's clean-up, the rail canted by the case's
inclination, the wheel's y = 0 at its taping line), OUTDIR/rail.prr and OUTDIR/wheel.prw
(SIMPACK, z down, no transformations) and OUTDIR/sweep.json, a spec for run_sweep.py of the
CONTACT tools (README.md in this folder) with FBPOS = the case's flange_back_position_mm (the wheel's
flange back in this frame), CANT = 0 (the rail is canted in the file), GAUGHT and GAUGWD from the
case, no YTAPE, dx = ds = 0.2 mm, NPOT_MAX 200000. The geometry.json of the run is kept in OUTDIR.

--surface contact (the default) writes a measured profile's `z_contact_mm` column: the surface
mhcontact's grid methods solve on, i.e. the profile already smoothed for contact by mhcontact's
spline at the case's geometry.smoothing_mm (default 5 mm), at the points' y; an exact profile, which
mhcontact does not smooth, as read (z_mm). CONTACT must then read it without smoothing of its own (SMOOTH = 0, the
default of the deck): both programs solve the same surface. --surface points writes the points as
read (z_mm): the unsmoothed measured surface, which the trust table's CONTACT references use since
2026-11-28 (README.md); for a reference that smooths with CONTACT's own spline add
"rail_ismooth"/"rail_smooth" to the deck by hand. --surface contact is kept for CONTACT runs on the
surface mhcontact solves (the diagnostic `mhc_auto` runs of contact_measured_surface_variants.csv).
"""
import argparse
import csv
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "..", "scripts"))
import trust_table  # noqa: E402


def write_simpack(path, kind, pts, src, what):
    with open(path, "w") as f:
        f.write("! SIMPACK profile written by export_contact_inputs.py from mhcontact geometry of %s\n" % src)
        f.write("! z: the %s\n" % what)
        f.write("! canonical points: y towards the field side, z DOWN (SIMPACK), mm; no transformations\n")
        f.write("header.begin\n  version = 1\n  type    = %d\nheader.end\n" % (1 if kind == "wheel" else 0))
        f.write("spline.begin\n  units.len.f = 1000.\n  units.ang.f = 1.\n  point.begin\n")
        for y, z in pts:
            f.write("    %.6f %.6f\n" % (y, -z))
        f.write("  point.end\nspline.end\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("spec")
    ap.add_argument("pair")
    ap.add_argument("out")
    ap.add_argument("--mhcontact", default=os.path.join(trust_table.ROOT, "build", "mhcontact"))
    ap.add_argument("--surface", choices=["contact", "points"], default="contact")
    a = ap.parse_args()
    spec = json.load(open(a.spec))
    sdir = os.path.dirname(os.path.abspath(a.spec))
    pair = [p for p in spec["pairs"] if p["name"] == a.pair][0]
    case = trust_table.absolutise(json.loads(json.dumps(pair["case"])), sdir)
    case["sweep"] = {"tY_mm": [0], "Q_kN": [50]}
    os.makedirs(a.out, exist_ok=True)
    cpath = os.path.join(a.out, "case.json")
    json.dump(case, open(cpath, "w"), indent=1)
    gdir = os.path.join(a.out, "geometry")
    subprocess.run([a.mhcontact, "geometry", cpath, "-o", gdir], check=True)
    # A profile smoothed for contact: measured (noise class) with a smoothing length > 0.
    gj = json.load(open(os.path.join(gdir, "geometry.json")))
    # geometry.smoothing_mm: a length, 0 (off) or "auto" (the default: a length from each
    # profile's own noise, reported by `mhcontact geometry` as the profile's contact_smoothing_mm).
    L = case.get("geometry", {}).get("smoothing_mm", "auto")
    smoothed = {k: a.surface == "contact" and (L == "auto" or L > 0) and gj["profiles"][k]["noise"]["class"] == "measured"
                for k in ("wheel", "rail")}
    Ls = {k: ("%g mm" % L) if L != "auto" else "a length from the profile's noise" for k in ("wheel", "rail")}
    pts = {"wheel": [], "rail": []}
    for r in csv.DictReader(open(os.path.join(gdir, "profiles.csv"))):
        k = r["kind"]
        z = r["z_contact_mm"] if smoothed[k] else r["z_mm"]
        if z != "":  # z_contact_mm is empty where the surface is not built
            pts[k].append((float(r["y_mm"]), float(z)))
    for k in ("rail", "wheel"):
        what = ("surface of mhcontact's grid methods: the points smoothed for contact at L = %s (z_contact_mm)" % Ls[k]
                if smoothed[k] else "points as read (z_mm)")
        write_simpack(os.path.join(a.out, "rail.prr" if k == "rail" else "wheel.prw"), k, pts[k], pair["name"], what)
        print("%s: %d points, %s" % (k, len(pts[k]), what))
    tr = case.get("track", {})
    sweep = {
        "name": pair["name"], "side": "right", "prefix": "r",
        "surface": {k: ("mhcontact geometry's z_contact_mm: smoothed for contact by mhcontact "
                        "(L = %s), read by CONTACT without smoothing" % Ls[k]) if smoothed[k]
                    else "the points as read (z_mm)" for k in ("rail", "wheel")},
        "profiles": ["rail.prr", "wheel.prw"],
        "deck": {"rail": "rail.prr", "wheel": "wheel.prw",
                 "gaught": tr.get("gauge_height_mm", 14), "gaugwd": tr.get("gauge_mm", 1435),
                 "fbdist": tr.get("flange_back_distance_mm", 1360), "fbpos": tr.get("flange_back_position_mm", -70),
                 "nomrad": case["wheel"].get("nominal_radius_mm", 460), "cant": 0.0,
                 "E": 1000.0 * case.get("material", {}).get("E_GPa", 210), "nu": case.get("material", {}).get("nu", 0.28),
                 "dx": 0.2, "ds": 0.2, "npot_max": 200000},
        "y_ws_mm": pair["sweep"]["tY_mm"], "Q_kN": pair["sweep"]["Q_kN"],
    }
    json.dump(sweep, open(os.path.join(a.out, "sweep.json"), "w"), indent=1)
    print("wrote %s/rail.prr, wheel.prw, sweep.json" % a.out)


if __name__ == "__main__":
    main()
