#!/usr/bin/env python3
"""Plot the contact geometry written by `mhcontact geometry CASE -o DIR`.

    plot_geometry.py DIR [--tY MM] [--pair P] [-o PREFIX]

DIR is the output directory of `mhcontact geometry CASE`, or of `mhcontact geometry MANIFEST` or
a batch `mhcontact run MANIFEST` (both have DIR/pairs.csv): then --pair P plots the geometry of
pair P (DIR/pairs/P/).

Writes PREFIX_caf.png: the contact angle function gamma(t_Y) with the potential-ellipse
intervals shaded (as Fig. 2 of Sebes et al. 2014), and PREFIX_profiles.png: the wheel placed
on the rail at t_Y = MM (default 5) with the strip of every potential ellipse marked (as Fig. 3).
PREFIX defaults to DIR/geometry. Needs matplotlib (Debian: python3-matplotlib); runs headless.
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="output directory of `mhcontact geometry`")
    ap.add_argument("--tY", type=float, default=5.0, help="t_Y [mm] of the profile plot (default 5)")
    ap.add_argument("--pair", type=int, help="profile pair of a batch directory (column `pair` of pairs.csv)")
    ap.add_argument("-o", "--output", help="prefix of the PNG files (default DIR/geometry, or DIR/geometry_pair_P)")
    a = ap.parse_args(argv)
    batch = os.path.exists(os.path.join(a.dir, "pairs.csv"))
    if batch and a.pair is None:
        sys.exit(f"plot_geometry.py: {a.dir} is a batch over several profile pairs (pairs.csv): "
                 f"give --pair P with P from the column `pair` of {a.dir}/pairs.csv")
    if not batch and a.pair is not None:
        sys.exit(f"plot_geometry.py: --pair is for batch directories; {a.dir} holds one pair (no pairs.csv)")
    d = os.path.join(a.dir, "pairs", str(a.pair)) if batch else a.dir
    try:
        caf = read_csv(os.path.join(d, "caf.csv"))
        geo = json.load(open(os.path.join(d, "geometry.json")))
        prof = read_csv(os.path.join(d, "profiles.csv"))
    except OSError as e:
        sys.exit(f"plot_geometry.py: {e}")
    prefix = a.output or os.path.join(a.dir, "geometry" if not batch else f"geometry_pair_{a.pair}")
    inputs = geo.get("inputs") or {}

    def pname(side):
        p = side.get("profile", side) if isinstance(side, dict) else side
        if isinstance(p, dict):
            p = p.get("file") or p.get("standard") or ""
        return os.path.basename(str(p))
    pair_txt = (f"pair {a.pair}: " if batch else "") + f"{pname(inputs.get('wheel', {}))} / {pname(inputs.get('rail', {}))}"
    model = inputs.get("model", "elastic")
    plim = (inputs.get("material") or {}).get("p_lim_MPa")
    model_txt = f"{model}, p_lim = {plim:g} MPa" if isinstance(plim, (int, float)) else f"{model}, p_lim = none"
    tY = [float(r["tY_mm"]) for r in caf]
    gam = [float(r["gamma_deg"]) for r in caf]
    ells = geo["potential_ellipses"]

    fig, ax = plt.subplots(figsize=(8, 4.5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, e in enumerate(ells):
        ax.axvspan(e["tY_min_mm"], e["tY_max_mm"], color=colors[i % len(colors)], alpha=0.12)
        ax.text(0.5 * (e["tY_min_mm"] + e["tY_max_mm"]), 0.97, f"#{e['ellipse']}",
                transform=ax.get_xaxis_transform(), ha="center", va="top")
    # Draw each interval separately so the jumps show as jumps.
    for i, e in enumerate(ells):
        xs = [t for t in tY if e["tY_min_mm"] <= t <= e["tY_max_mm"]]
        ys = [g for t, g in zip(tY, gam) if e["tY_min_mm"] <= t <= e["tY_max_mm"]]
        ax.plot(xs, ys, color=colors[i % len(colors)], lw=1.5)
    ax.set_xlabel("t_Y [mm]")
    ax.set_ylabel("contact angle gamma [deg]")
    ax.set_title(f"{pair_txt} ({model_txt})\ncontact angle function: {len(ells)} potential ellipses", fontsize=10)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_caf.png", dpi=120)
    plt.close(fig)

    # Profiles at the chosen t_Y: the wheel moved by y_offset + t_Y and lifted into contact.
    k = min(range(len(tY)), key=lambda i: abs(tY[i] - a.tY))
    row = caf[k]
    y_off = geo["y_offset_mm"]
    dz = float(row["wheel_dz_mm"])
    wy = [float(r["y_mm"]) + y_off + tY[k] for r in prof if r["kind"] == "wheel"]
    wz = [float(r["z_mm"]) + dz for r in prof if r["kind"] == "wheel"]
    ry = [float(r["y_mm"]) for r in prof if r["kind"] == "rail"]
    rz = [float(r["z_mm"]) for r in prof if r["kind"] == "rail"]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(ry, rz, "k-", lw=1.2, label="rail")
    ax.plot(wy, wz, "-", color="0.45", lw=1.2, label="wheel")
    for i, e in enumerate(ells):
        # The ellipse's strip: its own main strip if t_Y is inside its interval, else the main strip
        # of its t_Y nearest to t_Y (docs/method.md §3, step 6).
        kk = min(range(len(tY)), key=lambda j: abs(tY[j] - min(max(tY[k], e["tY_min_mm"]), e["tY_max_mm"])))
        yr = float(caf[kk]["y_rail_mm"])
        # rail height at yr by linear interpolation
        j = max(1, min(len(ry) - 1, next((m for m in range(len(ry)) if ry[m] >= yr), len(ry) - 1)))
        t = (yr - ry[j - 1]) / (ry[j] - ry[j - 1])
        zr = rz[j - 1] + t * (rz[j] - rz[j - 1])
        main = int(row["ellipse"]) == e["ellipse"]
        ax.plot([yr], [zr], "o" if main else "s", color=colors[i % len(colors)], ms=8 if main else 6,
                label=f"ellipse #{e['ellipse']}" + (" (main strip)" if main else ""))
    ax.set_aspect("equal")
    ax.set_xlabel("y [mm] (towards the field side)")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"{pair_txt} ({model_txt})\nstrips of the potential ellipses at t_Y = {tY[k]:g} mm", fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, fontsize=8)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_profiles.png", dpi=120, bbox_inches="tight")  # legend outside, right
    plt.close(fig)
    print(f"wrote {prefix}_caf.png, {prefix}_profiles.png")


if __name__ == "__main__":
    main()
