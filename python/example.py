#!/usr/bin/python3
"""The Python package anisotropic_fairing, step by step (run it as a script, or cell by cell in a notebook).

    pip install --no-build-isolation .        (in a virtual environment; see the README)
    python3 python/example.py [MESH]          (any triangle mesh file meshio reads)

Reads a noisy mesh (default: the bundled noisy fandisk), fairs it with the default run, fairs a noisy
scalar field with it, bounds the deviation, and evaluates and resamples the faired limit surface.
"""
import os
import sys

import meshio
import numpy as np

import anisotropic_fairing as af

# %% A mesh as numpy arrays: V (N x 3 float64 positions), F (M x 3 integer vertex indices), read by meshio
here = os.path.dirname(os.path.abspath(__file__))
bundled = os.path.join(here, '..', 'examples', 'Anisotropic_fairing', 'data', 'fandisk_noisy.obj')
path = sys.argv[1] if len(sys.argv) > 1 else bundled
mesh = meshio.read(path)
V, F = mesh.points, mesh.get_cells_type('triangle')
print('%s: %d vertices, %d faces' % (os.path.basename(path), len(V), len(F)))

# %% The default run: the noise is estimated from the mesh, the tensor, time step and stop chosen from it
V2, _, report = af.fair(V, F)
print('default run: %s after %d steps (%s kept); moved %.3g on average' %
      (report['stop_reason'], len(report['steps']), report['tensor'], np.linalg.norm(V2 - V, axis=1).mean()))
print('  choices:', (report['choices'] or '')[:120], '...')   # None only when the run did not start

# %% A function on the surface, faired with it: a noisy scalar field
rng = np.random.default_rng(1)
field = np.sin(V[:, 0]) + 0.2 * rng.standard_normal(len(V))
V3, field3, report = af.fair(V, F, attributes=field)
assert field3 is not None   # attributes in, attributes out
print('scalar field: roughness %.3g -> %.3g (mean |f_i - f_j| over the edges)' %
      tuple(np.abs(f[F[:, 0]] - f[F[:, 1]]).mean() for f in (field, field3)))

# %% A guaranteed bound: no vertex farther than 0.5% of the model's scale l from where it was
V4, _, report = af.fair(V, F, relative_maximum_deviation=0.005)
largest = np.linalg.norm(V4 - V, axis=1).max()
print('bounded: largest deviation %.4g <= %.4g' % (largest, report['maximum_deviation'] or 0.0))

# %% Progress, and stopping early, with a callback (the GIL is released while the run computes). Every run
# longer than about a second shows its progress on stderr (tqdm's bar if it is installed); quiet=True: not,
# as here, where the callback prints its own. Ctrl-C raises KeyboardInterrupt after the current step.
def progress(step):
    print('  step %d: area %.5g, int |H|^2 %.5g' % (step['step'], step['area'], step['H_integral']))
    return step['step'] < 3   # False ends the run
af.fair(V, F, relative_time_step=1e-4, number_of_iterations=10, callback=progress, quiet=True)

# %% The faired limit surface: control points in, exact limit positions, normals, curvature, finer meshes
V5 = af.fair(V, F, output_positions='control')[0]
surface = af.limit_surface(V5, F)
curvature = surface.curvatures()
print('limit surface: area %.5g, mean curvature from %.3g to %.3g' %
      (surface.area, np.percentile(curvature['mean_curvature'], 1), np.percentile(curvature['mean_curvature'], 99)))
V6, F6, field6 = surface.resample(2, attributes=field3)
print('resampled twice: %d vertices, %d faces, the field resampled with it' % (len(V6), len(F6)))

# %% A meshio.Mesh in, a meshio.Mesh out (its point data faired with it when named): any format meshio writes
faired, report = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={'field': field}), attributes='field')
faired.write(os.path.join(os.environ.get('TMPDIR', '/tmp'), 'faired.vtu'))
print('meshio: %s, the field faired with the surface, written as faired.vtu' % report['stop_reason'])

# %% Errors are Python exceptions with the library's message
try:
    af.fair(V, F[:, :2])
except ValueError as e:
    print('ValueError:', e)
