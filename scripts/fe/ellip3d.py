#!/usr/bin/env python3
"""3-D CalculiX model of an elliptic contact: one body with the summed curvatures, surface
z = -(A x^2 + B y^2), pressed by a rigid frictionless flat; a quarter model by symmetry (x >= 0,
y >= 0), 20-node bricks C3D20 (fully integrated), structured graded mesh written here.
Units mm, N, MPa.

  ellip3d.py --sy 350 --ratios 1 2 3 4 [--n 8] [--out CSV]

Wheel-rail-like crossed cylinders R 460 x 300 mm: A = 1/(2*460), B = 1/(2*300) per mm (the
equivalent ellipsoid on a flat). Each load is a step of prescribed flat displacement chosen so
that the elastic Hertz peak is p0_el = ratio * sigma_y; the rows report what the FE gives at the
FE load. An elastic run on the same mesh gives the finite-block correction of the approach.
"""
import argparse, datetime, math, os, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from axisym import E, NU, ESTAR, K_PEN, graded, run, step_of, parse_dat  # noqa: E402


def agm_KE(m):
    """Complete elliptic integrals K(m), E(m), parameter m = e^2 (AGM)."""
    a, b, s, p = 1.0, math.sqrt(1 - m), m / 2, 0.5
    c2 = m
    while abs(a - b) > 1e-15:
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        p *= 2
        s += p * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - s)


def hertz_ellipse(A, B):
    """k = b/a for curvature sums A < B (a along x)."""
    lo, hi = 1e-3, 1 - 1e-12
    for _ in range(200):
        k = 0.5 * (lo + hi)
        e2 = 1 - k * k
        K, Ee = agm_KE(e2)
        r = (Ee / (k * k) - K) / (K - Ee)
        if r > B / A:
            lo = k
        else:
            hi = k
    return k


def hertz_at_p0(A, B, p0):
    k = hertz_ellipse(A, B)
    e2 = 1 - k * k
    K, Ee = agm_KE(e2)
    a = p0 * k * (K - Ee) / (ESTAR * e2 * A)
    b = k * a
    return dict(a=a, b=b, p0=p0, delta=p0 * b * K / ESTAR, N=2 / 3 * math.pi * a * b * p0)


def hertz_at_N(A, B, N):
    h1 = hertz_at_p0(A, B, 1000.0)
    p0 = 1000.0 * (N / h1["N"]) ** (1 / 3)
    return hertz_at_p0(A, B, p0)


