#!/usr/bin/env python3
"""The test cli_input_meshes of anisotropic_fairing: meshes as users have them (Python 3, standard library only).

    input_meshes_test.py --tool BIN --data DIR --work DIR

- Non-manifold vertices and edges are faired without asking. Two noisy spheres touching at one vertex
  (a bow-tie) or along one edge (an edge of four faces), in ASCII and binary PLY, OFF and OBJ: the run
  succeeds with a warning and the report's input_changes; the output has the input's vertices in their
  order and number, the input's faces, and every vertex property that is not faired unchanged. Against
  an independent run: the same spheres with the shared vertex split by hand (a manifold input) are
  faired the same, and the shared vertex is written at the mean of its two copies.
- The raw scan angel.obj (the denoising benchmark's, one bow-tie: tests/data) is faired as it is.
- Polygon meshes (quads, pentagons) are triangulated: triangles out, vertex properties kept, each
  triangle with its polygon's face properties.
- --repair keeps the vertex properties of the vertices it keeps (the copy of a split vertex has its
  original's).
- STL output: binary (84 + 50 bytes per triangle), and ASCII with --ascii, the full doubles.
"""
import argparse
import json
import math
import os
import random
import shutil
import struct
import subprocess
import sys

from checks import check, failures


# ------------------------------------------------------------------------------------------------
# Meshes
# ------------------------------------------------------------------------------------------------
def icosphere(level):
    t = (1 + 5 ** 0.5) / 2
    V = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    F = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    for _ in range(level):
        middle, G = {}, []
        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(V)
                V.append([(V[a][k] + V[b][k]) / 2 for k in range(3)])
            return middle[key]
        for a, b, c in F:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            G += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        F = G
    return [[x / math.sqrt(sum(y * y for y in p)) for x in p] for p in V], F


def noisy(V, rng, sigma):
    return [[x * (1 + rng.gauss(0, sigma)) for x in p] for p in V]


def two_spheres(shared, seed=1):
    """Sphere A and sphere B touching at `shared` (1: a vertex, 2: an edge) of A's vertices, B's own
    copies of them dropped. Returns (V, F, hand_split_V, hand_split_F, shared_vertices): the second pair
    is the manifold mesh with B's shared vertices appended as vertices of their own."""
    rng = random.Random(seed)
    A, FA = icosphere(2)
    B, FB = icosphere(2)
    A, B = noisy(A, rng, 0.01), noisy(B, rng, 0.01)
    # A's vertex 0 (and its neighbour) on top of B's (B shifted by the distance between them)
    a = [0, next(b for f in FA if 0 in f for b in f if b != 0)][:shared]
    b = [3]   # B's vertex 3 is antipodal to A's vertex 0: B outside A, the same tangent plane there
    shift = [A[a[0]][k] - B[b[0]][k] for k in range(3)]
    B = [[p[k] + shift[k] for k in range(3)] for p in B]
    if shared == 2:   # and B's neighbour of 3 nearest to A's neighbour of 0 on it
        b.append(min({x for f in FB if 3 in f for x in f if x != 3}, key=lambda x: math.dist(B[x], A[a[1]])))
    for i, j in zip(a, b):
        B[j] = list(A[i])
    keep = [j for j in range(len(B)) if j not in b]
    index = {j: len(A) + n for n, j in enumerate(keep)}
    for i, j in zip(a, b):
        index[j] = i
    V = A + [B[j] for j in keep]
    F = FA + [[index[j] for j in f] for f in FB]
    # by hand: B's shared vertices as vertices of their own, after the others
    hand = {j: len(V) + n for n, j in enumerate(b)}
    Vh = V + [list(A[i]) for i in a]
    Fh = FA + [[hand.get(j, index[j]) for j in f] for f in FB]
    return V, F, Vh, Fh, a


def columns_for(V):
    """vertex properties that are not faired: a float 'quality' and a colour"""
    return {'quality': [float(i) * 0.25 for i in range(len(V))],
            'red': [i % 256 for i in range(len(V))], 'green': [(7 * i) % 256 for i in range(len(V))],
            'blue': [(13 * i) % 256 for i in range(len(V))]}


