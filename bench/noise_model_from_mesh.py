#!/usr/bin/env python3
"""What the noisy mesh alone says of its noise (issue 53, point 1), beside what its clean mesh says
(noise_model_pairs.py): each vertex's offset from its ring's centroid along the ring's normal (the noise at the
vertex less its ring's mean, plus curvature), read for its size, its spread over the surface against the same
offsets shuffled, its tails, and a lattice of the coordinates. A first measure of how far an estimate from the
mesh can tell the noise kinds apart; the package's estimator is not changed by it.

    python3 bench/noise_model_from_mesh.py DIR_OR_MESH...

A folder as noise_model_pairs.py reads; a mesh file (OBJ, OFF) alone: a scan without a clean mesh.

Prints one Markdown row per case: the estimate, and in brackets the truth where noise_model_pairs.py has it."""
import os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from noise_model_pairs import read_mesh, vertex_normals, mean_edge, regional_sigma, lattice_step   # noqa: E402


def ring_mean(V, F):
    """Per vertex: the mean of its neighbours' rows of V (a vector or an array of rows)."""
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    E = np.unique(np.sort(E, axis=1), axis=0)
    count = np.bincount(E.ravel(), minlength=len(V)).astype(float)
    total = np.zeros_like(V)
    np.add.at(total, E[:, 0], V[E[:, 1]])
    np.add.at(total, E[:, 1], V[E[:, 0]])
    return total / (np.maximum(count, 1)[:, None] if V.ndim == 2 else np.maximum(count, 1))


def ring_offsets(V, F):
    """Per vertex: (y - mean of its neighbours) . n, n the area-weighted normal at the vertex."""
    return np.sum((V - ring_mean(V, F)) * vertex_normals(V, F), axis=1)


def neighbour_correlation(r, F):
    """The correlation of a vertex's value with its ring's mean: about -1/sqrt(k) for ring offsets of noise
    independent from vertex to vertex, near 0 for independent noise itself, higher where it is correlated."""
    return np.corrcoef(r, ring_mean(r, F))[0, 1]


def tails(r):
    robust = 1.4826 * np.median(np.abs(r - np.median(r)))
    kurtosis = np.mean((r - r.mean()) ** 4) / np.mean((r - r.mean()) ** 2) ** 2
    return robust, kurtosis, np.mean(np.abs(r) > 4 * robust) if robust > 0 else np.nan   # (no core: nan)


def main():
    print('| case | offset rms / h (true noise) | regional max/min (shuffled) | kurtosis (true) '
          '| beyond 4 sigma_robust (true) | neighbour correlation (true) | lattice step / size |')
    print('|---|---|---|---|---|---|---|')
    for folder in sys.argv[1:]:
        if os.path.isfile(folder): folder, noisy, clean = os.path.dirname(folder), os.path.basename(folder), ''
        elif os.path.isfile(os.path.join(folder, 'Noisy.obj')): noisy, clean = 'Noisy.obj', 'Original.obj'
        else: noisy, clean = 'noisy.off', 'original.off'
        Y, F = read_mesh(os.path.join(folder, noisy))
        r = ring_offsets(Y, F)
        h = mean_edge(Y, F)
        robust, kurtosis, beyond = tails(r)
        lo, hi = regional_sigma(Y, r)
        slo, shi = regional_sigma(Y, np.random.default_rng(1).permutation(r))
        truth = ('', '', '', '')   # the truth: the clean mesh's normals, noise_model_pairs.py's measures
        if clean and os.path.isfile(os.path.join(folder, clean)):
            X, _ = read_mesh(os.path.join(folder, clean))
            dn = np.sum((Y - X) * vertex_normals(X, F), axis=1)
            t_robust, t_kurtosis, t_beyond = tails(dn)
            truth = (np.sqrt(np.mean(dn ** 2)) / h, t_kurtosis, t_beyond, neighbour_correlation(dn, F))
        with np.errstate(divide='ignore'):   # a region without offsets (a flat face on the lattice): inf
            spread, shuffled = hi / lo, shi / slo
        print('| %s | %.3f (%s) | %.2f (%.2f) | %.1f (%s) | %.2f%% (%s) | %.2f (%s) | %.2g |' % (
            os.path.basename(os.path.normpath(folder)) + ('' if clean else '/' + noisy), np.sqrt(np.mean(r ** 2)) / h,
            '%.3f' % truth[0] if truth[0] != '' else '-', spread, shuffled, kurtosis,
            '%.1f' % truth[1] if truth[1] != '' else '-', 100 * beyond,
            '%.2f%%' % (100 * truth[2]) if truth[2] != '' and np.isfinite(truth[2]) else '-',
            neighbour_correlation(r, F), '%.2f' % truth[3] if truth[3] != '' else '-', lattice_step(Y)))


if __name__ == '__main__':
    main()
