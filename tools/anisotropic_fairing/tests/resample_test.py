#!/usr/bin/env python3
"""The tests cli_resample and cli_snapshot of anisotropic_fairing (Python 3, standard library only).

    resample_test.py --tool BIN --example-data DIR --work DIR [--snapshot]

--resample K:
  - an attribute that is an affine function of the input positions, not faired (0 steps), stays that
    affine function of the positions at every new vertex: positions and attributes come from the same
    Loop basis (partition of unity, linear precision), through the whole program;
  - the input's vertices come first, line for line as the run without --resample writes them; the
    counts are V + E(N-1) + F(N-1)(N-2)/2 vertices and N^2 F faces (N = 2^K); the properties are the input's;
  - a new face has the properties (label, colour) of the input face it lies in;
  - usage errors, and a size beyond the program's budget fails before the fairing, with no output.
--snapshot: a PNG is written next to the output; a renderer that fails gives one line with its message,
  status snapshot_error and no output.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

from checks import check, failures


def run(tool, args, work, env=None):
    p = subprocess.run([tool] + args, cwd=work, capture_output=True, text=True, env=env)
    return p.returncode, p.stderr


def read_obj(path):
    points, faces = [], []
    for line in open(path):
        t = line.split()
        if t and t[0] == 'v':
            points.append([float(x) for x in t[1:4]])
        elif t and t[0] == 'f':
            faces.append([int(x.split('/')[0]) - 1 for x in t[1:4]])
    return points, faces


def read_ply(path):
    """(header lines, vertex rows as lists of strings, face rows, vertex property names)"""
    text = open(path).read()
    header, body = text.split('end_header\n', 1)
    header = header.splitlines()
    nv = int(re.search(r'element vertex (\d+)', '\n'.join(header)).group(1))
    names, in_vertex = [], False
    for h in header:
        if h.startswith('element'):
            in_vertex = h.startswith('element vertex')
        elif h.startswith('property') and in_vertex:
            names.append(h.split()[-1])
    rows = body.splitlines()
    return header, rows[:nv], rows[nv:], names


def write_ply(path, points, faces, columns):
    """ascii PLY with double vertex properties `columns` (name -> list)"""
    with open(path, 'w') as f:
        f.write('ply\nformat ascii 1.0\nelement vertex %d\n'
                'property double x\nproperty double y\nproperty double z\n' % len(points))
        for name in columns:
            f.write('property double %s\n' % name)
        f.write('element face %d\nproperty list uchar int vertex_indices\nend_header\n' % len(faces))
        for i, p in enumerate(points):
            f.write(' '.join(repr(v) for v in p + [columns[n][i] for n in columns]) + '\n')
        for t in faces:
            f.write('3 %d %d %d\n' % tuple(t))


def affine(p):
    return 2.0 * p[0] - 3.0 * p[1] + 0.5 * p[2] + 7.0


def test_resample(tool, data, work):
    points, faces = read_obj(os.path.join(data, 'fandisk_noisy.obj'))
    write_ply(os.path.join(work, 'fandisk_q.ply'), points, faces, {'q': [affine(p) for p in points]})
    V, F = len(points), len(faces)
    E = 3 * F // 2   # closed

    # an unfaired affine attribute is the same affine function of the positions at every new vertex
    code, err = run(tool, ['fandisk_q.ply', 'affine.ply', '--attributes', 'q', '--relative-time-step', '1e-3',
                           '--steps', '0', '--stop', 'off', '--resample', '1', '--quiet'], work)
    if check(code == 0, '--resample 1 with 0 steps runs (%s)' % err.strip()):
        _, rows, _, names = read_ply(os.path.join(work, 'affine.ply'))
        qi = names.index('q')
        worst = max(abs(float(r.split()[qi]) - affine([float(x) for x in r.split()[:3]])) for r in rows)
        check(worst <= 1e-9, 'an affine attribute stays the same affine function of the resampled positions '
              '(largest error %.3g)' % worst)

    # a run with and without --resample 2 (a few steps: the sanitizer builds run this too)
    steps = ['--relative-time-step', '1e-3', '--steps', '2', '--stop', 'off', '--quiet']
    code0, err0 = run(tool, ['fandisk_q.ply', 'plain.ply', '--attributes', 'q'] + steps, work)
    code2, err2 = run(tool, ['fandisk_q.ply', 'fine.ply', '--attributes', 'q',
                             '--resample', '2', '--report', 'fine.json'] + steps, work)
    if check(code0 == 0 and code2 == 0, 'a run with and without --resample 2 (%s %s)' % (err0.strip(), err2.strip())):
        h0, rows0, faces0, names0 = read_ply(os.path.join(work, 'plain.ply'))
        h2, rows2, faces2, names2 = read_ply(os.path.join(work, 'fine.ply'))
        N = 4
        check(len(rows2) == V + E * (N - 1) + F * (N - 1) * (N - 2) // 2 and len(faces2) == N * N * F,
              '--resample 2: %d vertices and %d faces (V + 3E + 3F, 16F)' % (len(rows2), len(faces2)))
        check(rows2[:V] == rows0, 'the input\'s vertices come first, line for line as without --resample')
        check(names2 == names0 == ['x', 'y', 'z', 'q'], 'the properties are the input\'s (%s)' % names2)
        report = json.load(open(os.path.join(work, 'fine.json')))
        check(report['resample'] == 2 and report['resampled_vertices'] == len(rows2) and
              report['resampled_faces'] == len(faces2),
              'the report gives resample, resampled_vertices, resampled_faces')

    # face properties: a new face has those of the input face it lies in
    with open(os.path.join(work, 'octahedron.ply'), 'w') as f:
        f.write('ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\nproperty double z\n'
                'element face 8\nproperty list uchar int vertex_indices\nproperty int label\n'
                'property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n'
                '1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n')
        tris = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
        for i, t in enumerate(tris):
            f.write('3 %d %d %d %d %d %d 7\n' % (t + (100 + i, 10 * i, 255 - 10 * i)))
    code, err = run(tool, ['octahedron.ply', 'octahedron_fine.ply', '--resample', '1', '--relative-time-step', '1e-3',
                           '--steps', '1', '--quiet'], work)
    if check(code == 0, '--resample 1 on a PLY with face properties (%s)' % err.strip()):
        header, _, face_rows, _ = read_ply(os.path.join(work, 'octahedron_fine.ply'))
        expected = ['3 %s %d %d %d 7' % ('%d %d %d', 100 + k // 4, 10 * (k // 4), 255 - 10 * (k // 4))
                    for k in range(32)]
        got = [r.split()[:1] + r.split()[4:] for r in face_rows]
        check(len(face_rows) == 32 and
              all(got[k] == expected[k].replace('%d %d %d ', '').split() for k in range(32)),
              'each new face has the label and colour of its input face (%s ...)' % face_rows[:2])
        check([h for h in header if h.startswith('property')][-4:] ==
              ['property int label', 'property uchar red', 'property uchar green', 'property uchar blue'],
              'the face properties are the input\'s')

    # usage errors, and the size budget before the fairing
    for args, what in ((['--resample', '11'], 'above 10'),
                       (['--resample', '1', '--element', 'linear'], 'with --element linear'),
                       (['--resample', '1', '--output', 'control'], 'with --output control')):
        code, err = run(tool, ['octahedron.ply', 'bad.ply'] + args, work)
        check(code == 2 and err.startswith('anisotropic_fairing: ') and
              not os.path.exists(os.path.join(work, 'bad.ply')),
              '--resample %s: usage error, no output (%s)' % (what, err.strip()))
    code, err = run(tool, ['fandisk_q.ply', 'huge.ply', '--resample', '10', '--report', 'huge.json'], work)
    check(code == 1 and 'would write' in err and not os.path.exists(os.path.join(work, 'huge.ply')) and
          json.load(open(os.path.join(work, 'huge.json')))['status'] == 'invalid_parameter' and
          json.load(open(os.path.join(work, 'huge.json')))['steps'] == [],
          '--resample 10 on 12946 faces: refused before the fairing (%s)' % err.strip())


def test_snapshot(tool, data, work):
    src = os.path.join(data, 'fandisk_noisy.obj')
    steps = ['--relative-time-step', '1e-3', '--steps', '2', '--stop', 'off', '--quiet']
    code, err = run(tool, [src, 'shot.off', '--snapshot', 'shot.png', '--report', 'shot.json'] + steps, work)
    if check(code == 0, '--snapshot renders (%s)' % err.strip()):
        head = open(os.path.join(work, 'shot.png'), 'rb').read(24)
        width, height = int.from_bytes(head[16:20], 'big'), int.from_bytes(head[20:24], 'big')
        check(head[:8] == b'\x89PNG\r\n\x1a\n' and width > height > 100,
              'a PNG, wider than high (%dx%d)' % (width, height))
        check(json.load(open(os.path.join(work, 'shot.json')))['snapshot'] == 'shot.png',
              'the report names the snapshot')
    # a renderer that fails: one line with its message, no output, no picture
    failing = os.path.join(work, 'failing_renderer.py')
    with open(failing, 'w') as f:
        f.write('import sys\nsys.stderr.write("render_mesh.py: no VTK here\\n")\nsys.exit(1)\n')
    env = dict(os.environ, AF_RENDER_SCRIPT=failing)
    code, err = run(tool, [src, 'shot2.off', '--snapshot', 'shot2.png', '--report', 'shot2.json'] + steps, work, env)
    check(code == 1 and err.count('\n') == 1 and 'no VTK here' in err and
          not os.path.exists(os.path.join(work, 'shot2.off')) and
          not os.path.exists(os.path.join(work, 'shot2.png')) and
          json.load(open(os.path.join(work, 'shot2.json')))['status'] == 'snapshot_error',
          'a failing renderer: one line with its message, status snapshot_error, no output (%s)' % err.strip())
    code, err = run(tool, [src, 'shot3.off', '--snapshot', 'shot3.jpg'], work)
    check(code == 2, '--snapshot needs a .png (%s)' % err.strip())
    left = [f for f in os.listdir(work) if '.tmp' in f]
    check(not left, 'no temporary file left (%s)' % left)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--tool', required=True)
    ap.add_argument('--example-data', required=True)
    ap.add_argument('--work', required=True)
    ap.add_argument('--snapshot', action='store_true')
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    if a.snapshot:
        test_snapshot(a.tool, a.example_data, a.work)
    else:
        test_resample(a.tool, a.example_data, a.work)
    if failures:
        sys.exit('%d check(s) failed' % len(failures))


if __name__ == '__main__':
    main()
