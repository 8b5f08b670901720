#!/usr/bin/env python3
"""The noise the standard denoising pairs carry (issue 53, point 1), measured against their clean meshes:
how much of Noisy - Original lies along the original vertex normals and how much in the tangent planes, how
its size varies over the surface, how heavy its tails are (impulses), and whether the coordinates sit on a
lattice (quantisation). Ground truth for the estimators that read the noise from the noisy mesh alone.

    python3 bench/noise_model_pairs.py DIR...

Each DIR holds a pair with the same vertices and faces: Noisy.obj and Original.obj (../shared/data/denoising),
or noisy.off and original.off (what `write_cases` writes, with the quantised, impulsive and depth-noise cases).

Prints one Markdown row per pair."""
import os, sys
import numpy as np


def read_mesh(path):
    """Vertices and triangles of an OBJ or OFF file."""
    if path.endswith('.off'):
        words = [w for line in open(path) for w in line.split('#')[0].split()]
        nv, nf = int(words[1]), int(words[2])
        V = np.array(words[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
        F, k = [], 4 + 3 * nv
        for _ in range(nf):
            n = int(words[k]); F.append([int(w) for w in words[k + 1:k + 4]]); k += n + 1
        return V, np.array(F)
    V, F = [], []
    for line in open(path):
        t = line.split()
        if not t: continue
        if t[0] == 'v': V.append([float(x) for x in t[1:4]])
        elif t[0] == 'f': F.append([int(w.split('/')[0]) - 1 for w in t[1:4]])
    return np.array(V), np.array(F)


def vertex_normals(V, F):
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])   # twice the area, along the normal
    N = np.zeros_like(V)
    for k in range(3): np.add.at(N, F[:, k], n)
    return N / np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-300)


def mean_edge(V, F):
    E = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    return np.linalg.norm(V[E[:, 0]] - V[E[:, 1]], axis=1).mean()


def regional_sigma(V, d, parts=4):
    """The normal part's rms over a parts^3 grid of boxes (those holding at least 50 vertices): its spread."""
    lo, hi = V.min(0), V.max(0)
    cell = np.minimum(((V - lo) / np.maximum(hi - lo, 1e-300) * parts).astype(int), parts - 1)
    key = cell[:, 0] * parts * parts + cell[:, 1] * parts + cell[:, 2]
    s = [np.sqrt(np.mean(d[key == k] ** 2)) for k in np.unique(key) if np.sum(key == k) >= 50]
    return (min(s), max(s)) if s else (np.nan, np.nan)   # (a mesh too small to tell)


def lattice_step(V):
    """The smallest step between distinct coordinate values, relative to the bounding box (a lattice: large)."""
    steps = [np.diff(np.unique(V[:, c])) for c in range(3)]
    span = (V.max(0) - V.min(0)).max()
    return min(s[s > 0].min() for s in steps if len(s)) / span


def main():
    print('| pair | h | rms normal / h | tangential / normal | regional sigma max/min (shuffled) | kurtosis '
          '| |n| > 4 sigma_robust | lattice step / size |')
    print('|---|---|---|---|---|---|---|---|')
    for folder in sys.argv[1:]:
        obj = os.path.isfile(os.path.join(folder, 'Noisy.obj'))
        names = ('Original.obj', 'Noisy.obj') if obj else ('original.off', 'noisy.off')
        X, F = read_mesh(os.path.join(folder, names[0]))
        Y, G = read_mesh(os.path.join(folder, names[1]))
        assert X.shape == Y.shape and np.array_equal(F, G), folder
        N = vertex_normals(X, F)
        D = Y - X
        dn = np.sum(D * N, axis=1)
        dt = np.linalg.norm(D - dn[:, None] * N, axis=1)
        h = mean_edge(X, F)
        rms_n, rms_t = np.sqrt(np.mean(dn ** 2)), np.sqrt(np.mean(dt ** 2))
        robust = 1.4826 * np.median(np.abs(dn - np.median(dn)))
        kurt = np.mean((dn - dn.mean()) ** 4) / np.mean((dn - dn.mean()) ** 2) ** 2
        lo, hi = regional_sigma(X, dn)
        # the same spread for noise of one size everywhere: the normal parts dealt to the vertices at random
        slo, shi = regional_sigma(X, np.random.default_rng(1).permutation(dn))
        print('| %s | %.4g | %.3f | %.3f | %.2f (%.2f) | %.1f | %.2f%% | %.2g |' % (
            os.path.basename(os.path.normpath(folder)), h, rms_n / h, rms_t / rms_n, hi / lo, shi / slo, kurt,
            100 * np.mean(np.abs(dn) > 4 * robust), lattice_step(Y)))


if __name__ == '__main__':
    main()
