#!/usr/bin/env python3
"""How far the noise of a mesh is correlated over its surface (issue 53, point 1: scanner noise is correlated
over neighbouring vertices, which a per-vertex estimate reads as shape). The residual of the noisy mesh after
a few umbrella steps, along the normals, is correlated with its mean over the ring.
The same filter applied to independent noise (the pairs and write_cases' Gaussian cases) gives the values that
mean "no correlation"; higher values are noise that varies smoothly over the surface, or fine shape.

    python3 bench/noise_correlation.py [--steps N] DIR_OR_MESH..."""
import os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from noise_model_pairs import read_mesh, vertex_normals, mean_edge   # noqa: E402
from noise_model_from_mesh import ring_mean   # noqa: E402


def residual(Y, F, steps):
    """(Y - Y smoothed by `steps` umbrella steps of 1/2) along the normals of Y."""
    S = Y.copy()
    for _ in range(steps): S = 0.5 * S + 0.5 * ring_mean(S, F)
    return np.sum((Y - S) * vertex_normals(Y, F), axis=1)


def main():
    args = sys.argv[1:]
    steps = 3
    if args[:1] == ['--steps']: steps, args = int(args[1]), args[2:]
    print('| mesh | residual rms / h | correlation with its ring |')
    print('|---|---|---|')
    for arg in args:
        path = arg if os.path.isfile(arg) else os.path.join(arg, 'Noisy.obj') \
            if os.path.isfile(os.path.join(arg, 'Noisy.obj')) else os.path.join(arg, 'noisy.off')
        Y, F = read_mesh(path)
        r = residual(Y, F, steps)
        size = np.sqrt(np.mean(r ** 2)) / mean_edge(Y, F)
        correlation = np.corrcoef(r, ring_mean(r, F))[0, 1]
        print('| %s | %.3f | %.2f |' % (os.path.basename(os.path.normpath(arg)), size, correlation))


if __name__ == '__main__':
    main()
