#!/usr/bin/env python3
"""Kalker's linear theory of steady rolling on an ellipse by his polynomial (series) method, to
convergence: C11, C22, C23, C33 independent of any element grid.

The problem (Kalker 1990, ch. 1 and Appendix E; Johnson, Contact Mechanics §8.3): two bodies of
equal elastic constants (G, ν) roll in full adhesion (the limit of small creepage) on the ellipse
E = {x²/a² + y²/b² ≤ 1}, x the rolling direction. The slip vanishes everywhere in E:

    ∂u_x/∂x = ξ − φ y,   ∂u_y/∂x = η + φ x          in E                         (S1)

and the traction is bounded (it vanishes) at the leading edge x = a √(1 − y²/b²)     (S2)

(which edge leads only mirrors the solution: the coefficients do not depend on it). u is the
difference of the two bodies' surface displacements, u = A t, with the Cerruti kernel of the two
half-spaces together

    K(r) = 1/(π G r) [ (1 − ν) I + ν r̂ r̂ᵀ ]                                        (K1)

The traction is sought as t = P(x, y) / √(1 − x²/a² − y²/b²), P a polynomial vector of degree n
(products of Chebyshev polynomials T_i(x/a) T_j(y/b), i + j ≤ n). By Galin's theorem A maps such a
traction onto a polynomial displacement of the same degree inside E; the map is computed here by
quadrature at 3 × (number of basis functions) points inside E and a polynomial fit (its residual,
printed, is at rounding level, which checks Galin's theorem and the quadrature together). The
quadrature is in polar coordinates about the field point, where (K1) × r dr is bounded, and along
each ray r = m + h cos ψ takes the inverse square root out exactly: every integrand left is smooth
(trapezoid rule in θ, Gauss–Legendre in ψ).

(S1) is then a polynomial identity: it fixes P up to the n + 1 coefficients per component of the
displacement's part that depends on y alone; those are chosen so that P vanishes on the leading
edge (S2) in the least-squares sense at 4 (n + 1) points (uniform in the angle of the scaled unit
circle). As n grows this converges to the exact linear theory; the sequence of n is printed so
that the convergence shows. The forces are the integrals of t over E (exact quadrature of
P / √(1 − ρ²) in polar coordinates):

    Fx = G c² C11 ξ,   Fy = G c² C22 η + G c³ C23 φ,   Mz = −G c³ C23 η + G c⁴ C33 φ  (c = √(ab))

in magnitude (the signs depend on which body's traction is taken; Kalker's table lists the
magnitudes). C23 comes out twice: from Fy at pure φ and from Mz at pure η (the reciprocity of
the linear theory; their difference is a check of convergence).

Usage: python3 scripts/kalker_series.py [--aob 0.2,0.5,1,2,5] [--nu 0.25,0.28] [--degrees 8,10,12,14,16]
                                        [--out CSV]
One row per (a/b, ν, n), written as it goes. The reference table tests/data/kalker_series/ was
made by it (README there).
"""
import argparse, math, sys, time

import numpy as np
from numpy.polynomial import chebyshev as cheb
from numpy.polynomial.legendre import leggauss


def basis_list(n):
    return [(i, j) for i in range(n + 1) for j in range(n + 1 - i)]


def chebder_matrix(n):
    """D with T'(X) coefficients = D @ coefficients (d/dX of the Chebyshev series)."""
    D = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        e = np.zeros(n + 1)
        e[i] = 1
        d = cheb.chebder(e)
        D[:len(d), i] = d
    return D


def basis_values(B, X, Y, n, d_dX=False):
    TX = cheb.chebvander(X, n)
    if d_dX:
        TX = TX @ chebder_matrix(n)
    TY = cheb.chebvander(Y, n)
    return np.stack([TX[:, i] * TY[:, j] for i, j in B], axis=1)


def displacement_map(a, b, nu, n, Z, nth, nps):
    """u (G = 1) at the points Z (M × 2) from each basis traction P_b / √(1 − x²/a² − y²/b²):
    U[0] u_x from t_x, U[1] u_x from t_y (= u_y from t_x), U[2] u_y from t_y; each M × Nb."""
    B = basis_list(n)
    th = (np.arange(nth) + 0.5) * 2 * np.pi / nth
    ex, ey = np.cos(th), np.sin(th)
    xg, wg = leggauss(nps)
    alpha = ex**2 / a**2 + ey**2 / b**2
    U = np.zeros((3, len(Z), len(B)))
    for k, (x0, y0) in enumerate(Z):
        # along the ray x0 + r e: 1 − |x|²_E = α (r_b − r)(r + r_m) = α h² sin²ψ with r = m + h cos ψ
        beta = x0**2 / a**2 + y0**2 / b**2
        gam = x0 * ex / a**2 + y0 * ey / b**2
        m = -gam / alpha
        h = np.sqrt(gam**2 + alpha * (1 - beta)) / alpha
        psi0 = np.arccos(np.clip(-m / h, -1, 1))               # r = 0
        psi = psi0[:, None] * (xg[None, :] + 1) / 2
        wpsi = psi0[:, None] * wg[None, :] / 2
        r = m[:, None] + h[:, None] * np.cos(psi)
        X = (x0 + r * ex[:, None]) / a
        Y = (y0 + r * ey[:, None]) / b
        V = basis_values(B, X.ravel(), Y.ravel(), n).reshape(nth, nps, len(B))
        # ∫ t dr along the ray = α^(−1/2) ∫ P dψ; the kernel (K1) times r dr is [(1−ν) I + ν e eᵀ]/π
        S = np.einsum('tp,tpb->tb', wpsi, V) * (alpha**-0.5)[:, None] * (2 / nth)
        U[0, k] = ((1 - nu) + nu * ex**2) @ S
        U[1, k] = (nu * ex * ey) @ S
        U[2, k] = ((1 - nu) + nu * ey**2) @ S
    return B, U