# ------------------------------------------------------------------------------------------------
# Files
# ------------------------------------------------------------------------------------------------
PLY_TYPES = {'char': 'b', 'uchar': 'B', 'int8': 'b', 'uint8': 'B', 'short': 'h', 'ushort': 'H',
             'int16': 'h', 'uint16': 'H', 'int': 'i', 'uint': 'I', 'int32': 'i', 'uint32': 'I',
             'float': 'f', 'float32': 'f', 'double': 'd', 'float64': 'd'}


def write_ply(path, V, F, columns, binary=False, face_columns=None):
    face_columns = face_columns or {}
    head = ['ply', 'format %s 1.0' % ('binary_little_endian' if binary else 'ascii'), 'element vertex %d' % len(V),
            'property double x', 'property double y', 'property double z']
    head += ['property %s %s' % ('float' if n == 'quality' else 'uchar', n) for n in columns]
    head += ['element face %d' % len(F), 'property list uchar int vertex_indices']
    head += ['property int %s' % n for n in face_columns] + ['end_header']
    with open(path, 'wb') as f:
        f.write(('\n'.join(head) + '\n').encode())
        for i, p in enumerate(V):
            if binary:
                props = b''.join(struct.pack('<f' if n == 'quality' else '<B', c[i]) for n, c in columns.items())
                f.write(struct.pack('<3d', *p) + props)
            else:
                props = ''.join(' %s' % c[i] for c in columns.values())
                f.write((' '.join(repr(x) for x in p) + props + '\n').encode())
        for k, t in enumerate(F):
            if binary:
                props = b''.join(struct.pack('<i', c[k]) for c in face_columns.values())
                f.write(struct.pack('<B%di' % len(t), len(t), *t) + props)
            else:
                props = ''.join(' %d' % c[k] for c in face_columns.values())
                f.write(('%d %s%s\n' % (len(t), ' '.join(map(str, t)), props)).encode())


def read_ply(path):
    """{element: (property names, rows)}; a list property is one tuple"""
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    elements, fmt = [], None
    for line in data[:end].decode().splitlines():
        w = line.split()
        if w[0] == 'format':
            fmt = w[1]
        elif w[0] == 'element':
            elements.append((w[1], int(w[2]), []))
        elif w[0] == 'property':
            elements[-1][2].append((w[-1], w[1:-1]))
    out, body = {}, data[end:]
    if fmt == 'ascii':
        words = iter(body.decode().split())
        def value(t):
            w = next(words)
            return float(w) if t in ('float', 'double', 'float32', 'float64') else int(w)
    else:
        at = [0]
        def value(t):
            v = struct.unpack_from('<' + PLY_TYPES[t], body, at[0])[0]
            at[0] += struct.calcsize(PLY_TYPES[t])
            return v
    for name, count, props in elements:
        rows = []
        for _ in range(count):
            rows.append([tuple(value(t[2]) for _ in range(value(t[1]))) if t[0] == 'list' else value(t[0])
                         for _, t in props])
        out[name] = ([p for p, _ in props], rows)
    return out


def write_off(path, V, F, colours=None):
    with open(path, 'w') as f:
        f.write('%s\n%d %d 0\n' % ('COFF' if colours else 'OFF', len(V), len(F)))
        for i, p in enumerate(V):
            f.write(' '.join(repr(x) for x in p) + (' %d %d %d' % colours[i] if colours else '') + '\n')
        for t in F:
            f.write('%d %s\n' % (len(t), ' '.join(map(str, t))))


def read_off(path):
    """(keyword, vertex rows of words, faces, face rows' words after the indices)"""
    lines = [line.split('#')[0].split() for line in open(path)]
    lines = [w for w in lines if w]
    keyword = lines[0][0]
    counts = lines[0][1:] if len(lines[0]) > 1 else lines[1]
    first = 1 if len(lines[0]) > 1 else 2
    nv, nf = int(counts[0]), int(counts[1])
    rows = lines[first:first + nv]
    faces, rest = [], []
    for w in lines[first + nv:first + nv + nf]:
        k = int(w[0])
        faces.append(tuple(int(x) for x in w[1:1 + k]))
        rest.append(w[1 + k:])
    return keyword, rows, faces, rest


def write_obj(path, V, F):
    with open(path, 'w') as f:
        for p in V:
            f.write('v %r %r %r\n' % tuple(p))
        for t in F:
            f.write('f %s\n' % ' '.join(str(i + 1) for i in t))


