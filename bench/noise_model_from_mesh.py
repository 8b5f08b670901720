#!/usr/bin/env python3
"""What the noisy mesh alone says of its noise (issue 53, point 1), beside what its clean mesh says
(noise_model_pairs.py): each vertex's offset from its ring's centroid along the ring's normal (the noise at the
vertex less its ring's mean, plus curvature), read for its size, its spread over the surface against the same
offsets shuffled, its tails, and a lattice of the coordinates. A first measure of how far an estimate from the
mesh can tell the noise kinds apart; the package's estimator is not changed by it.

    python3 bench/noise_model_from_mesh.py DIR...      (the folders of noise_model_pairs.py)

Prints one Markdown row per case: the estimate, and in brackets the truth where noise_model_pairs.py has it."""
import os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from noise_model_pairs import read_mesh, vertex_normals, mean_edge, regional_sigma, lattice_step   # noqa: E402


def ring_offsets(V, F):
    """Per vertex: (y - mean of its neighbours) . n, n the area-weighted normal at the vertex."""
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    E = np.unique(np.sort(E, axis=1), axis=0)
    count = np.bincount(E.ravel(), minlength=len(V)).astype(float)
    centroid = np.zeros_like(V)
    np.add.at(centroid, E[:, 0], V[E[:, 1]])
    np.add.at(centroid, E[:, 1], V[E[:, 0]])
    centroid /= np.maximum(count, 1)[:, None]
    return np.sum((V - centroid) * vertex_normals(V, F), axis=1)


def tails(r):
    robust = 1.4826 * np.median(np.abs(r - np.median(r)))
    kurtosis = np.mean((r - r.mean()) ** 4) / np.mean((r - r.mean()) ** 2) ** 2
    return robust, kurtosis, np.mean(np.abs(r) > 4 * robust) if robust > 0 else np.nan   # (no core: nan)


def main():
    print('| case | offset rms / h (true noise) | regional max/min (shuffled) | kurtosis (true) '
          '| beyond 4 sigma_robust (true) | lattice step / size |')
    print('|---|---|---|---|---|---|')
    for folder in sys.argv[1:]:
        obj = os.path.isfile(os.path.join(folder, 'Noisy.obj'))
        noisy, clean = ('Noisy.obj', 'Original.obj') if obj else ('noisy.off', 'original.off')
        Y, F = read_mesh(os.path.join(folder, noisy))
        r = ring_offsets(Y, F)
        h = mean_edge(Y, F)
        robust, kurtosis, beyond = tails(r)
        lo, hi = regional_sigma(Y, r)
        slo, shi = regional_sigma(Y, np.random.default_rng(1).permutation(r))
        truth = ('', '', '')   # the truth: the clean mesh's normals, noise_model_pairs.py's measures
        if os.path.isfile(os.path.join(folder, clean)):
            X, _ = read_mesh(os.path.join(folder, clean))
            dn = np.sum((Y - X) * vertex_normals(X, F), axis=1)
            t_robust, t_kurtosis, t_beyond = tails(dn)
            truth = (np.sqrt(np.mean(dn ** 2)) / h, t_kurtosis, t_beyond)
        with np.errstate(divide='ignore'):   # a region without offsets (a flat face on the lattice): inf
            spread, shuffled = hi / lo, shi / slo
        print('| %s | %.3f (%s) | %.2f (%.2f) | %.1f (%s) | %.2f%% (%s) | %.2g |' % (
            os.path.basename(os.path.normpath(folder)), np.sqrt(np.mean(r ** 2)) / h,
            '%.3f' % truth[0] if truth[0] != '' else '-', spread, shuffled, kurtosis,
            '%.1f' % truth[1] if truth[1] != '' else '-', 100 * beyond,
            '%.2f%%' % (100 * truth[2]) if truth[2] != '' and np.isfinite(truth[2]) else '-', lattice_step(Y)))


if __name__ == '__main__':
    main()
