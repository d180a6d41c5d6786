#!/usr/bin/env python3
"""Axisymmetric CalculiX model: one body with the summed curvature 1/R (surface z = -r^2/(2R))
pressed by a rigid frictionless flat. CAX8 (fully integrated), structured graded mesh written
here (no gmsh needed). Units mm, N, MPa.

  axisym.py hertz  [--out CSV]   elastic sphere vs Hertz, mesh refinement h = a/10, a/20, a/40
  axisym.py jg     [--out CSV]   elastic-perfectly-plastic sphere vs Jackson & Green (2005)

Needs ccx (Debian calculix-ccx) on PATH; runs it as `nice -n 10 ccx` with OMP_NUM_THREADS=1.
"""
import argparse, datetime, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_common import E, NU, ESTAR, K_PEN, graded, run, step_of, smooth, edge_p2, ccx_version  # noqa: E402

R_GLOBAL = 100.0
LEVELS = [int(x) for x in os.environ.get("FE_LEVELS", "10 20 40").split()]  # h = a/level (hertz)


def build(R, L, h, r_fine, z_fine, steps, sy=None, tag="m"):
    """Writes the .inp; returns (name, info). steps: list of flat displacements [mm]."""
    rs = graded(0.0, L, h, r_fine)
    ds = graded(0.0, L, h, z_fine)          # depth below the surface
    nr, nz = len(rs), len(ds)
    # corner-node grid (2*nr-1) x (2*nz-1) including mid-side nodes
    rr = []
    for i in range(nr - 1):
        rr += [rs[i], 0.5 * (rs[i] + rs[i + 1])]
    rr.append(rs[-1])
    dd = []
    for j in range(nz - 1):
        dd += [ds[j], 0.5 * (ds[j] + ds[j + 1])]
    dd.append(ds[-1])
    NI, NJ = len(rr), len(dd)
    nid = lambda i, j: 1 + i + NI * j
    coord = {}
    for j, d in enumerate(dd):
        for i, r in enumerate(rr):
            top = -r * r / (2 * R)
            # depth measured from the curved top, squeezed to a flat bottom at z = -L
            z = top - d * (L + top) / L
            coord[nid(i, j)] = (r, z)
    elems = []
    for j in range(0, NJ - 1, 2):
        for i in range(0, NI - 1, 2):
            # counter-clockwise in (r, z): z decreases with j
            n1, n2, n3, n4 = nid(i, j + 2), nid(i + 2, j + 2), nid(i + 2, j), nid(i, j)
            n5, n6, n7, n8 = nid(i + 1, j + 2), nid(i + 2, j + 1), nid(i + 1, j), nid(i, j + 1)
            elems.append((n1, n2, n3, n4, n5, n6, n7, n8))
    top_nodes = [nid(i, 0) for i in range(NI) if rr[i] <= 1.05 * r_fine + 1e-12]
    axis = [nid(0, j) for j in range(NJ)]
    bottom = [nid(i, NJ - 1) for i in range(NI)]
    # rigid flat: a block r in [0, 1.2 r_fine], z in [0, t], all its nodes prescribed
    base = NI * NJ + 1000
    fr = graded(0.0, 1.2 * r_fine, 4 * h, 1.2 * r_fine)
    fr2 = []
    for i in range(len(fr) - 1):
        fr2 += [fr[i], 0.5 * (fr[i] + fr[i + 1])]
    fr2.append(fr[-1])
    t = 4 * h
    fz = [0.0, 0.5 * t, t]
    fid = lambda i, j: base + i + len(fr2) * j
    for j, z in enumerate(fz):
        for i, r in enumerate(fr2):
            coord[fid(i, j)] = (r, z)
    felems = []
    for i in range(0, len(fr2) - 1, 2):
        felems.append((fid(i, 0), fid(i + 2, 0), fid(i + 2, 2), fid(i, 2),
                       fid(i + 1, 0), fid(i + 2, 1), fid(i + 1, 2), fid(i, 1)))
    flat_nodes = [fid(i, j) for j in range(3) for i in range(len(fr2))]
    ne = len(elems)
    name = f"{tag}"
    with open(name + ".inp", "w") as f:
        w = f.write
        w("*HEADING\nmhcontact scripts/fe/axisym.py\n*NODE, NSET=NALL\n")
        for n, (r, z) in coord.items():
            w(f"{n}, {r:.10g}, {z:.10g}\n")
        w("*ELEMENT, TYPE=CAX8, ELSET=BODY\n")
        for k, e in enumerate(elems, 1):
            w(f"{k}, " + ", ".join(map(str, e)) + "\n")
        w("*ELEMENT, TYPE=CAX8, ELSET=FLAT\n")
        for k, e in enumerate(felems, ne + 1):
            w(f"{k}, " + ", ".join(map(str, e)) + "\n")
        def nset(nm, ns):
            w(f"*NSET, NSET={nm}\n")
            for k in range(0, len(ns), 12):
                w(", ".join(map(str, ns[k:k + 12])) + ",\n")
        nset("TOP", top_nodes); nset("AXIS", axis); nset("BOTTOM", bottom)
        nset("FLATN", flat_nodes); nset("CENTER", [nid(0, 0)])
        w("*SURFACE, NAME=SLAVE, TYPE=NODE\nTOP\n")
        w("*ELSET, ELSET=FLATE\n")
        for k in range(ne + 1, ne + 1 + len(felems)):
            w(f"{k},\n")
        w("*SURFACE, NAME=MASTER\nFLATE, S1\n")
        w("*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n")
        w(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{K_PEN:g}, 0.1\n")
        w(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E:g}, {NU:g}\n")
        if sy is not None:
            w(f"*PLASTIC\n{sy:g}, 0.0\n")
        w("*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n*SOLID SECTION, ELSET=FLAT, MATERIAL=STEEL\n")
        w("*BOUNDARY\nAXIS, 1, 1\nBOTTOM, 2, 2\nFLATN, 1, 1\n")
        for s, dz in enumerate(steps):
            w("*STEP, INC=1000\n*STATIC\n0.25, 1.0, 1e-6, 0.5\n")
            w(f"*BOUNDARY\nFLATN, 2, 2, {-dz:.10g}\n")
            w("*NODE PRINT, NSET=CENTER\nU\n*NODE PRINT, NSET=FLATN, TOTALS=ONLY\nRF\n")
            w("*EL FILE\nS" + (", PEEQ" if sy is not None else "") + "\n*END STEP\n")
    info = dict(body_max=NI * NJ, nodes=len(coord), elements=ne, h=h, rs=rr, top=top_nodes, coord=coord)
    return name, info


def parse_dat(name):
    """Per step (last increment): center u_z and the total flat reaction."""
    out, mode, step = {}, None, 0
    for line in open(name + ".dat"):
        s = line.strip()
        if " and time" in s:
            step = step_of(float(s.split()[-1]))
            out.setdefault(step, {})
            mode = "u" if "set CENTER" in s else "rf" if "set FLATN" in s else None
            continue
        if not s or mode is None:
            continue
        v = s.split()
        if mode == "u":
            out[step]["uz"] = float(v[2])
        else:
            # CalculiX expands CAX elements to a 2-degree wedge: forces are for 2 degrees
            out[step]["P"] = -float(v[1]) * 180.0
        mode = None
    return [out[k] for k in sorted(out)]


def parse_frd(name, top, coord, R):
    """Per step (last increment): contact pressure -S_yy at the top nodes, and the maximum nodal
    equivalent plastic strain PE with its depth below the deformed-free surface and its radius."""
    res, blk, step, top_set = {}, None, 0, set(top)
    for line in open(name + ".frd"):
        if line.startswith("  100C"):
            step = step_of(float(line[12:24]))
            res.setdefault(step, {"p": {}, "pe": (0.0, 0.0, 0.0)})
            continue
        if line.startswith(" -4"):
            blk = line.split()[1]
            if blk == "STRESS":
                res[step]["p"] = {}
            elif blk == "PE":
                res[step]["pe"] = (0.0, 0.0, 0.0)
            continue
        if line.startswith(" -3"):
            blk = None
            continue
        if line.startswith(" -1") and blk in ("STRESS", "PE"):
            n = int(line[3:13])
            if n not in coord or n > BODY_MAX[0]:
                continue
            if blk == "STRESS" and n in top_set:
                res[step]["p"][n] = -float(line[25:37])
            elif blk == "PE":
                val = float(line[13:25])
                if val > res[step]["pe"][0]:
                    r, z = coord[n]
                    res[step]["pe"] = (val, -r * r / (2 * R) - z, r)
    return [res[k] for k in sorted(res)]


BODY_MAX = [0]


def contact_edge(ps, top, coord):
    """Contact radius: p^2 extrapolated linearly to zero from the last two loaded nodes."""
    return edge_p2([(coord[n][0], ps.get(n, 0.0)) for n in top])


def solve_rows(R, L, h, r_fine, steps, sy, tag):
    name, info = build(R, L, h, r_fine, r_fine, steps, sy, tag)
    BODY_MAX[0] = info["body_max"]
    run(name)
    rows = parse_dat(name)
    fr = parse_frd(name, info["top"], info["coord"], R)
    # only the steps that completed (a stopped run: the last step may be part-way)
    done = sum(1 for l in open(name + ".sta") if len(l.split()) == 7 and l.split()[0].isdigit()
               and abs(float(l.split()[5]) - 1.0) < 1e-9)
    rows, fr = rows[:done], fr[:done]
    out = []
    for k, row in enumerate(rows):
        ps = fr[k]["p"]
        a = contact_edge(ps, info["top"], info["coord"])
        # smoothed profile inside the patch (window 0.15 a, at least 3 nodes each side)
        inside = [(info["coord"][n][0], p) for n, p in ps.items() if info["coord"][n][0] <= 0.9 * a]
        sm = smooth(inside + [(-r, p) for r, p in inside if r > 0], max(0.15 * a, 1.6 * h))
        sm = [(r, p) for r, p in sm if r >= 0]
        pe = fr[k]["pe"]
        # bracket of the edge: midway between the last node carrying > 2 % of the peak and the next
        pts = sorted((info["coord"][n][0], p) for n, p in ps.items())
        pk = max(p for _, p in pts)
        i0 = next(i for i, (x, p) in enumerate(pts) if p <= 0.02 * pk and x > 0)
        a_mid, a_half = 0.5 * (pts[i0][0] + pts[i0 - 1][0]), 0.5 * (pts[i0][0] - pts[i0 - 1][0])
        out.append(dict(step=k, omega_fe=-row["uz"], P=row["P"], a=a, a_mid=a_mid, a_half=a_half,
                        pmax=max(p for _, p in sm), pc=sm[0][1],
                        pmax_nodes=max(ps.values()),
                        peeq=pe[0], peeq_depth=pe[1], peeq_r=pe[2]))
    return out, info


def hertz(R, P):
    a = (3 * P * R / (4 * ESTAR)) ** (1 / 3)
    return a, a * a / R, 3 * P / (2 * math.pi * a * a)


def provenance(cmd, extra):
    return [f"# generated by scripts/fe/axisym.py ({cmd}) on {datetime.date.today().isoformat()}",
            f"# solver: CalculiX ccx {ccx_version()} (nice -n 10, OMP_NUM_THREADS=1)",
            f"# model: axisymmetric CAX8 (fully integrated), one body of curvature 1/R on a rigid frictionless flat,"
            f" node-to-surface penalty {K_PEN:g} MPa/mm, E = {E:g} MPa, nu = {NU:g}, small strain",
            ] + ["# " + x for x in extra]


def cmd_hertz(args):
    R = R_GLOBAL
    d = 0.04                 # mm flat displacement -> a ~ 2 mm
    a_ref = math.sqrt(R * d)
    L = 30 * a_ref
    lines = provenance("hertz", [f"R = {R} mm, block r,z in [0, {L:.1f}] mm fixed at z = -L, flat displacement {d} mm",
                                 "approach corrected for the finite block: delta = u_center + c P with c from the finest mesh at the same block",
                                 "columns: h_over_a [-], nodes, P [N], a_fe [mm] (p^2 extrapolated to 0), a_hertz [mm], p_centre_fe [MPa] (-S_zz smoothed by a moving quadratic fit over +-0.15 a, at r = 0),"
                                 " pmax_nodes_fe [MPa] (largest nodal -S_zz: shows the corner/mid-node oscillation of extrapolated stresses), p0_hertz [MPa], "
                                 "u_center [mm] (uncorrected approach: finite block, not compared), delta_hertz [mm], err_a, err_p0 (centre), err_pmax_nodes (relative, Hertz at the FE load)"])
    rows = []
    for nh in LEVELS:
        h = a_ref / nh
        out, info = solve_rows(R, L, h, 1.25 * a_ref, [d], None, f"/tmp/fe_runs/hertz_{nh}")
        o = out[0]
        aH, dH, p0H = hertz(R, o["P"])
        rows.append((1.0 / nh, info["nodes"], o["P"], o["a"], aH, o["pc"], o["pmax_nodes"], p0H, o["omega_fe"], dH,
                     o["a"] / aH - 1, o["pc"] / p0H - 1, o["pmax_nodes"] / p0H - 1))
        print(rows[-1], flush=True)
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
        f.write("h_over_a,nodes,P_N,a_fe_mm,a_hertz_mm,p_centre_fe_MPa,pmax_nodes_fe_MPa,p0_hertz_MPa,u_center_mm,delta_hertz_mm,err_a,err_p0,err_pmax_nodes\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")


def jg(w_over_wc, sy, R):
    """Jackson & Green (2005) fits, J. Tribol. 127(2):343-354, doi:10.1115/1.1866166."""
    C = 1.295 * math.exp(0.736 * NU)
    wc = (math.pi * C * sy / (2 * ESTAR)) ** 2 * R
    Pc = 4.0 / 3.0 * (R / ESTAR) ** 2 * (C * math.pi * sy / 2) ** 3
    Ac = math.pi ** 3 * (C * sy * R / (2 * ESTAR)) ** 2
    x = w_over_wc
    B = 0.14 * math.exp(23 * sy / ESTAR)
    if x <= 1.9:
        return x ** 1.5, x, wc, Pc, Ac
    A = x * (x / 1.9) ** B
    a_over_R = math.sqrt(A * Ac / math.pi) / R
    HG = 2.84 * (1 - math.exp(-0.82 * a_over_R ** -0.7))
    P = math.exp(-0.25 * x ** (5 / 12)) * x ** 1.5 + 4 * HG / C * (1 - math.exp(-x ** (5 / 9) / 25)) * x
    return P, A, wc, Pc, Ac


def cmd_jg(args):
    R, sy = R_GLOBAL, args.sy
    _, _, wc, Pc, Ac = jg(1, sy, R)
    xs = [1, 2, 4, 8, 15, 30, 60, 100]
    w_max = 100 * wc
    a_max = math.sqrt(R * w_max) * 1.4
    L = 25 * a_max
    h = a_max / args.n
    steps = [x * wc for x in xs]
    # the elastic run only gives the finite-block correction: two loads suffice
    el, _ = solve_rows(R, L, h, 1.15 * a_max, steps[-3::2], None, "/tmp/fe_runs/jg_el")
    # finite-block correction: delta_halfspace - u_center = c P, c from the elastic rows (least squares)
    cs = [(hertz(R, o["P"])[1] - o["omega_fe"], o["P"]) for o in el]
    c = sum(d * P for d, P in cs) / sum(P * P for _, P in cs)
    resid = max(abs(hertz(R, o["P"])[1] - o["omega_fe"] - c * o["P"]) / hertz(R, o["P"])[1] for o in el)
    pl, info = solve_rows(R, L, h, 1.15 * a_max, steps, sy, "/tmp/fe_runs/jg_pl")
    lines = provenance("jg", [f"R = {R} mm, sigma_y = {sy} MPa (elastic-perfectly plastic, von Mises), E' = {ESTAR:.0f} MPa,"
                              f" omega_c = {wc:.5g} mm, P_c = {Pc:.5g} N, A_c = {Ac:.5g} mm^2",
                              f"mesh: h = {h:.4g} mm (a_max/{args.n}), {info['nodes']} nodes, {info['elements']} CAX8, block {L:.1f} mm",
                              f"finite-block correction from the elastic run on the same mesh: omega = u_center + c P, c = {c:.4g} mm/N"
                              f" (elastic rows after correction within {100*resid:.2f} % of Hertz)",
                              "columns: omega_over_wc prescribed (flat displacement), omega_over_wc_corr, P/Pc FE and JG(omega_corr), A/Ac FE (edge by p^2 extrapolation;"
                              " and by the midpoint of the last loaded and first unloaded surface node, with its relative uncertainty +-) and JG,"
                              " pmean/sy (on the midpoint area), pmax/sy (smoothed profile), peeq max (nodal), its depth/a, r/a"] +
                             [f"elastic check on the same mesh: omega/omega_c = {e['omega_fe'] / wc:.4g}: a/a_hertz = "
                              f"{e['a'] / hertz(R, e['P'])[0]:.4f}, p_centre/p0_hertz = {e['pc'] / hertz(R, e['P'])[2]:.4f},"
                              f" corrected approach/Hertz = {(e['omega_fe'] + c * e['P']) / hertz(R, e['P'])[1]:.4f}" for e in el])
    rows = []
    for x, o in zip(xs, pl):
        w = o["omega_fe"] + c * o["P"]
        Pj, Aj, *_ = jg(w / wc, sy, R)
        A = math.pi * o["a"] ** 2
        Am = math.pi * o["a_mid"] ** 2
        rows.append((x, w / wc, o["P"] / Pc, Pj, A / Ac, Am / Ac, 2 * o["a_half"] / o["a_mid"], Aj, o["P"] / Am / sy, o["pmax"] / sy, o["peeq"],
                     o["peeq_depth"] / o["a"], o["peeq_r"] / o["a"]))
        print(rows[-1], flush=True)
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
        f.write("omega_over_wc,omega_corr_over_wc,P_over_Pc_fe,P_over_Pc_jg,A_over_Ac_fe_p2,A_over_Ac_fe_mid,A_fe_mid_uncertainty,A_over_Ac_jg,pmean_over_sy,pmax_over_sy,"
                "peeq_max,peeq_depth_over_a,peeq_r_over_a\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("case", choices=["hertz", "jg"])
    ap.add_argument("--out", default=None)
    ap.add_argument("--sy", type=float, default=350.0)
    ap.add_argument("--n", type=int, default=25, help="elements across a_max (jg)")
    a = ap.parse_args()
    a.out = a.out or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "fe", f"axisym_{a.case}.csv")
    {"hertz": cmd_hertz, "jg": cmd_jg}[a.case](a)