def read_obj(path):
    V, F = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == 'v':
            V.append([float(x) for x in w[1:4]])
        elif w and w[0] == 'f':
            F.append(tuple(int(x.split('/')[0]) - 1 for x in w[1:]))
    return V, F


def run(tool, args, work):
    p = subprocess.run([tool] + args + ['--quiet'], cwd=work, capture_output=True, text=True)
    return p.returncode, p.stderr


def report(work, name):
    return json.load(open(os.path.join(work, name)))


def points_of(table):
    names, rows = table
    x, y, z = names.index('x'), names.index('y'), names.index('z')
    return [[r[x], r[y], r[z]] for r in rows]


def column(table, name):
    names, rows = table
    return [r[names.index(name)] for r in rows]


# ------------------------------------------------------------------------------------------------
# Tests
# ------------------------------------------------------------------------------------------------
def non_manifold(tool, work):
    for shared, what in ((1, 'bow-tie vertex'), (2, 'edge of four faces')):
        V, F, Vh, Fh, a = two_spheres(shared)
        cols = columns_for(V)
        size = max(max(p[k] for p in V) - min(p[k] for p in V) for k in range(3))
        # the same spheres split by hand: a manifold input, faired by the same default run
        hand_cols = {n: c + [c[i] for i in a] for n, c in cols.items()}
        write_ply(os.path.join(work, 'hand.ply'), Vh, Fh, hand_cols)
        rc, err = run(tool, ['hand.ply', 'hand_out.ply', '--report', 'hand.json'], work)
        check(rc == 0 and 'non-manifold' not in err,
              '%s split by hand: a manifold mesh faired (%s)' % (what, err.strip()[-200:]))
        hand = points_of(read_ply(os.path.join(work, 'hand_out.ply'))['vertex'])
        for fmt in ('ply', 'binary.ply', 'off', 'obj'):
            name = 'nm%d.%s' % (shared, fmt)
            path = os.path.join(work, name)
            if fmt.endswith('ply'):
                write_ply(path, V, F, cols, binary=fmt.startswith('binary'))
            elif fmt == 'off':
                write_off(path, V, F, list(zip(cols['red'], cols['green'], cols['blue'])))
            else:
                write_obj(path, V, F)
            before = open(path, 'rb').read()
            out = 'out_' + name
            rc, err = run(tool, [name, out, '--report', name + '.json'], work)
            label = '%s (%s)' % (what, fmt)
            if not check(rc == 0, '%s: faired without asking (exit %d: %s)' % (label, rc, err.strip()[-300:])):
                continue
            check(open(path, 'rb').read() == before, '%s: the input is unchanged' % label)
            check('non-manifold' in err and 'split' in err and 'mean of its copies' in err,
                  '%s: a warning says what was done' % label)
            r = report(work, name + '.json')
            check(r['status'] == 'success' and r['split_vertices'] == shared and r['vertices'] == len(V) and
                  any('split' in c for c in r['input_changes']),
                  '%s: the report says it (split_vertices %s)' % (label, r['split_vertices']))
            if fmt.endswith('ply'):
                t = read_ply(os.path.join(work, out))
                P, faces = points_of(t['vertex']), [row[0] for row in t['face'][1]]
                check(column(t['vertex'], 'quality') == cols['quality'] and
                      column(t['vertex'], 'red') == cols['red'] and column(t['vertex'], 'blue') == cols['blue'],
                      '%s: every vertex property kept, in vertex order' % label)
            elif fmt == 'off':
                keyword, rows, faces, rest = read_off(os.path.join(work, out))
                P = [[float(x) for x in row[:3]] for row in rows]
                check('C' in keyword and [tuple(int(float(x)) for x in row[3:6]) for row in rows] ==
                      list(zip(cols['red'], cols['green'], cols['blue'])),
                      '%s: the colours kept, in vertex order' % label)
            else:
                P, faces = read_obj(os.path.join(work, out))
            check(len(P) == len(V), '%s: the input\'s %d vertices written (%d)' % (label, len(V), len(P)))
            check([tuple(f) for f in faces] == [tuple(f) for f in F],
                  '%s: the input\'s faces written, as they were' % label)
            check(all(math.isfinite(x) for p in P for x in p) and
                  max(math.dist(p, q) for p, q in zip(P, V)) > 1e-4 * size,
                  '%s: the surface was faired' % label)
            # the split run is the run split by hand: the shared vertices at the mean of their two copies
            if fmt == 'ply':
                worst = max(math.dist(P[i], hand[i]) for i in range(len(V)) if i not in a)
                check(worst < 1e-9 * size,
                      '%s: the other vertices as the hand-split run writes them (%.2g)' % (label, worst))
                for k, i in enumerate(a):
                    mean = [(hand[i][c] + hand[len(V) + k][c]) / 2 for c in range(3)]
                    check(math.dist(P[i], mean) < 1e-9 * size and math.dist(hand[i], hand[len(V) + k]) > 1e-6 * size,
                          '%s: vertex %d at the mean of its copies (%.2g off; the copies %.2g apart)' %
                          (label, i, math.dist(P[i], mean), math.dist(hand[i], hand[len(V) + k])))


