#!/usr/bin/env python3
"""How far the noise of a mesh is correlated over its surface (issue 53, point 1: scanner noise is correlated
over neighbouring vertices, which a per-vertex estimate reads as shape, and too small).

Two statistics per mesh:
- the residual of the mesh after a few umbrella steps, along the normals, correlated with its mean over the ring
  (the first measurement; shape raises it as much as correlation does);
- the second differences of the heights (a vertex's height over its ring's centroid, along its normal, minus the
  ring's mean height: what the package's noise estimate reads), clipped at 3 robust deviations, correlated with
  their mean over the ring (lag 1) and over the next ring (lag 2). The same for unit noise drawn on the mesh's own
  connectivity and averaged k = 0, 1, 2 times with its ring's mean (half each) is the null curve: independent
  noise lies at k = 0, correlated noise further along it, shape off it. The reading of the noise estimate falls
  along the curve too (unit noise averaged once reads 0.66), which is what a correlation would correct.

    python3 bench/noise_correlation.py [--steps N] DIR_OR_MESH...
(a DIR holds noisy.off or Noisy.obj; its original.off, when there, is read too: the clean mesh's own reading)"""
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


def rings(F, n):
    """Each vertex's ring, and the ring of its ring without either."""
    nb = [set() for _ in range(n)]
    for f in F:
        for x in range(3): nb[f[x]].update((f[(x + 1) % 3], f[(x + 2) % 3]))
    second = []
    for i in range(n):
        s = set().union(*(nb[j] for j in nb[i])) if nb[i] else set()
        second.append(np.array(sorted(s - nb[i] - {i}), dtype=int))
    return [np.array(sorted(s), dtype=int) for s in nb], second


def mean_over(d, R):
    return np.array([d[r].mean() if len(r) else 0.0 for r in R])


def lags(height, R):
    """The clipped second differences of `height`, correlated with their means over the ring and the next."""
    d = height - mean_over(height, R[0])
    s = 1.4826 * np.median(np.abs(d))
    d = np.clip(d, -3 * s, 3 * s)
    return tuple(np.corrcoef(d, mean_over(d, r))[0, 1] for r in R)


def null_curve(R, n, rng):
    out = []
    for k in (0, 1, 2):
        u = rng.standard_normal(n)
        for _ in range(k): u = 0.5 * u + 0.5 * mean_over(u, R[0])
        out.append(lags(u - mean_over(u, R[0]), R))
    return out


def row(label, path, steps, rng):
    Y, F = read_mesh(path)
    r = residual(Y, F, steps)
    R = rings(F, len(Y))
    height = np.sum((Y - ring_mean(Y, F)) * vertex_normals(Y, F), axis=1)
    null = ' | '.join('%.2f / %.2f' % c for c in null_curve(R, len(Y), rng))
    print('| %s | %.3f | %.2f | %.2f / %.2f | %s |' % (label, np.sqrt(np.mean(r ** 2)) / mean_edge(Y, F),
                                                     np.corrcoef(r, ring_mean(r, F))[0, 1], *lags(height, R), null))
    sys.stdout.flush()


def main():
    args = sys.argv[1:]
    steps = 3
    if args[:1] == ['--steps']: steps, args = int(args[1]), args[2:]
    rng = np.random.default_rng(1)
    print('| mesh | residual rms / h | its correlation with the ring | second differences: lag 1 / lag 2 | '
          'null k = 0 | k = 1 | k = 2 |')
    print('|---|---|---|---|---|---|---|')
    for arg in args:
        if os.path.isfile(arg):
            row(os.path.basename(arg), arg, steps, rng)
            continue
        noisy = os.path.join(arg, 'Noisy.obj') if os.path.isfile(os.path.join(arg, 'Noisy.obj')) \
            else os.path.join(arg, 'noisy.off')
        row(os.path.basename(os.path.normpath(arg)), noisy, steps, rng)
        if os.path.isfile(os.path.join(arg, 'original.off')):
            row(os.path.basename(os.path.normpath(arg)) + ' (clean)', os.path.join(arg, 'original.off'), steps, rng)


if __name__ == '__main__':
    main()
