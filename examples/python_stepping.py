"""A wheel stepped through a lateral motion, the contact solved at every step, as
examples/c_stepping does in C (docs/python.md). Notebook style: run it, read it, change it.

    PYTHONPATH=<prefix>/lib/python3/dist-packages python3 python_stepping.py [--case CASE.json] [--plot out.png]

Without --case the pair is S1002 on 60E1 canted 1:40, generated from the standards. The wheel
moves t_Y(t) = 7 mm sin(2 pi t / 1 s) for one second at 1 kHz under Q = 50 kN; every 50th step
is printed as in c_stepping. With matplotlib installed, --plot draws Fy and the contact angle.
"""
import argparse

import numpy as np

import mhcontact

# %% The pair: built once (geometry tables), then shared by every step.
ap = argparse.ArgumentParser()
ap.add_argument("--case", help="a case file (e.g. cases/manchester.json): its pair, as `mhcontact run` builds it")
ap.add_argument("--plot", help="write a plot of the forces to this file (needs matplotlib)")
args = ap.parse_args()
if args.case:
    pair = mhcontact.Pair.from_case_file(args.case)
else:
    pair = mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                          {"rail_inclination": "1:40"})
print(f"mhcontact {mhcontact.__version__} (ABI {mhcontact.abi_version}, FFT {mhcontact.fft_backend})")

# %% Step by step, as a time integrator would call it (one call per step).
steps = 1000
t = np.arange(steps + 1) / steps                  # [s]
tY = 7e-3 * np.sin(2 * np.pi * t)                 # [m]
print("t_s,tY_mm,status,n_contacts,Fz_kN,Fy_kN,pmax_MPa,gamma_main_deg,dFz_ddz_kN_per_mm")
for k in range(0, steps + 1, 50):
    r = pair.solve(tY[k], Q_N=50e3)
    print(f"{t[k]:.3f},{r['tY_mm']:.3f},{r['status']},{r['n_contacts']},{r['Fz_kN']:.3f},{r['Fy_kN']:.3f},"
          f"{r['pmax_MPa']:.1f},{r['gamma_main_deg']:.3f},{r['dFz_ddz_kN_per_mm']:.1f}")

# %% All steps at once: columns named as in cases.csv, solved on every core without the GIL.
cols = pair.solve_many(tY, Q_N=50e3)
print(f"solve_many: {np.sum(cols['status'] == 'ok')} of {tY.size} steps ok, "
      f"largest Fy {np.nanmax(cols['Fy_kN']):.1f} kN at t_Y = {cols['tY_mm'][np.nanargmax(cols['Fy_kN'])]:.2f} mm")

# %% The penetration-driven force element: the approach prescribed, its stiffness.
dz = pair.solve(0.0, Q_N=50e3)["dz_virtual_mm"] * 1e-3
for f in (1.0, 1.1):
    r = pair.solve(0.0, dz_m=f * dz)
    print(f"approach {f * dz * 1e3:.6f} mm: Fz {r['Fz_kN']:.3f} kN, stiffness {r['dFz_ddz_kN_per_mm']:.1f} kN/mm")

# %% A plot, if matplotlib is there.
if args.plot:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no plot")
    else:
        fig, ax = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
        ax[0].plot(t, cols["Fy_kN"], label="Fy")
        ax[0].plot(t, cols["Fz_kN"], label="Fz")
        ax[0].set_ylabel("force [kN]")
        ax[0].legend()
        ax[1].plot(t, cols["gamma_main_deg"])
        ax[1].set_ylabel("contact angle [deg]")
        ax[1].set_xlabel("t [s]")
        fig.savefig(args.plot, dpi=100)
        print(f"plot: {args.plot}")