def raw_scan(tool, work, data):
    shutil.copy(os.path.join(data, 'angel.obj'), work)
    V, F = read_obj(os.path.join(work, 'angel.obj'))
    rc, err = run(tool, ['angel.obj', 'angel_out.obj', '--report', 'angel.json'], work)
    if not check(rc == 0, 'raw scan angel.obj faired as it is (exit %d: %s)' % (rc, err.strip()[-300:])):
        return
    r = report(work, 'angel.json')
    P, G = read_obj(os.path.join(work, 'angel_out.obj'))
    check(r['status'] == 'success' and r['split_vertices'] > 0 and 'non-manifold' in err,
          'angel.obj: its non-manifold vertices split, said')
    check(len(P) == len(V) and G == F,
          'angel.obj: the scan\'s %d vertices and %d faces written as they were' % (len(V), len(F)))


def polygons(tool, work):
    # a cube of 4 x 4 quads a side, on the unit sphere, one quad pair merged into a hexagon per side
    rng = random.Random(3)
    n, index, V, Q = 4, {}, [], []
    def vertex(p):
        key = tuple(round(x, 9) for x in p)
        if key not in index:
            index[key] = len(V)
            length = math.sqrt(sum(x * x for x in p))
            V.append([x / length * (1 + rng.gauss(0, 0.01)) for x in p])
        return index[key]
    for axis in range(3):
        for sign in (-1, 1):
            for i in range(n):
                for j in range(n):
                    def point(u, v):
                        p = [0, 0, 0]
                        p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = sign, -1 + 2 * u / n, -1 + 2 * v / n
                        return vertex(p)
                    q = [point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)]
                    Q.append(q if sign > 0 else q[::-1])
    # two quads of each side made one hexagon: polygons of 4 and 6 corners
    P = []
    for s in range(6):
        side = Q[16 * s:16 * s + 16]
        a, b = side[0], side[1]   # (i, j) and (i + 1, j): they share an edge
        shared = set(a) & set(b)
        ring = a[:]
        k = next(k for k in range(4) if a[k] in shared and a[(k + 1) % 4] in shared)
        ring = a[:k + 1] + [x for x in b[b.index(a[k]) + 1:] + b[:b.index(a[k])] if x not in shared] + a[k + 1:]
        P += [ring] + side[2:]
    cols = columns_for(V)
    write_off(os.path.join(work, 'quads.off'), V, P, list(zip(cols['red'], cols['green'], cols['blue'])))
    labels = {'label': [10 * k for k in range(len(P))]}
    write_ply(os.path.join(work, 'quads.ply'), V, P, cols, binary=True, face_columns=labels)
    corners = sum(len(p) for p in P)
    triangles = corners - 2 * len(P)
    rc, err = run(tool, ['quads.off', 'quads_out.off', '--report', 'quads.json'], work)
    if check(rc == 0, 'a polygon mesh (%d quads and hexagons) faired (exit %d: %s)' % (len(P), rc, err.strip()[-300:])):
        keyword, rows, faces, rest = read_off(os.path.join(work, 'quads_out.off'))
        check(not any(rest), 'polygons: no face colours where the input had none')
        r = report(work, 'quads.json')
        check('triangulated' in err and r['triangulated_faces'] == len(P) and r['faces'] == triangles,
              'polygons: triangulated, said in a warning and the report (%s)' % r['triangulated_faces'])
        check(len(faces) == triangles and all(len(f) == 3 for f in faces),
              'polygons: written as %d triangles' % triangles)
        check(len(rows) == len(V) and [tuple(int(float(x)) for x in row[3:6]) for row in rows] ==
              list(zip(cols['red'], cols['green'], cols['blue'])), 'polygons: the vertices and their colours kept')
    rc, err = run(tool, ['quads.ply', 'quads_out.ply'], work)
    if check(rc == 0, 'a binary PLY of polygons with a face property faired (exit %d: %s)' % (rc, err.strip()[-300:])):
        t = read_ply(os.path.join(work, 'quads_out.ply'))
        faces, label = [row[0] for row in t['face'][1]], column(t['face'], 'label')
        expected = sorted(l for k, p in enumerate(P) for l in [labels['label'][k]] * (len(p) - 2))
        covers = all(set(f) <= set(P[label[k] // 10]) for k, f in enumerate(faces))
        check(sorted(label) == expected and covers,
              'polygons: each triangle has the face property of the polygon it was cut from')
        check(column(t['vertex'], 'quality') == cols['quality'], 'polygons: the vertex properties kept')


def repair(tool, work):
    V, F, _, _, a = two_spheres(1, seed=5)
    cols = columns_for(V)
    write_ply(os.path.join(work, 'repair.ply'), V, F, cols)
    rc, err = run(tool, ['repair.ply', 'repair_out.ply', '--repair', '--report', 'repair.json'], work)
    if not check(rc == 0, '--repair on a bow-tie (exit %d: %s)' % (rc, err.strip()[-300:])):
        return
    t = read_ply(os.path.join(work, 'repair_out.ply'))
    q = column(t['vertex'], 'quality')
    check(len(q) == len(V) + 1 and q[:len(V)] == cols['quality'] and q[len(V)] == cols['quality'][a[0]],
          '--repair: the vertex properties kept, the copy with its original\'s (%d vertices)' % len(q))
    check(any(c.startswith('--repair:') for c in report(work, 'repair.json')['input_changes']),
          '--repair: its changes in the report')


def stl(tool, work, data):
    shutil.copy(os.path.join(data, 'bumpy.off'), work)
    words = open(os.path.join(work, 'bumpy.off')).read().split()
    faces = int(words[2])
    rc, err = run(tool, ['bumpy.off', 'bumpy.stl', '--steps', '1', '--relative-time-step', '1e-3'], work)
    if check(rc == 0, 'STL output (exit %d: %s)' % (rc, err.strip()[-200:])):
        b = open(os.path.join(work, 'bumpy.stl'), 'rb').read()
        check(len(b) == 84 + 50 * faces and struct.unpack_from('<I', b, 80)[0] == faces,
              'STL: binary, %d triangles' % faces)
    rc, err = run(tool, ['bumpy.off', 'bumpy_text.stl', '--ascii', '--steps', '1', '--relative-time-step', '1e-3'],
                  work)
    if check(rc == 0, 'ASCII STL output (exit %d: %s)' % (rc, err.strip()[-200:])):
        text = open(os.path.join(work, 'bumpy_text.stl')).read()
        vertices = [line.split()[1:] for line in text.splitlines() if line.strip().startswith('vertex')]
        check(text.startswith('solid') and len(vertices) == 3 * faces, 'STL --ascii: text, %d triangles' % faces)
        digits = max(len(x.lstrip('-').replace('.', '').split('e')[0].lstrip('0')) for v in vertices for x in v)
        check(digits > 9, 'STL --ascii: the full doubles (up to %d significant digits)' % digits)
        binary = open(os.path.join(work, 'bumpy.stl'), 'rb').read()
        first = struct.unpack_from('<3f', binary, 84 + 12)
        check(all(abs(float(x) - y) <= 1e-6 * max(1, abs(y)) for x, y in zip(vertices[0], first)),
              'STL: binary and text hold the same triangles')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--tool', required=True)
    ap.add_argument('--data', required=True, help='tools/anisotropic_fairing/tests/data')
    ap.add_argument('--example-data', required=True)
    ap.add_argument('--work', required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    non_manifold(a.tool, a.work)
    raw_scan(a.tool, a.work, a.data)
    polygons(a.tool, a.work)
    repair(a.tool, a.work)
    stl(a.tool, a.work, a.example_data)
    print('%d failed' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
