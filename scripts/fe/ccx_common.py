"""Helpers shared by the CalculiX scripts of scripts/fe: material constants, graded node spacing,
running ccx, step bookkeeping, the CalculiX version for the provenance lines, Hertz for an ellipse
on a rigid flat and the contact-edge estimate. Units mm, N, MPa.
"""
import math, os, subprocess, sys

E, NU = 210000.0, 0.3           # MPa, -
ESTAR = E / (1 - NU * NU)       # rigid flat: composite modulus E' = E/(1 - nu^2)
K_PEN = 1.0e7                   # MPa/mm penalty slope of the node-to-surface contact (axisym.py)


def graded(x0, x1, h, x_fine, growth=1.25):
    """Nodes from x0 to x1: uniform step h up to x_fine, then growing by `growth`."""
    xs = [x0]
    while xs[-1] + h <= x_fine + 1e-12:
        xs.append(xs[-1] + h)
    step = h
    while xs[-1] < x1 - 1e-12:
        step *= growth
        nxt = xs[-1] + step
        if nxt > x1 - 0.5 * step:
            nxt = x1
        xs.append(nxt)
    return xs


def run(name):
    """Runs `nice -n 10 ccx -i name` with one thread. An earlier run of the same deck (its copy
    name.inp.done) is re-used; FE_REUSE=1 re-parses any earlier results."""
    os.makedirs(os.path.dirname(name) or ".", exist_ok=True)
    if os.environ.get("FE_REUSE") and os.path.exists(name + ".frd"):
        return
    deck = open(name + ".inp").read()
    if os.path.exists(name + ".inp.done") and open(name + ".inp.done").read() == deck:
        return
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    p = subprocess.run(["nice", "-n", "10", "ccx", "-i", os.path.abspath(name)], env=env, capture_output=True, text=True,
                       cwd=os.path.dirname(os.path.abspath(name)))   # ccx writes spooles.out etc. into its cwd
    if "Job finished" not in p.stdout:
        sys.stderr.write(p.stdout[-3000:])
        raise RuntimeError("ccx failed on " + name)
    with open(name + ".inp.done", "w") as f:
        f.write(deck)


def step_of(t):
    """Step index of a total time t (every step has period 1)."""
    return max(0, math.ceil(t - 1e-7) - 1)


def ccx_version():
    out = subprocess.run(["ccx", "-v"], capture_output=True, text=True).stdout.splitlines()
    v = [l.strip() for l in out if "Version" in l]
    return v[0] if v else "?"


def write_nset(w, name, ns):
    w(f"*NSET, NSET={name}\n")
    for k in range(0, len(ns), 12):
        w(", ".join(map(str, ns[k:k + 12])) + ",\n")


def smooth(pts, w):
    """Moving least-squares (quadratic) smoothing of a pressure profile [(r, p)], window half-width w:
    the nodal -S_zz of quadratic elements under node-to-surface penalty contact alternates between
    corner and mid-side nodes by a few per cent; the local fit averages it out."""
    pts = sorted(pts)
    out = []
    for r0, _ in pts:
        S = [[0.0] * 3 for _ in range(3)]
        t = [0.0] * 3
        for r, p in pts:
            if abs(r - r0) <= w:
                x = r - r0
                v = (1.0, x, x * x)
                for i in range(3):
                    t[i] += v[i] * p
                    for j in range(3):
                        S[i][j] += v[i] * v[j]
        def det(M):
            return (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
                    + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
        d = det(S)
        M0 = [[t[i]] + S[i][1:] for i in range(3)]
        out.append((r0, det(M0) / d if abs(d) > 0 else 0.0))
    return out


def edge_p2(pts):
    """Contact edge along a line of surface nodes [(r, p)]: p^2 extrapolated linearly to zero from
    the last two loaded nodes (the Hertz edge has p^2 linear in the distance to it)."""
    pts = sorted(pts)
    pmax = max(p for _, p in pts)
    last = max(i for i, (_, p) in enumerate(pts) if p > 1e-3 * pmax)
    (r1, p1), (r2, p2) = pts[last - 1], pts[last]
    if p1 * p1 - p2 * p2 <= 0:
        return r2
    e = r2 + p2 * p2 * (r2 - r1) / (p1 * p1 - p2 * p2)
    return min(e, pts[last + 1][0]) if last + 1 < len(pts) else e


def agm_KE(m):
    """Complete elliptic integrals K(m), E(m), parameter m = e^2 (AGM)."""
    a, b, s, p = 1.0, math.sqrt(1 - m), m / 2, 0.5
    while abs(a - b) > 1e-15:
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        p *= 2
        s += p * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - s)


def hertz_ellipse(A, B):
    """Hertz k = b/a for curvature sums A < B (a along x), by bisection on (E/k^2 - K)/(K - E) = B/A."""
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


def hertz_at_p0(A, B, p0, estar=ESTAR):
    """Hertz ellipse of curvature sums A <= B [1/mm] with peak p0 [MPa], modulus estar [MPa]
    (Johnson, Contact Mechanics §4.2): semi-axes a >= b [mm], approach delta [mm], load N [N]."""
    k = hertz_ellipse(A, B)
    e2 = 1 - k * k
    K, Ee = agm_KE(e2)
    a = p0 * k * (K - Ee) / (estar * e2 * A)
    b = k * a
    return dict(a=a, b=b, p0=p0, delta=p0 * b * K / estar, N=2 / 3 * math.pi * a * b * p0)


def hertz_at_N(A, B, N, estar=ESTAR):
    h1 = hertz_at_p0(A, B, 1000.0, estar)
    p0 = 1000.0 * (N / h1["N"]) ** (1 / 3)
    return hertz_at_p0(A, B, p0, estar)
