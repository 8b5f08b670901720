#!/usr/bin/env python3
"""The noise read through stencils of one, two and three rings (issue 53: is a raw scan's noise correlated over a
few rings, which the noise estimate's one-ring second differences would read as shape?).

Per mesh and ring count r: the heights of the vertices over the mean of their r-disk (along the vertex normals),
minus the same mean of the heights; their robust deviation divided by that of unit noise drawn on the mesh's own
connectivity through the same differences, in units of the mean edge h. Independent noise over a smooth shape
reads about the same through every stencil, growing only with the shape; noise correlated over a few rings reads
more through the wider stencils. With --mixtures, the mesh (a clean one) is also read under 0.09 h of independent
noise along its normals, alone and with 0.1 h of unit noise averaged 2, 4 and 8 times with its ring's mean.

    python3 bench/noise_stencils.py [--mixtures] MESH..."""
import os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from noise_model_pairs import read_mesh, vertex_normals, mean_edge   # noqa: E402
from noise_model_from_mesh import ring_mean   # noqa: E402


def disks(F, n, radius):
    """Per vertex, the vertices within `radius` edges of it, itself left out."""
    nb = [set() for _ in range(n)]
    for f in F:
        for x in range(3): nb[f[x]].update((f[(x + 1) % 3], f[(x + 2) % 3]))
    out = []
    for i in range(n):
        seen, front = {i}, {i}
        for _ in range(radius):
            front = set().union(*(nb[j] for j in front)) - seen
            seen |= front
        out.append(np.array(sorted(seen - {i}), dtype=int))
    return out


def mean_over(v, rows):
    return np.array([v[r].mean(axis=0) if len(r) else 0 * v[i] for i, r in enumerate(rows)])


def robust(x):
    return 1.4826 * np.median(np.abs(x - np.median(x)))


def readings(Y, F, stencils, unit):
    N, h, out = vertex_normals(Y, F), mean_edge(Y, F), []
    for rows in stencils:
        height = np.sum((Y - mean_over(Y, rows)) * N, axis=1)
        null = unit - mean_over(unit, rows)
        out.append(robust(height - mean_over(height, rows)) / robust(null - mean_over(null, rows)) / h)
    return ' / '.join('%.3f' % x for x in out)


def averaged(u, F, times):
    for _ in range(times): u = 0.5 * u + 0.5 * ring_mean(u, F)
    return u / np.sqrt(np.mean(u ** 2))


def main():
    args = sys.argv[1:]
    mixtures = args[:1] == ['--mixtures']
    if mixtures: args = args[1:]
    rng = np.random.default_rng(0)
    print('| mesh | noise read through 1 / 2 / 3 rings (h) |')
    print('|---|---|')
    for path in args:
        Y, F = read_mesh(path)
        n = len(Y)
        stencils = [disks(F, n, r) for r in (1, 2, 3)]
        unit = rng.standard_normal(n)
        print('| %s | %s |' % (path, readings(Y, F, stencils, unit)))
        if not mixtures: continue
        N, h = vertex_normals(Y, F), mean_edge(Y, F)
        for times in (0, 2, 4, 8):
            e = 0.09 * rng.standard_normal(n) + (0.1 * averaged(rng.standard_normal(n), F, times) if times else 0)
            label = '+ 0.09 h independent' + (' + 0.1 h averaged %d times' % times if times else '')
            print('| %s | %s |' % (label, readings(Y + (e * h)[:, None] * N, F, stencils, unit)))


if __name__ == '__main__':
    main()
