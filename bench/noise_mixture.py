#!/usr/bin/env python3
"""A Gaussian core plus sparse hits (issue 53, point 1), fitted by EM to the ring offsets of the noisy mesh
(noise_model_from_mesh.py): r ~ (1 - p) N(0, s0^2) + p N(0, s1^2), s1 > s0. Gives each vertex a probability of
being hit. Beside the truth where there is a clean mesh: the vertices whose noise along the normal exceeds
half an edge, on the impulsive cases (the generated ones move a tenth of the vertices by one edge): how many of
them the fit flags (recall) and how many it flags that are not (precision). A vertex is flagged when the broad
component is the likelier and its offset is the largest of its ring.

    python3 bench/noise_mixture.py DIR_OR_MESH..."""
import os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from noise_model_pairs import read_mesh, vertex_normals, mean_edge   # noqa: E402
from noise_model_from_mesh import ring_offsets   # noqa: E402


def ring_maximum(a, F):
    """Per vertex: the largest of a over its neighbours."""
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    m = np.full(len(a), -np.inf)
    np.maximum.at(m, E[:, 0], a[E[:, 1]])
    np.maximum.at(m, E[:, 1], a[E[:, 0]])
    return m


def fit_mixture(r, iterations=200):
    """EM for two zero-mean normals; returns (p, s0, s1, posterior of the broad one per value)."""
    s0 = max(1.4826 * np.median(np.abs(r)), 1e-12 * np.abs(r).max() + 1e-300)
    s1, p = max(3 * np.sqrt(np.mean(r ** 2)), 2 * s0), 0.1
    for _ in range(iterations):
        a = (1 - p) * np.exp(-0.5 * (r / s0) ** 2) / s0
        b = p * np.exp(-0.5 * (r / s1) ** 2) / s1
        w = b / np.maximum(a + b, 1e-300)
        p = np.clip(w.mean(), 1e-6, 1 - 1e-6)
        s0 = np.sqrt(np.sum((1 - w) * r ** 2) / max(np.sum(1 - w), 1e-300))
        s1 = max(np.sqrt(np.sum(w * r ** 2) / max(np.sum(w), 1e-300)), 1.5 * s0)
    return p, s0, s1, w


def main():
    print('| case | hit share p | core s0 / h | hits s1 / h | flagged | true hits | recall | precision |')
    print('|---|---|---|---|---|---|---|---|')
    for arg in sys.argv[1:]:
        if os.path.isfile(arg): folder, noisy, clean = os.path.dirname(arg), os.path.basename(arg), ''
        elif os.path.isfile(os.path.join(arg, 'Noisy.obj')): folder, noisy, clean = arg, 'Noisy.obj', 'Original.obj'
        else: folder, noisy, clean = arg, 'noisy.off', 'original.off'
        Y, F = read_mesh(os.path.join(folder, noisy))
        h = mean_edge(Y, F)
        r = ring_offsets(Y, F)
        p, s0, s1, w = fit_mixture(r)
        # a hit moves its ring's offsets the other way by a share of it: of a hit and its ring, the hit is the
        # vertex whose offset is the largest
        flagged = (w > 0.5) & (np.abs(r) >= ring_maximum(np.abs(r), F))
        row = [os.path.basename(os.path.normpath(arg)), '%.3f' % p, '%.3f' % (s0 / h), '%.3f' % (s1 / h),
               '%.1f%%' % (100 * flagged.mean()), '-', '-', '-']
        if clean and 'mpulsive' in arg:   # hits by construction: a tenth moved by an edge (Twelve: its own)
            X, _ = read_mesh(os.path.join(folder, clean))
            hit = np.abs(np.sum((Y - X) * vertex_normals(X, F), axis=1)) > 0.5 * mean_edge(X, F)
            row[5] = '%.1f%%' % (100 * hit.mean())
            if hit.any(): row[6] = '%.2f' % (np.sum(flagged & hit) / hit.sum())
            if flagged.any(): row[7] = '%.2f' % (np.sum(flagged & hit) / flagged.sum())
        print('| ' + ' | '.join(row) + ' |')


if __name__ == '__main__':
    main()