def build(A, B, a, b, n, steps, sy, name):
    hx, hy = a / n, b / n
    h = min(hx, hy)
    L = 8 * a
    xs = graded(0.0, L, hx, 1.2 * a, 1.6)
    ys = graded(0.0, L, hy, 1.2 * b, 1.6)
    ds = graded(0.0, L, h, 0.8 * b, 1.5)
    def refine(v):
        r = []
        for i in range(len(v) - 1):
            r += [v[i], 0.5 * (v[i] + v[i + 1])]
        return r + [v[-1]]
    X, Y, D = refine(xs), refine(ys), refine(ds)
    NI, NJ, NK = len(X), len(Y), len(D)
    nid = lambda i, j, k: 1 + i + NI * (j + NJ * k)
    coord = {}
    for k in range(NK):
        for j in range(NJ):
            for i in range(NI):
                if (i % 2) + (j % 2) + (k % 2) > 1:
                    continue
                x, y, d = X[i], Y[j], D[k]
                top = -(A * x * x + B * y * y)
                coord[nid(i, j, k)] = (x, y, top - d * (L + top) / L)
    elems = []
    for k in range(0, NK - 1, 2):
        for j in range(0, NJ - 1, 2):
            for i in range(0, NI - 1, 2):
                lo, hi = k + 2, k  # z low = deeper
                c = lambda ii, jj, kk: nid(ii, jj, kk)
                e = [c(i, j, lo), c(i + 2, j, lo), c(i + 2, j + 2, lo), c(i, j + 2, lo),
                     c(i, j, hi), c(i + 2, j, hi), c(i + 2, j + 2, hi), c(i, j + 2, hi),
                     c(i + 1, j, lo), c(i + 2, j + 1, lo), c(i + 1, j + 2, lo), c(i, j + 1, lo),
                     c(i + 1, j, hi), c(i + 2, j + 1, hi), c(i + 1, j + 2, hi), c(i, j + 1, hi),
                     c(i, j, k + 1), c(i + 2, j, k + 1), c(i + 2, j + 2, k + 1), c(i, j + 2, k + 1)]
                elems.append(e)
    body_max = NI * NJ * NK
    top = [nid(i, j, 0) for j in range(NJ) for i in range(NI)
           if nid(i, j, 0) in coord and X[i] <= 1.3 * a and Y[j] <= 1.3 * b]
    # rigid flat: one layer over [0, 1.4 a] x [0, 1.4 b], every node prescribed
    fx = refine(graded(0.0, 1.4 * a, 2 * hx, 1.4 * a))
    fy = refine(graded(0.0, 1.4 * b, 2 * hy, 1.4 * b))
    t = 2 * h
    fz = [0.0, t / 2, t]
    FI, FJ = len(fx), len(fy)
    base = body_max + 1000
    fid = lambda i, j, k: base + i + FI * (j + FJ * k)
    for k in range(3):
        for j in range(FJ):
            for i in range(FI):
                if (i % 2) + (j % 2) + (k % 2) > 1:
                    continue
                coord[fid(i, j, k)] = (fx[i], fy[j], fz[k])
    felems = []
    for j in range(0, FJ - 1, 2):
        for i in range(0, FI - 1, 2):
            lo, hi = 0, 2
            c = fid
            felems.append([c(i, j, lo), c(i + 2, j, lo), c(i + 2, j + 2, lo), c(i, j + 2, lo),
                           c(i, j, hi), c(i + 2, j, hi), c(i + 2, j + 2, hi), c(i, j + 2, hi),
                           c(i + 1, j, lo), c(i + 2, j + 1, lo), c(i + 1, j + 2, lo), c(i, j + 1, lo),
                           c(i + 1, j, hi), c(i + 2, j + 1, hi), c(i + 1, j + 2, hi), c(i, j + 1, hi),
                           c(i, j, 1), c(i + 2, j, 1), c(i + 2, j + 2, 1), c(i, j + 2, 1)])
    flat_nodes = [n for n in coord if n > base - 1]
    xsym = [n for n in coord if n <= body_max and coord[n][0] == 0.0]
    ysym = [n for n in coord if n <= body_max and coord[n][1] == 0.0]
    bottom = [nid(i, j, NK - 1) for j in range(NJ) for i in range(NI) if nid(i, j, NK - 1) in coord]
    ne = len(elems)
    with open(name + ".inp", "w") as f:
        w = f.write
        w("*HEADING\nmhcontact scripts/fe/ellip3d.py\n*NODE, NSET=NALL\n")
        for nn, (x, y, z) in coord.items():
            w(f"{nn}, {x:.10g}, {y:.10g}, {z:.10g}\n")
        def elset(typ, es, first, nm):
            w(f"*ELEMENT, TYPE={typ}, ELSET={nm}\n")
            for kk, e in enumerate(es, first):
                w(f"{kk}, " + ", ".join(map(str, e[:15])) + ",\n" + ", ".join(map(str, e[15:])) + "\n")
        elset("C3D20", elems, 1, "BODY")
        elset("C3D20", felems, ne + 1, "FLAT")
        def nset(nm, ns):
            w(f"*NSET, NSET={nm}\n")
            for kk in range(0, len(ns), 12):
                w(", ".join(map(str, ns[kk:kk + 12])) + ",\n")
        nset("TOP", top); nset("XSYM", xsym); nset("YSYM", ysym); nset("BOTTOM", bottom)
        nset("FLATN", flat_nodes); nset("CENTER", [nid(0, 0, 0)])
        w("*SURFACE, NAME=SLAVE, TYPE=NODE\nTOP\n*SURFACE, NAME=MASTER\nFLAT, S1\n")
        w("*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n")
        w(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{K_PEN:g}, 0.1\n")
        w(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E:g}, {NU:g}\n")
        if sy is not None:
            w(f"*PLASTIC\n{sy:g}, 0.0\n")
        w("*MATERIAL, NAME=RIG\n*ELASTIC\n{0:g}, {1:g}\n".format(E, NU))
        w("*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n*SOLID SECTION, ELSET=FLAT, MATERIAL=RIG\n")
        w("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\nBOTTOM, 3, 3\nFLATN, 1, 2\n")
        for dz in steps:
            w("*STEP, INC=1000\n*STATIC\n0.25, 1.0, 1e-6, 0.5\n")
            w(f"*BOUNDARY\nFLATN, 3, 3, {-dz:.10g}\n")
            w("*NODE PRINT, NSET=CENTER\nU\n*NODE PRINT, NSET=FLATN, TOTALS=ONLY\nRF\n")
            w("*EL FILE\nS" + (", PEEQ" if sy is not None else "") + "\n*END STEP\n")
    return dict(coord=coord, top=top, body_max=body_max, nodes=len(coord), elements=ne, h=(hx, hy), L=L)


def parse_dat3(name):
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
            out[step]["uz"] = float(v[3])
        else:
            out[step]["N"] = -4 * float(v[2])   # quarter model
        mode = None
    return [out[k] for k in sorted(out)]


def parse_frd3(name, info, A, B):
    res, blk, step, top = {}, None, 0, set(info["top"])
    coord = info["coord"]
    for line in open(name + ".frd"):
        if line.startswith("  100C"):
            step = step_of(float(line[12:24]))
            res.setdefault(step, {"p": {}, "pe": (0.0, 0.0, 0.0, 0.0)})
            continue
        if line.startswith(" -4"):
            blk = line.split()[1]
            if blk == "STRESS":
                res[step]["p"] = {}
            elif blk == "PE":
                res[step]["pe"] = (0.0, 0.0, 0.0, 0.0)
            continue
        if line.startswith(" -3"):
            blk = None
            continue
        if line.startswith(" -1") and blk in ("STRESS", "PE"):
            nn = int(line[3:13])
            if nn > info["body_max"]:
                continue
            if blk == "STRESS" and nn in top:
                res[step]["p"][nn] = -float(line[37:49])
            elif blk == "PE":
                val = float(line[13:25])
                if val > res[step]["pe"][0]:
                    x, y, z = coord[nn]
                    res[step]["pe"] = (val, -(A * x * x + B * y * y) - z, x, y)
    return [res[k] for k in sorted(res)]


def edge(pts):
    pts.sort()
    pmax = max(p for _, p in pts)
    last = max(i for i, (_, p) in enumerate(pts) if p > 1e-3 * pmax)
    (r1, p1), (r2, p2) = pts[last - 1], pts[last]
    if p1 * p1 - p2 * p2 <= 0:
        return r2
    e = r2 + p2 * p2 * (r2 - r1) / (p1 * p1 - p2 * p2)
    return min(e, pts[last + 1][0]) if last + 1 < len(pts) else e


def solve(A, B, sy, ratios, n, tag, sy_ref):
    ref = hertz_at_p0(A, B, max(ratios) * sy_ref)
    a, b = 1.15 * ref["a"], 1.15 * ref["b"]   # the plastic patch is larger
    steps = [hertz_at_p0(A, B, r * sy_ref)["delta"] for r in ratios]
    info = build(A, B, a, b, n, steps, sy, tag)
    run(tag)
    rows = parse_dat3(tag)
    fr = parse_frd3(tag, info, A, B)
    out = []
    for k, r in enumerate(rows):
        ps = fr[k]["p"]
        c = info["coord"]
        ax = edge([(c[nn][0], p) for nn, p in ps.items() if c[nn][1] == 0.0])
        by = edge([(c[nn][1], p) for nn, p in ps.items() if c[nn][0] == 0.0])
        out.append(dict(u=-r["uz"], N=r["N"], a=ax, b=by, pmax=max(ps.values()), pc=ps[1], pe=fr[k]["pe"]))
    return out, info


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sy", type=float, default=350.0)
    ap.add_argument("--ratios", type=float, nargs="+", default=[2, 3, 4])
    ap.add_argument("--n", type=int, default=8, help="elements across the largest semi-axis a")
    ap.add_argument("--Rw", type=float, default=460.0)
    ap.add_argument("--Rr", type=float, default=300.0)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    # two identical half-space-like bodies = one body of the same material with HALF the pair's
    # curvature sums on a rigid flat: same pressure, same stresses in each body, half the approach
    A, B = 1 / (4 * args.Rw), 1 / (4 * args.Rr)
    if A > B:
        sys.exit("give Rw >= Rr (a along x)")
    tag = f"/tmp/fe_runs/e3_{int(args.sy)}_{args.n}"
    # the elastic run gives the finite-block correction and the mesh check: the largest load only
    el, info = solve(A, B, None, args.ratios[-1:], args.n, tag + "_el", args.sy)
    cs = [(hertz_at_N(A, B, o["N"])["delta"] - o["u"], o["N"]) for o in el]
    cN = sum(d * N for d, N in cs) / sum(N * N for _, N in cs)
    pl, _ = solve(A, B, args.sy, args.ratios, args.n, tag + "_pl", args.sy)
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "fe",
                                   f"crossed_cylinders_{int(args.Rw)}x{int(args.Rr)}_sy{int(args.sy)}.csv")
    ver = [l for l in subprocess.run(["ccx", "-v"], capture_output=True, text=True).stdout.splitlines() if "Version" in l]
    hdr = [f"# generated by scripts/fe/ellip3d.py --sy {args.sy:g} --ratios {' '.join(f'{r:g}' for r in args.ratios)} --n {args.n}"
           f" --Rw {args.Rw:g} --Rr {args.Rr:g} on {datetime.date.today().isoformat()}",
           f"# solver: CalculiX ccx {ver[0].strip() if ver else '?'} (nice -n 10, OMP_NUM_THREADS=1)",
           f"# model: wheel and rail of one steel, R {args.Rw:g} x {args.Rr:g} mm (pair curvature sums {2*A:.6g}, {2*B:.6g} 1/mm), modelled as a quarter of ONE body with half those curvature sums"
           f" (A = {A:.6g}, B = {B:.6g} 1/mm) on a rigid frictionless flat (exact for half-space-like bodies: same pressure and stresses in each body; pair approach = 2 x body approach), C3D20,"
           f" node-to-surface penalty {K_PEN:g} MPa/mm, E = {E:g} MPa, nu = {NU:g}, elastic-perfectly plastic (von Mises), small strain",
           f"# mesh: {info['nodes']} nodes, {info['elements']} C3D20, fine zone h = {info['h'][0]:.4g} x {info['h'][1]:.4g} mm"
           f" (a/{args.n}), block {info['L']:.1f} mm",
           f"# approach corrected for the finite block from the elastic run on the same mesh: delta = u_center + c N,"
           f" c = {cN:.4g} mm/N",
           "# columns: p0el_over_sy = elastic Hertz peak at the FE load / sigma_y; N [N]; a, b [mm] FE semi-axes (p^2 extrapolated"
           " to 0 along the axes); area [mm^2] = pi a b; pmean, pmax [MPa] (pmax: largest nodal -S_zz on the surface); pmax_el_over_hertz uses the centre node; delta [mm] corrected approach of the PAIR (2 x the body); *_el: the elastic FE run"
           " on the same mesh at the largest prescribed displacement (mesh check against Hertz, the same for every row); peeq max [-] and its depth [mm]"]
    with open(out, "w") as f:
        f.write("\n".join(hdr) + "\n")
        f.write("sigma_y_MPa,p0el_over_sy,N_N,a_mm,b_mm,area_mm2,pmean_MPa,pmax_MPa,delta_mm,"
                "a_el_over_hertz,b_el_over_hertz,pmax_el_over_hertz,delta_el_over_hertz,peeq_max,peeq_depth_mm,peeq_x_mm,peeq_y_mm\n")
        e = el[0]
        for o in pl:
            H = hertz_at_N(A, B, o["N"])
            He = hertz_at_N(A, B, e["N"])
            area = math.pi * o["a"] * o["b"]
            row = [args.sy, H["p0"] / args.sy, o["N"], o["a"], o["b"], area, o["N"] / area, o["pmax"], 2 * (o["u"] + cN * o["N"]),
                   e["a"] / He["a"], e["b"] / He["b"], e["pc"] / He["p0"], (e["u"] + cN * e["N"]) / He["delta"],
                   o["pe"][0], o["pe"][1], o["pe"][2], o["pe"][3]]
            f.write(",".join(f"{v:.6g}" for v in row) + "\n")
            print(row, flush=True)


if __name__ == "__main__":
    main()
