#!/usr/bin/env bash
# `pip install .` as docs/python.md#installing-with-pip gives it, offline: a fresh virtual
# environment over Debian's packages (--system-site-packages: numpy, scikit-build, setuptools),
# pip builds the module through the project's CMake (pyproject.toml, setup.py) and installs it;
# the installed module is imported from outside the source tree and solves a case.
# The source is copied first (scikit-build builds in the source tree, in _skbuild/), to a fixed
# place in the build directory so that ccache makes a re-run cheap.
set -euo pipefail
src=$1; build=$2; py=${3:-/usr/bin/python3}
work=$build/pip-test
rm -rf "$work"; mkdir -p "$work/src"
tar -C "$src" --exclude='./build*' --exclude=./_skbuild --exclude=./.git --exclude='*.egg-info' -cf - . | tar -C "$work/src" -xf -
command -v ccache >/dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=ccache
cd "$work/src"
# --- docs/python.md, Installing with pip ---
"$py" -m venv --system-site-packages "$work/venv"
PIP_NO_INDEX=1 "$work/venv/bin/pip" install -q --no-build-isolation .
cd "$work"
"$work/venv/bin/python" - "$work/venv" <<'PY'
import os, sys
import mhcontact
venv = os.path.realpath(sys.argv[1])
assert os.path.realpath(mhcontact.__file__).startswith(venv), mhcontact.__file__  # the installed copy
pair = mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"), {"rail_inclination": "1:40"})
r = pair.solve(2e-3, Q_N=50e3)
assert r["status"] in ("ok", "outside_validity") and abs(r["Fz_kN"] - 50) < 1e-6 * 50, r
assert callable(mhcontact.fleet)
print("pip_install: mhcontact", mhcontact.__version__, "from", os.path.dirname(mhcontact.__file__), "Fz_kN", r["Fz_kN"])
PY
rm -rf "$work"
