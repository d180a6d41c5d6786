#!/usr/bin/env python3
"""A thin ctypes driver of CONTACT's library version (module 3: one Hertzian ellipse, steady rolling).

CONTACT (E. A. H. Vollebregt, https://github.com/eve70a/CONTACT, Apache-2.0) builds a shared library
`contact_addon_linux64.so` (make PROD=clib_l64; tests/data/contact_tangential/README.md says how it was
built here). Its `cntc_*` routines take every argument by reference (Fortran bind(c) without VALUE),
so each call below passes pointers. Used by scripts/contact_c33.py; the same settings as CONTACT's
own program src/test_table.f90 (the 3,220-case table), so that both speak for the same solver:
module 3, steady rolling (T = 3), the exact normal pressure of the grid (B = 0) or a prescribed
Hertzian bound, the exact tangential solver (M = 0), Coulomb friction, CONTACT's units (N, mm,
N/mm², φ in rad/mm). Signs are Kalker's, module 3's: forces on body 1 (the wheel), a positive
creepage gives a negative force (lib/contact/tangential/tangential_types.hpp).
"""
import ctypes as C

# caddon_flags.inc of CONTACT 25.2 (the codes of the flags passed to cntc_setflags and friends)
IF_UNITS, UN_CNTC = 1933, 1934
IC_BOUND, IC_TANG = 1971, 1972
IC_OUTPUT, IC_FLOW, IC_MATFIL = 1984, 1985, 1987
IF_IDEBUG, IF_WRTINP, IF_OPENMP = 2000, 2002, 2003


class Contact:
    """One CONTACT result element (ire = 1), one contact problem (icp = 1), module 3."""

    def __init__(self, library, G=82000.0, nu=0.28, mu=0.3, fn=82000.0, veloc=10000.0, bound=0,
                 eps=1e-9, maxgs=2000):
        self.lib = C.CDLL(library)
        self.ire, self.icp = C.c_int(1), C.c_int(1)
        ver, ierr, iout = C.c_int(0), C.c_int(0), C.c_int(0)
        empty = C.c_char_p(b"")
        name = b"c33"
        self.lib.cntc_initializefirst(C.byref(ver), C.byref(ierr), C.byref(iout), empty, empty,
                                      C.c_char_p(name), C.byref(C.c_int(0)), C.byref(C.c_int(0)),
                                      C.byref(C.c_int(len(name))))
        self._flags(self.lib.cntc_setglobalflags, [(IF_IDEBUG, 0), (IF_OPENMP, -1)], local=False)
        self.lib.cntc_initialize(C.byref(self.ire), C.byref(C.c_int(3)), C.byref(ver), C.byref(ierr),
                                 empty, C.byref(C.c_int(0)))
        self._flags(self.lib.cntc_setflags, [(IF_UNITS, UN_CNTC), (IF_WRTINP, 0), (IC_MATFIL, 0),
                                             (IC_OUTPUT, 0), (IC_FLOW, 0), (IC_TANG, 3), (IC_BOUND, bound)])
        self._reals(self.lib.cntc_setfrictionmethod, 0, [mu, mu])
        self._reals(self.lib.cntc_setmaterialparameters, 0, [nu, nu, G, G])
        self.lib.cntc_setreferencevelocity(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_double(veloc)))
        self.lib.cntc_setnormalforce(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_double(fn)))
        ip = (C.c_int * 4)(maxgs, 1, 30, 1)      # MAXGS, MAXIN, MAXNR, MAXOUT
        rp = (C.c_double * 1)(eps)
        self.lib.cntc_setsolverflags(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_int(0)),
                                     C.byref(C.c_int(4)), ip, C.byref(C.c_int(1)), rp)

    def _flags(self, fn, pairs, local=True):
        n = len(pairs)
        f = (C.c_int * n)(*[p[0] for p in pairs])
        v = (C.c_int * n)(*[p[1] for p in pairs])
        if local:
            fn(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_int(n)), f, v)
        else:
            fn(C.byref(C.c_int(n)), f, v)

    def _reals(self, fn, imeth, vals):
        arr = (C.c_double * len(vals))(*vals)
        fn(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_int(imeth)), C.byref(C.c_int(len(vals))), arr)

    def solve(self, aa, bb, mx, my, scale, cksi, ceta, cphi):
        """The ellipse aa × bb [mm] on mx × my elements over scale × the ellipse; creepages ξ, η [-],
        φ [rad/mm]. Returns dict FN, FX, FY [N], MZ [N mm], adhesion fraction, ierr."""
        p = (C.c_double * 5)(mx, my, aa, bb, scale)
        self.lib.cntc_sethertzcontact(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_int(-3)),
                                      C.byref(C.c_int(5)), p)
        self.lib.cntc_setcreepages(C.byref(self.ire), C.byref(self.icp), C.byref(C.c_double(cksi)),
                                   C.byref(C.c_double(ceta)), C.byref(C.c_double(cphi)))
        ierr = C.c_int(0)
        self.lib.cntc_calculate(C.byref(self.ire), C.byref(self.icp), C.byref(ierr))
        fn, fx, fy, mz = (C.c_double() for _ in range(4))
        self.lib.cntc_getcontactforces(C.byref(self.ire), C.byref(self.icp), C.byref(fn), C.byref(fx),
                                       C.byref(fy), C.byref(mz))
        ca, ha, sa = C.c_double(), C.c_double(), C.c_double()
        self.lib.cntc_getcontactpatchareas(C.byref(self.ire), C.byref(self.icp), C.byref(ca), C.byref(ha),
                                           C.byref(sa))
        return {"FN": fn.value, "FX": fx.value, "FY": fy.value, "MZ": mz.value,
                "adhesion": ha.value / ca.value if ca.value > 0 else float("nan"), "ierr": ierr.value}

    def close(self):
        self.lib.cntc_finalize(C.byref(self.ire))
