#!/usr/bin/env python3
"""3-D CalculiX model of an elliptic contact on the half-space idealisation: a quarter block
(x, y >= 0 by symmetry) with a FLAT top, pressed by a rigid frictionless indenter whose surface is
the gap of the two bodies, z = A x^2 + B y^2, its facet corners on the block's own (x, y) grid.
Node-to-surface contact (slave: the block's top faces, so that CPRESS is a pressure), linear
bricks with incompatible modes (C3D8I). Structured mesh, uniform over the contact, growing
geometrically to the block's faces. Units mm, N, MPa.

  ellip3d.py elastic --n 8 12 16            mesh convergence of the elastic model against Hertz
  ellip3d.py plastic --sy 350 --ratios 1 1.5 2 2.5 3 3.5 4 [--n 12]
                                            elastic-perfectly-plastic rows, p0_el/sigma_y = ratios

Wheel and rail of one steel, crossed cylinders R 460 x 300 mm: the pair's curvature sums are
1/(2*460), 1/(2*300) per mm. Two identical half-space bodies are one body with HALF the pair's
curvature sums on a rigid flat (same pressure, same stresses in each body, the pair's approach
twice the body's); the model is that one body, the tables report the pair.

Each load level is its own run on its own mesh, scaled to the elastic Hertz patch of that load
(n elements per semi-axis): under small strain and the half-space idealisation the problem is
self-similar (lengths scale with sigma_y R/E), so every row is solved at the same resolution.
The finite block is stiffer than a half-space; the approach is corrected by delta = u_centre + c N
with c fitted on the elastic runs of the same (scaled) mesh, c = c_hat / (E' L) (block size L).
"""
import argparse, concurrent.futures, datetime, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_common import E, NU, ESTAR, K_PEN, graded, run, step_of, write_nset, ccx_version, hertz_at_p0, hertz_at_N  # noqa: E402

L_OVER_A = 8.0         # block size / elastic semi-axis a
GROWTH = 1.4           # element growth outside the uniform zone
FINE = 1.35            # uniform zone: [0, FINE a] x [0, FINE b], depth FINE b
CONTACT = 1.6          # gap elements on [0, CONTACT a] x [0, CONTACT b]
HERE = os.path.dirname(os.path.abspath(__file__))


