"""pip install . -- the Python package anisotropic_fairing, built by CMake through scikit-build.

    python3 -m venv --system-site-packages env && env/bin/pip install --no-build-isolation .

Debian 12 gives every build dependency (python3-skbuild, pybind11-dev, python3-dev, python3-numpy, cmake,
g++ and the library's libcgal-dev, libeigen3-dev, libboost-dev, libtbb-dev, nlohmann-json3-dev):
--no-build-isolation builds with them, without the network. CMake builds only the module
(ANISOTROPIC_FAIRING_PYTHON_ONLY) and installs it into the package beside python/src/anisotropic_fairing/.
"""
import os
import re

from skbuild import setup

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, 'CMakeLists.txt')) as f:
    version = re.search(r'project\(Anisotropic_fairing VERSION ([0-9.]+)', f.read()).group(1)

setup(
    name='anisotropic_fairing',
    version=version,
    description='Anisotropic fairing of triangle meshes and of functions on them with Loop-subdivision finite elements',
    license='GPL-3.0-or-later',
    packages=['anisotropic_fairing'],
    package_dir={'': 'python/src'},
    package_data={'anisotropic_fairing': ['py.typed', '*.pyi']},
    python_requires='>=3.9',
    install_requires=['numpy'],
    extras_require={'meshio': ['meshio'], 'open3d': ['open3d'], 'vtk': ['vtk'], 'progress': ['tqdm']},
    cmake_args=['-DANISOTROPIC_FAIRING_PYTHON_ONLY=ON', '-DBUILD_TESTING=OFF', '-DCMAKE_BUILD_TYPE=Release'],
    cmake_install_dir='python/src',
)
