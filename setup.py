"""The Python package mhcontact, built by the project's CMake through scikit-build (pyproject.toml).
Only the module is installed (CMake component `python`: mhcontact/_core and the package's .py files),
with the library inside the extension; the command-line tool is installed with cmake --install."""
import re
import sys
from pathlib import Path

from skbuild import setup

here = Path(__file__).resolve().parent
version = re.search(r"project\(mhcontact\s+VERSION\s+([0-9.]+)", (here / "CMakeLists.txt").read_text()).group(1)

setup(
    name="mhcontact",
    version=version,
    description="Wheel-rail normal contact: multi-Hertzian method, elastic half-space, strips",
    license="Apache-2.0",
    python_requires=">=3.9",
    install_requires=["numpy"],
    packages=["mhcontact"],
    package_dir={"": "python"},
    cmake_args=["-DCMAKE_BUILD_TYPE=Release", "-DMHCONTACT_BUILD_TESTS=OFF", "-DMHCONTACT_PYTHON=ON", "-DMHCONTACT_PYTHON_ONLY=ON",
                "-DMHCONTACT_PYTHON_INSTALL_DIR=.", "-DPython3_EXECUTABLE=" + sys.executable],
    cmake_install_dir="python",
    cmake_install_target="install-python",
)