def build(A, B, a, b, n, steps, sy, name, kpen=K_PEN):
    """Writes name.inp: block [0, L]^2 x [-L, 0], n elements per semi-axis a, b of the elastic
    patch, one step per flat displacement in `steps` [mm]. sy None: elastic. kpen: penalty slope
    [MPa/mm] of the contact."""
    hx, hy = a / n, b / n
    hz = min(hx, hy)
    L = L_OVER_A * a
    X = graded(0.0, L, hx, FINE * a, GROWTH)
    Y = graded(0.0, L, hy, FINE * b, GROWTH)
    D = graded(0.0, L, hz, FINE * b, GROWTH)
    NI, NJ, NK = len(X), len(Y), len(D)
    nid = lambda i, j, k: 1 + i + NI * (j + NJ * k)
    coord = {}
    for k in range(NK):
        for j in range(NJ):
            for i in range(NI):
                coord[nid(i, j, k)] = (X[i], Y[j], -D[k])
    elems = []
    for k in range(NK - 1):
        for j in range(NJ - 1):
            for i in range(NI - 1):
                lo, hi = k + 1, k        # lo: deeper face first, counter-clockwise seen from +z
                elems.append([nid(i, j, lo), nid(i + 1, j, lo), nid(i + 1, j + 1, lo), nid(i, j + 1, lo),
                              nid(i, j, hi), nid(i + 1, j, hi), nid(i + 1, j + 1, hi), nid(i, j + 1, hi)])
    body_max = NI * NJ * NK
    # rigid indenter: the surface z = A x^2 + B y^2 on the block's own (x, y) grid over the contact
    # zone, so that every slave node meets a facet corner at its own clearance; one layer of
    # bricks, every node prescribed
    IC = max(i for i in range(NI) if X[i] <= CONTACT * a) + 1
    JC = max(j for j in range(NJ) if Y[j] <= CONTACT * b) + 1
    t = 2 * hz
    rid = lambda i, j, k: body_max + 1 + i + (IC + 1) * (j + (JC + 1) * k)
    for k in range(2):
        for j in range(JC + 1):
            for i in range(IC + 1):
                coord[rid(i, j, k)] = (X[i], Y[j], A * X[i] ** 2 + B * Y[j] ** 2 + k * t)
    relems = [[rid(i, j, 0), rid(i + 1, j, 0), rid(i + 1, j + 1, 0), rid(i, j + 1, 0),
               rid(i, j, 1), rid(i + 1, j, 1), rid(i + 1, j + 1, 1), rid(i, j + 1, 1)]
              for j in range(JC) for i in range(IC)]
    top = [nid(i, j, 0) for j in range(JC + 1) for i in range(IC + 1)]
    clr = {nid(i, j, 0): A * X[i] ** 2 + B * Y[j] ** 2 for j in range(JC + 1) for i in range(IC + 1)}
    rig = [rid(i, j, k) for k in range(2) for j in range(JC + 1) for i in range(IC + 1)]
    ne = len(elems)
    with open(name + ".inp", "w") as f:
        w = f.write
        w("*HEADING\nmhcontact scripts/fe/ellip3d.py\n*NODE, NSET=NALL\n")
        for nn, (x, y, z) in coord.items():
            w(f"{nn}, {x:.10g}, {y:.10g}, {z:.10g}\n")
        w("*ELEMENT, TYPE=C3D8I, ELSET=BODY\n")
        for kk, e in enumerate(elems, 1):
            w(f"{kk}, " + ", ".join(map(str, e)) + "\n")
        w("*ELEMENT, TYPE=C3D8, ELSET=RIGID\n")
        for kk, e in enumerate(relems, ne + 1):
            w(f"{kk}, " + ", ".join(map(str, e)) + "\n")
        write_nset(w, "XSYM", [nid(0, j, k) for k in range(NK) for j in range(NJ)])
        write_nset(w, "YSYM", [nid(i, 0, k) for k in range(NK) for i in range(NI)])
        write_nset(w, "BOTTOM", [nid(i, j, NK - 1) for j in range(NJ) for i in range(NI)])
        write_nset(w, "TOP", top)
        write_nset(w, "RIGN", rig)
        write_nset(w, "CENTER", [nid(0, 0, 0)])
        write_nset(w, "AXES", [n for n in top if coord[n][0] == 0.0 or coord[n][1] == 0.0])
        # node-to-surface contact, slave: the block's top faces (their areas make CPRESS a pressure),
        # master: the indenter's lower faces
        w("*ELSET, ELSET=TOPEL\n")
        tops = [1 + i + (NI - 1) * j for j in range(JC) for i in range(IC)]    # top layer: k = 0
        for kk in range(0, len(tops), 12):
            w(", ".join(map(str, tops[kk:kk + 12])) + ",\n")
        w("*SURFACE, NAME=SLAVE\nTOPEL, S2\n*SURFACE, NAME=MASTER\nRIGID, S1\n")
        w("*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n")
        w(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{kpen:.6g}, 0.1\n")
        w(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E:g}, {NU:g}\n")
        if sy is not None:
            w(f"*PLASTIC\n{sy:g}, 0.0\n")
        w(f"*MATERIAL, NAME=RIG\n*ELASTIC\n{E:g}, {NU:g}\n")
        w("*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n*SOLID SECTION, ELSET=RIGID, MATERIAL=RIG\n")
        w("*BOUNDARY\nXSYM, 1, 1\nYSYM, 2, 2\nBOTTOM, 3, 3\nRIGN, 1, 2\n")
        for dz in steps:
            # plastic: a first increment of 1/16 (larger ones stall while the patch spreads over many nodes)
            w("*STEP, INC=1000\n*STATIC\n" + ("0.25" if sy is None else "0.0625") + ", 1.0, 1e-5, 0.25\n")
            w(f"*BOUNDARY\nRIGN, 3, 3, {-dz:.10g}\n")
            w("*NODE PRINT, NSET=CENTER\nU\n*NODE PRINT, NSET=RIGN, TOTALS=ONLY\nRF\n*NODE PRINT, NSET=AXES\nU\n")
            w("*CONTACT FILE\nCSTR\n*EL FILE\nS" + (", PEEQ" if sy is not None else "") + "\n*END STEP\n")
    return dict(kpen=kpen, steps=list(steps), AB=(A, B), coord=coord, clr=clr, body_max=body_max, nodes=body_max, elements=ne, h=(hx, hy, hz), L=L)


def parse_dat(name, info):
    """Per step (last increment): centre u_z, the indenter's total force (quarter) and u_z of the
    surface nodes on the axes."""
    out, mode, step = {}, None, 0
    for line in open(name + ".dat"):
        s = line.strip()
        if " and time" in s:
            step = step_of(float(s.split()[-1]))
            mode = "u" if "set CENTER" in s else "rf" if "set RIGN" in s else "ax" if "set AXES" in s else None
            if mode == "ax":
                out.setdefault(step, {})["ax"] = {}
            continue
        if not s or mode is None:
            continue
        v = s.split()
        if mode == "u":
            out.setdefault(step, {})["uz"] = float(v[3])
            mode = None
        elif mode == "rf":
            out.setdefault(step, {})["F"] = float(v[2])
            mode = None
        else:
            out[step]["ax"][int(v[0])] = tuple(float(x) for x in v[1:4])
    return [out[k] for k in sorted(out)]


def parse_frd(name, info):
    """Per step (last output): contact pressure CPRESS at the slave nodes, and the largest nodal
    equivalent plastic strain with its depth and x, y."""
    res, blk, step, comp = {}, None, 0, []
    coord, bm = info["coord"], info["body_max"]
    for line in open(name + ".frd"):
        if line.startswith("  100C"):
            step = step_of(float(line[12:24]))
            res.setdefault(step, {"p": {}, "pe": (0.0, 0.0, 0.0, 0.0)})
            continue
        if line.startswith(" -4"):
            blk, comp = line.split()[1], []
            if blk == "PE":
                res[step]["pe"] = (0.0, 0.0, 0.0, 0.0)
            elif blk == "CONTACT":
                res[step]["p"] = {}
            continue
        if line.startswith(" -5"):
            comp.append(line.split()[1])
            continue
        if line.startswith(" -3"):
            blk = None
            continue
        if line.startswith(" -1") and blk in ("PE", "CONTACT"):
            nn = int(line[3:13])
            if nn > bm:
                continue
            if blk == "PE":
                val = float(line[13:25])
                if val > res[step]["pe"][0]:
                    x, y, z = coord[nn]
                    res[step]["pe"] = (val, -z, x, y)
            else:
                k = comp.index("CPRESS")
                res[step]["p"][nn] = float(line[13 + 12 * k:25 + 12 * k])
    return [res[k] for k in sorted(res)]


def edge_open(pts):
    """Contact edge along a line of surface nodes [(r, separation)]: outside an elastic contact edge
    the separation grows as (r - a)^(3/2) (Johnson, Contact Mechanics §4.2), so s^(2/3) of the first
    two open nodes is extrapolated linearly to zero, kept between the last closed and the first
    open node. (Node forces over tributary areas smear the pressure across the edge; the
    separations do not.)"""
    pts = sorted(pts)
    io = next(i for i, (_, s) in enumerate(pts) if s > 0 and i > 0)
    (x1, s1), (x2, s2) = pts[io], pts[io + 1]
    t1, t2 = s1 ** (2 / 3), s2 ** (2 / 3)
    e = x1 - t1 * (x2 - x1) / (t2 - t1)
    return min(max(e, pts[io - 1][0]), x1)


def rows_of(name, info, sy):
    """Per step: load N (whole contact), semi-axes, centre and peak pressure, centre approach of the
    body (uncorrected) and the largest equivalent plastic strain with its place."""
    rows = parse_dat(name, info)
    fr = parse_frd(name, info)
    out = []
    coord = info["coord"]
    for k, r in enumerate(rows):
        p = fr[k]["p"]
        d = info["steps"][k]
        A, B = info["AB"]
        # separation from the indenter at the node's displaced (x, y): the lateral displacement
        # (µm) moves the clearance by 2 A x u_x, as much as the separation near the edge
        sep = {nb: A * (coord[nb][0] + ux) ** 2 + B * (coord[nb][1] + uy) ** 2 - d - uz
               for nb, (ux, uy, uz) in r["ax"].items()}
        a = edge_open([(coord[nb][0], s) for nb, s in sep.items() if coord[nb][1] == 0.0])
        b = edge_open([(coord[nb][1], s) for nb, s in sep.items() if coord[nb][0] == 0.0])
        out.append(dict(u=-r["uz"], N=-4 * r["F"], a=a, b=b, pc=p.get(1, 0.0), pmax=max(p.values()),
                        pe=fr[k]["pe"] if sy is not None else (0.0, 0.0, 0.0, 0.0)))
    return out


def pair_curvatures(Rw, Rr):
    """Body curvature sums (half the pair's) from the pair's principal relative radii: Rw along the
    rolling direction, Rr across it (crossed cylinders: the wheel's rolling radius and the rail's
    profile radius; in general 1/Rr = 1/R_rail,transverse + 1/R_wheel,transverse). The model's x
    axis carries the smaller curvature A (the larger semi-axis a), y the larger B: x is the rolling
    direction when Rw >= Rr, the transverse one otherwise (a patch wider than long)."""
    cw, cr = 1 / (4 * Rw), 1 / (4 * Rr)
    return min(cw, cr), max(cw, cr)


def n_tag(n):
    """Suffix of a table's name for its (finest) mesh: none for n = 8, the level of the reference
    tables, "_n12" for n = 12 (so that a second level never overwrites the first)."""
    return "" if n == 8 else f"_n{n}"


def hertz_table(Rw, Rr, n=8):
    """Name of the elastic validation table of a shape on the mesh of n elements per semi-axis."""
    return ("ellip3d_hertz" if (Rw, Rr) == (460, 300) else f"ellip3d_R{int(Rw)}x{int(Rr)}_hertz") + n_tag(n) + ".csv"


def plastic_table(Rw, Rr, sy, n):
    """Name of the elastic-perfectly-plastic table of a shape, yield stress and mesh."""
    return f"ellip3d_R{int(Rw)}x{int(Rr)}_sy{int(sy)}" + n_tag(n) + ".csv"


def x_axis(Rw, Rr):
    return "rolling" if Rw >= Rr else "transverse"


def penalty(b, k_hat):
    """Penalty slope [MPa/mm] of a mesh scaled to the elastic semi-axis b: K_PEN, or k_hat E'/b.
    The penalty lets the surface sink p/K into the indenter, against an approach of about
    p0 b K(e)/E' (Hertz): a fixed K is a larger error on a smaller patch (a flange's b of 0.2-0.4 mm:
    K_PEN gave the peak 2 % low and b 5-9 % wide), k_hat E'/b the same on every patch and keeps the
    model self-similar."""
    return K_PEN if k_hat is None else k_hat * ESTAR / b


def elastic_deck(A, B, p0, n, tag, k_hat=None):
    """Elastic deck on the mesh of the Hertz patch at peak p0, two loads (0.8 p0 and p0)."""
    H = hertz_at_p0(A, B, p0)
    steps = [hertz_at_p0(A, B, f * p0)["delta"] for f in (0.8, 1.0)]
    info = build(A, B, H["a"], H["b"], n, steps, None, tag, penalty(H["b"], k_hat))
    info["AB"] = (A, B)
    return info


def block_fit(el, info):
    """c_hat = c E' L from delta_hertz - u_centre = c N (least squares over the elastic rows)."""
    cs = [(hertz_at_N(*info["AB"], o["N"])["delta"] - o["u"], o["N"]) for o in el]
    c = sum(d * N for d, N in cs) / sum(N * N for _, N in cs)
    return c * ESTAR * info["L"]


def cmd_elastic(args):
    A, B = pair_curvatures(args.Rw, args.Rr)
    p0 = args.p0
    kt = "" if args.k_pen is None else f"_k{args.k_pen:g}"
    decks = [(f"/tmp/fe_runs/e3el_{n}_{p0:g}_{int(args.Rw)}x{int(args.Rr)}{kt}", n) for n in args.n]
    infos = [elastic_deck(A, B, p0, n, tag, args.k_pen) for tag, n in decks]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:   # ccx runs are separate processes
        list(pool.map(run, [t for t, _ in decks]))
    res = []
    for (tag, n), info in zip(decks, infos):
        el = rows_of(tag, info, None)
        res.append((n, el, info, block_fit(el, info)))
        print(n, info["nodes"], info["elements"], [(o["N"], o["a"], o["b"], o["pc"], o["pmax"], o["u"]) for o in el], flush=True)
    c_hat = res[-1][3]      # the finest mesh's block correction, applied to every level
    out = args.out or os.path.join(HERE, "..", "..", "tests", "data", "fe", hertz_table(args.Rw, args.Rr, args.n[-1]))
    hdr = [f"# generated by scripts/fe/ellip3d.py elastic --n {' '.join(map(str, args.n))} --p0 {p0:g}"
           f" --Rw {args.Rw:g} --Rr {args.Rr:g}" + ("" if args.k_pen is None else f" --k-pen {args.k_pen:g}")
           + f" on {datetime.date.today().isoformat()}",
           f"# solver: CalculiX ccx {ccx_version()} (one thread: OMP_NUM_THREADS=1, CCX_NPROC_EQUATION_SOLVER=1)",
           f"# case: {case_line(args.Rw, args.Rr, A, B)}",
           f"# model: {model_line(A, B, args.k_pen)}",
           f"# mesh: quarter block [0, {L_OVER_A:g} a]^2 x [-{L_OVER_A:g} a, 0] fixed in z at its bottom, uniform zone "
           f"{FINE:g} a x {FINE:g} b x {FINE:g} b with h = a/n, b/n, min of both in depth, growth {GROWTH:g} outside; a, b the Hertz"
           f" semi-axes at the prescribed peak; two loads per mesh (peak 0.8 p0 and p0)",
           f"# approach corrected for the finite block: delta = u_centre + c N, c = c_hat/(E' L), c_hat = {c_hat:.5g} fitted on the"
           f" two loads of the finest mesh (n = {args.n[-1]}); L the block size",
           "# columns: n [elements per semi-axis], nodes, N [N] (body on the flat = the pair), a_fe, b_fe [mm] (edge from the separations"
           " of the open nodes along the axes, see edge_open), p_centre_fe, pmax_fe [MPa] (contact pressure CPRESS at the nodes), u_centre [mm] (body, uncorrected), then Hertz at the"
           " FE load: a_hertz, b_hertz [mm], p0_hertz [MPa], delta_hertz [mm] (body); err_* relative (FE/Hertz - 1), err_delta after"
           " the block correction"]
    with open(out, "w") as f:
        f.write("\n".join(hdr) + "\n")
        f.write("n,nodes,N_N,a_fe_mm,b_fe_mm,p_centre_fe_MPa,pmax_fe_MPa,u_centre_mm,a_hertz_mm,b_hertz_mm,p0_hertz_MPa,"
                "delta_hertz_mm,err_a,err_b,err_p_centre,err_pmax,err_delta\n")
        for n, el, info, _ in res:
            c = c_hat / (ESTAR * info["L"])
            for o in el:
                H = hertz_at_N(A, B, o["N"])
                row = [n, info["nodes"], o["N"], o["a"], o["b"], o["pc"], o["pmax"], o["u"], H["a"], H["b"], H["p0"], H["delta"],
                       o["a"] / H["a"] - 1, o["b"] / H["b"] - 1, o["pc"] / H["p0"] - 1, o["pmax"] / H["p0"] - 1,
                       (o["u"] + c * o["N"]) / H["delta"] - 1]
                f.write(",".join(f"{v:.6g}" for v in row) + "\n")
                print(row, flush=True)


def case_line(Rw, Rr, A, B):
    return (f"wheel and rail of one steel, principal relative radii {Rw:g} mm (rolling) x {Rr:g} mm (transverse) (pair curvature"
            f" sums {2 * A:.6g}, {2 * B:.6g} 1/mm along the model's x and y); x, the larger semi-axis a, is the {x_axis(Rw, Rr)} direction")


def model_line(A, B, k_hat=None):
    return (f"one body with half the pair's curvature sums (A = {A:.6g}, B = {B:.6g} 1/mm) on a rigid frictionless flat,"
            f" half-space idealisation: flat-topped quarter block pressed by a rigid indenter of surface z = A x^2 + B y^2"
            f" (facet corners on the block's (x, y) grid; node-to-surface contact, slave: the block's top faces, penalty "
            + (f"{K_PEN:g} MPa/mm" if k_hat is None else f"K = k_hat E'/b_el = {k_hat:g} E'/b_el, b_el the elastic semi-axis the mesh is scaled to")
            + f"), C3D8I, E = {E:g} MPa, nu = {NU:g}, small strain")


def cmd_plastic(args):
    A, B = pair_curvatures(args.Rw, args.Rr)
    sy = args.sy
    # block correction: elastic run on the mesh of the largest load (self-similar meshes: c_hat holds for all)
    # the block correction from the elastic run of `elastic --p0` on the same n: the meshes are
    # scaled copies, so c_hat = c E' L holds for every row
    kt = "" if args.k_pen is None else f"_k{args.k_pen:g}"
    etag = f"/tmp/fe_runs/e3el_{args.n}_{args.p0:g}_{int(args.Rw)}x{int(args.Rr)}{kt}"
    einfo = elastic_deck(A, B, args.p0, args.n, etag, args.k_pen)
    run(etag)
    el = rows_of(etag, einfo, None)
    c_hat = block_fit(el, einfo)
    runs = []
    for r in args.ratios:
        H = hertz_at_p0(A, B, r * sy)
        tag = f"/tmp/fe_runs/e3pl_{args.n}_{int(sy)}_{int(args.Rw)}x{int(args.Rr)}{kt}_{r:g}"
        runs.append((tag, build(A, B, H["a"], H["b"], args.n, [H["delta"]], sy, tag, penalty(H["b"], args.k_pen))))
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:   # ccx runs are separate processes
        list(pool.map(run, [t for t, _ in runs]))
    rows = []
    for tag, info in runs:
        o = rows_of(tag, info, sy)[-1]
        c = c_hat / (ESTAR * info["L"])
        Hn = hertz_at_N(A, B, o["N"])
        area = math.pi * o["a"] * o["b"]
        rows.append([sy, Hn["p0"] / sy, o["N"], o["a"], o["b"], area, o["N"] / area, o["pc"], o["pmax"],
                     2 * (o["u"] + c * o["N"]), Hn["a"], Hn["b"], 2 * Hn["delta"], o["pe"][0], o["pe"][1], o["pe"][2], o["pe"][3]])
        print(rows[-1], flush=True)
    Ee = [(o["a"] / hertz_at_N(A, B, o["N"])["a"] - 1, o["b"] / hertz_at_N(A, B, o["N"])["b"] - 1,
           o["pc"] / hertz_at_N(A, B, o["N"])["p0"] - 1, (o["u"] + c_hat / (ESTAR * einfo["L"]) * o["N"]) / hertz_at_N(A, B, o["N"])["delta"] - 1)
          for o in el]
    out = args.out or os.path.join(HERE, "..", "..", "tests", "data", "fe", plastic_table(args.Rw, args.Rr, sy, args.n))
    hdr = [f"# generated by scripts/fe/ellip3d.py plastic --sy {sy:g} --ratios {' '.join(f'{r:g}' for r in args.ratios)} --n {args.n}"
           f" --Rw {args.Rw:g} --Rr {args.Rr:g}" + ("" if args.k_pen is None else f" --k-pen {args.k_pen:g}")
           + f" on {datetime.date.today().isoformat()}",
           f"# solver: CalculiX ccx {ccx_version()} (one thread: OMP_NUM_THREADS=1, CCX_NPROC_EQUATION_SOLVER=1)",
           f"# case: {case_line(args.Rw, args.Rr, A, B)},"
           f" elastic-perfectly plastic (von Mises, sigma_y = {sy:g} MPa, no hardening)",
           f"# model: {model_line(A, B, args.k_pen)}",
           f"# mesh: one run per row, scaled to the elastic Hertz patch of the row's prescribed load: n = {args.n} elements per semi-axis,"
           f" uniform zone {FINE:g} a x {FINE:g} b x {FINE:g} b, growth {GROWTH:g}, block {L_OVER_A:g} a (validated elastic: {hertz_table(args.Rw, args.Rr, args.n)})",
           f"# approach corrected for the finite block: delta = u_centre + c N, c = c_hat/(E' L), c_hat = {c_hat:.5g} fitted on the elastic"
           f" run of the same n at peak {args.p0:g} MPa and 0.8 of it ({hertz_table(args.Rw, args.Rr, args.n)}; the meshes are scaled copies)",
           "# elastic run, FE/Hertz - 1 at the two loads (a, b, p_centre, delta after correction): "
           + "; ".join(", ".join(f"{v:+.4f}" for v in e) for e in Ee),
           "# columns (the PAIR): sigma_y [MPa]; p0el_over_sy = elastic Hertz peak at the FE load / sigma_y; N [N]; a, b [mm] semi-axes"
           " (edge from the separations of the open nodes along the axes, see edge_open); area [mm^2] = pi a b; pmean = N/area, p_centre, pmax [MPa] (contact pressure CPRESS at the nodes); delta [mm] corrected approach of the"
           " pair (2 x the body's); a_el, b_el [mm], delta_el [mm] Hertz at the FE load; peeq_max [-] largest nodal equivalent plastic"
           " strain, its depth below the surface and x, y [mm]"]
    with open(out, "w") as f:
        f.write("\n".join(hdr) + "\n")
        f.write("sigma_y_MPa,p0el_over_sy,N_N,a_mm,b_mm,area_mm2,pmean_MPa,p_centre_MPa,pmax_MPa,delta_mm,"
                "a_el_mm,b_el_mm,delta_el_mm,peeq_max,peeq_depth_mm,peeq_x_mm,peeq_y_mm\n")
        for row in rows:
            f.write(",".join(f"{v:.6g}" for v in row) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case", choices=["elastic", "plastic"])
    ap.add_argument("--sy", type=float, default=350.0)
    ap.add_argument("--ratios", type=float, nargs="+", default=[1, 1.5, 2, 2.5, 3, 3.5, 4])
    ap.add_argument("--n", type=int, nargs="+", default=None, help="elements per semi-axis (elastic: several levels)")
    ap.add_argument("--p0", type=float, default=1400.0, help="Hertz peak of the elastic runs' patch [MPa]")
    ap.add_argument("--Rw", type=float, default=460.0)
    ap.add_argument("--Rr", type=float, default=300.0)
    ap.add_argument("--k-pen", type=float, default=None,
                    help="penalty slope K = k_pen E'/b_el per mesh (default: the fixed K_PEN of ccx_common.py)")
    ap.add_argument("--out", default=None)
    ap.add_argument("--jobs", type=int, default=1, help="ccx runs at a time (one thread each)")
    args = ap.parse_args()
    if args.case == "elastic":
        args.n = args.n or [8, 12]
        cmd_elastic(args)
    else:
        args.n = (args.n or [12])[0]
        cmd_plastic(args)


if __name__ == "__main__":
    main()