def coefficients(aob, nu, n, nth=512, seed=1):
    """C11, C22, C23 (from Fy at pure φ), C23 (from Mz at pure η), C33 at degree n; c = √(ab) = 1, G = 1."""
    a, b = math.sqrt(aob), 1 / math.sqrt(aob)
    B = basis_list(n)
    Nb = len(B)
    M = 3 * Nb
    rng = np.random.default_rng(seed)
    rho, t = 0.8 * np.sqrt(rng.random(M)), 2 * np.pi * rng.random(M)
    Z = np.stack([a * rho * np.cos(t), b * rho * np.sin(t)], axis=1)
    B, U = displacement_map(a, b, nu, n, Z, nth, n + 24)
    V = basis_values(B, Z[:, 0] / a, Z[:, 1] / b, n)
    rhs = U.transpose(1, 0, 2).reshape(M, -1)
    coef = np.linalg.lstsq(V, rhs, rcond=None)[0]
    fit = np.abs(V @ coef - rhs).max() / np.abs(rhs).max()
    coef = coef.reshape(Nb, 3, Nb)
    dU = np.einsum('mk,kqb->mqb', basis_values(B, Z[:, 0] / a, Z[:, 1] / b, n, True) / a, coef)
    # (S1) at the points Z, unknowns [P_x, P_y]
    C = np.vstack([np.hstack([dU[:, 0], dU[:, 1]]), np.hstack([dU[:, 1], dU[:, 2]])])
    # (S2): P = 0 at the leading edge
    nle = 4 * (n + 1)
    Yl = np.cos((np.arange(nle) + 0.5) * np.pi / nle)
    Vl = basis_values(B, np.sqrt(1 - Yl**2), Yl, n)
    L = np.zeros((2 * nle, 2 * Nb))
    L[:nle, :Nb] = Vl
    L[nle:, Nb:] = Vl
    # force and moment of each basis traction: ρ = sin τ takes ρ dρ / √(1 − ρ²) = sin τ dτ
    xr, wr = leggauss(60)
    tau, wt = (xr + 1) * np.pi / 4, wr * np.pi / 4
    nt = 256
    ph = (np.arange(nt) + 0.5) * 2 * np.pi / nt
    R = np.sin(tau)[:, None]
    Xq, Yq = (R * np.cos(ph)).ravel(), (R * np.sin(ph)).ravel()
    wq = np.repeat(wt * np.sin(tau), nt) * (2 * np.pi / nt) * a * b
    Vq = basis_values(B, Xq, Yq, n)
    F, Mx, My = wq @ Vq, (wq * Xq * a) @ Vq, (wq * Yq * b) @ Vq
    # C P = r exactly (its null space: the y-only displacements), min |L P| over that null space
    _, s, Vt = np.linalg.svd(C)
    rank = int((s > s[0] * 1e-10).sum())
    N = Vt[rank:].T
    x, y = np.concatenate([Z[:, 0], Z[:, 0]]), np.concatenate([Z[:, 1], Z[:, 1]])
    ex, ey = np.repeat([1.0, 0.0], M), np.repeat([0.0, 1.0], M)
    out = {}
    for name, r in (('xi', ex), ('eta', ey), ('phi', -y * ex + x * ey)):
        P0 = np.linalg.lstsq(C, r, rcond=1e-12)[0]
        P = P0 + N @ np.linalg.lstsq(L @ N, -L @ P0, rcond=None)[0]
        out[name] = (F @ P[:Nb], F @ P[Nb:], Mx @ P[Nb:] - My @ P[:Nb])
    return dict(C11=abs(out['xi'][0]), C22=abs(out['eta'][1]), C23=abs(out['phi'][1]),
                C23_Mz=abs(out['eta'][2]), C33=abs(out['phi'][2]), fit=fit)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--aob', default='0.2,0.5,1,2,5')
    ap.add_argument('--nu', default='0.25,0.28')
    ap.add_argument('--degrees', default='8,10,12,14,16')
    ap.add_argument('--nth', type=int, default=512, help='trapezoid points in θ')
    ap.add_argument('--out', default=None)
    o = ap.parse_args()
    f = open(o.out, 'w') if o.out else sys.stdout
    f.write('a_over_b,nu,degree,C11,C22,C23,C23_from_Mz,C33,fit_residual,seconds\n')
    for aob in map(float, o.aob.split(',')):
        for nu in map(float, o.nu.split(',')):
            for n in map(int, o.degrees.split(',')):
                t0 = time.time()
                c = coefficients(aob, nu, n, o.nth)
                f.write(f"{aob:g},{nu:g},{n},{c['C11']:.6f},{c['C22']:.6f},{c['C23']:.6f},"
                        f"{c['C23_Mz']:.6f},{c['C33']:.6f},{c['fit']:.1e},{time.time() - t0:.1f}\n")
                f.flush()


if __name__ == '__main__':
    main()
