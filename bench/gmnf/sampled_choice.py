#!/usr/bin/env python3
"""Would the default run choose the same flow on a sample of the mesh? For each case of CASES (CASE/noisy.off),
cuts patches of PATCH faces grown from random seed faces until a fraction of the faces (at least MIN faces) is
taken, with a one-face gap between patches and pinched vertices removed, writes the sample as OFF, runs the
program's default run on it (its borders held as vertices), and prints the flow it keeps next to the one the
whole mesh's report (WHOLE/CASE.json, from a run of the program on noisy.off) names.

    python3 bench/gmnf/sampled_choice.py --tool build/bin/anisotropic_fairing --cases DIR --whole DIR --work DIR
           [--patch 1500] [--min-faces 8000] [--fraction 0.1] [--seed 1]

Python 3 and numpy (python3-numpy).
"""
import argparse, json, os, subprocess, sys, time
from collections import defaultdict, deque

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import score  # noqa: E402


def face_adjacency(t):
    edge_faces = defaultdict(list)
    for f, tri in enumerate(t):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            edge_faces[(min(a, b), max(a, b))].append(f)
    adj = [[] for _ in range(len(t))]
    for fs in edge_faces.values():
        if len(fs) == 2:
            adj[fs[0]].append(fs[1])
            adj[fs[1]].append(fs[0])
    vert_faces = defaultdict(list)
    for f, tri in enumerate(t):
        for a in tri:
            vert_faces[int(a)].append(f)
    return adj, vert_faces


def grow_patches(t, adj, vert_faces, target, patch, rng):
    state = np.zeros(len(t), np.int8)   # 0 free, 1 taken, 2 touches a taken patch
    taken = 0
    for s in rng.permutation(len(t)):
        if taken >= target:
            break
        if state[s] != 0:
            continue
        faces, queue, seen = [], deque([s]), {s}
        while queue and len(faces) < patch:
            f = queue.popleft()
            if state[f] != 0:
                continue
            faces.append(f)
            for g in adj[f]:
                if g not in seen:
                    seen.add(g)
                    queue.append(g)
        for f in faces:
            state[f] = 1
        for f in faces:
            for a in t[f]:
                for g in vert_faces[int(a)]:
                    if state[g] == 0:
                        state[g] = 2
        taken += len(faces)
    return set(np.where(state == 1)[0].tolist())


def remove_pinches(t, adj, vert_faces, S):
    """drops the smaller fans at a vertex whose selected faces form more than one fan, until none does"""
    changed = True
    while changed:
        changed = False
        for a in set(t[list(S)].ravel().tolist()):
            fs = [f for f in vert_faces[a] if f in S]
            parent = {f: f for f in fs}

            def find(x):
                while parent[x] != x:
                    parent[x] = parent[parent[x]]
                    x = parent[x]
                return x
            for f in fs:
                for g in adj[f]:
                    if g in parent and a in t[g]:
                        parent[find(f)] = find(g)
            groups = defaultdict(list)
            for f in fs:
                groups[find(f)].append(f)
            if len(groups) > 1:
                for group in sorted(groups.values(), key=len)[:-1]:
                    S.difference_update(group)
                changed = True
    return S


def write_sample(v, t, S, path):
    sel = np.array(sorted(S))
    vs = np.unique(t[sel].ravel())
    remap = -np.ones(len(v), np.int64)
    remap[vs] = np.arange(len(vs))
    with open(path, 'w') as o:
        o.write('OFF\n%d %d 0\n' % (len(vs), len(sel)))
        for p in v[vs]:
            o.write('%.17g %.17g %.17g\n' % tuple(p))
        for f in sel:
            o.write('3 %d %d %d\n' % tuple(remap[t[f]]))
    return len(sel)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--tool', required=True)
    ap.add_argument('--cases', required=True)
    ap.add_argument('--whole', required=True, help='reports of the whole meshes: WHOLE/CASE.json')
    ap.add_argument('--work', required=True)
    ap.add_argument('--patch', type=int, default=1500)
    ap.add_argument('--min-faces', type=int, default=8000)
    ap.add_argument('--fraction', type=float, default=0.1)
    ap.add_argument('--seed', type=int, default=1)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    differ = 0
    cases = sorted(os.listdir(a.cases))
    for case in cases:
        v, t = score.read_mesh(os.path.join(a.cases, case, 'noisy.off'))
        adj, vert_faces = face_adjacency(t)
        target = int(min(1.0, max(a.min_faces / len(t), a.fraction)) * len(t))
        S = remove_pinches(t, adj, vert_faces, grow_patches(t, adj, vert_faces, target, a.patch, np.random.default_rng(a.seed)))
        sample = os.path.join(a.work, case + '.off')
        faces = write_sample(v, t, S, sample)
        report = os.path.join(a.work, case + '.json')
        start = time.perf_counter()
        subprocess.run([a.tool, sample, os.path.join(a.work, case + '_out.off'), '--quiet', '--boundary', 'vertices', '--report', report],
                       capture_output=True)
        seconds = time.perf_counter() - start
        kept = json.load(open(report)).get('tensor')
        whole = json.load(open(os.path.join(a.whole, case + '.json'))).get('tensor')
        differ += kept != whole
        print('%-34s %6d of %6d faces  whole: %-11s sample: %-11s %5.2f s%s' % (case, faces, len(t), whole, kept, seconds,
                                                                            '' if kept == whole else '  DIFFERS'))
    print('%d of %d choices differ' % (differ, len(cases)))


if __name__ == '__main__':
    main()
