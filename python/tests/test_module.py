"""Tests of the Python package anisotropic_fairing (pytest; run by CTest as python_module, and as
python_package against the package pip installed).

The environment gives the package (PYTHONPATH, or none: the installed one), the command-line program
(AF_TOOL) and the data (AF_DATA: examples/Anisotropic_fairing/data); meshes are read and written by
meshio. The module must give the program's results (to 1e-12) and the program's report keys; bad input
raises, never crashes; the GIL is released during a run; a run shows its progress on stderr (through
tqdm: Debian python3-tqdm, and without it) unless quiet, and Ctrl-C ends it.
"""
import io
import json
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time

import meshio
import numpy as np
import pytest

import anisotropic_fairing as af

TOOL = os.environ.get('AF_TOOL', '')
DATA = os.environ.get('AF_DATA', '')


def read_mesh(path):
    """V (N x 3 float64), F (M x 3 int64) of a triangle mesh file, read by meshio"""
    m = meshio.read(path)
    return m.points, m.get_cells_type('triangle')


def write_ply(path, V, F, q):
    """a binary PLY (every double exact) with the vertex property q"""
    meshio.Mesh(V, [('triangle', F.astype(np.int32))], point_data={'q': q}).write(path, binary=True)


def read_ply_xyzq(path):
    m = meshio.read(path)
    return m.points, m.point_data['q']


def run_tool(args, cwd):
    p = subprocess.run([TOOL] + args + ['--quiet'], cwd=cwd, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return p


@pytest.fixture(scope='module')
def fandisk():
    return read_mesh(os.path.join(DATA, 'fandisk_noisy.obj'))


def grid(n=8, z=None):
    """a bordered (n+1) x (n+1) grid in the plane z = 0 (or z(x, y)), two triangles per square"""
    V = np.array([[i / n, j / n, 0.0] for j in range(n + 1) for i in range(n + 1)])
    if z is not None:
        V[:, 2] = z(V[:, 0], V[:, 1])
    F = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i, (j + 1) * (n + 1) + i + 1
            F += [[a, b, d], [a, d, c]]
    return V, np.array(F)


def test_default_run_equals_the_program(fandisk, tmp_path):
    V, F = fandisk
    run_tool([os.path.join(DATA, 'fandisk_noisy.obj'), 'out.off', '--report', 'out.json'], tmp_path)
    expected, _ = read_mesh(tmp_path / 'out.off')
    program_report = json.load(open(tmp_path / 'out.json'))
    V0, F0 = V.copy(), F.copy()
    V2, attributes, report = af.fair(V, F)
    assert attributes is None
    scale = np.ptp(V, axis=0).max()
    assert np.abs(V2 - expected).max() <= 1e-12 * scale
    assert np.array_equal(V, V0) and np.array_equal(F, F0), 'the input arrays are not modified'
    assert set(report) == set(program_report), 'the report has the keys of the program\'s JSON report'
    for key in ('status', 'stop_reason', 'tensor', 'automatic_parameters', 'vertices', 'faces', 'noise_level',
                'choices'):
        assert report[key] == program_report[key], key
    assert len(report['steps']) == len(program_report['steps']) > 0
    assert report['status'] == 'success' and report['stop_reason'] == 'noise_level'


def test_attributes_coupled_equal_the_program(fandisk, tmp_path):
    V, F = fandisk
    rng = np.random.default_rng(3)
    q = np.sin(V[:, 0]) + 0.1 * rng.standard_normal(len(V))
    write_ply(tmp_path / 'in.ply', V, F, q)
    settings = ['--attributes', 'q', '--mode', 'coupled', '--attribute-weight', '0.5', '--relative-time-step', '1e-3',
                '--steps', '3', '--stop', 'off']
    run_tool(['in.ply', 'out.ply'] + settings, tmp_path)
    expected_V, expected_q = read_ply_xyzq(tmp_path / 'out.ply')
    V2, q2, report = af.fair(V, F, attributes=q, attribute_mode='coupled', attribute_weight=0.5,
                             relative_time_step=1e-3, number_of_iterations=3, stopping_criteria='off')
    assert q2.shape == q.shape, 'a 1-D attribute comes back 1-D'
    assert np.abs(V2 - expected_V).max() <= 1e-12 * np.ptp(V, axis=0).max()
    assert np.abs(q2 - expected_q).max() <= 1e-12 * np.ptp(q)
    assert np.abs(q2 - q).max() > 1e-3, 'the attribute was faired'
    assert report['mode'] == 'coupled' and report['attribute_dimension'] == 1 and len(report['steps']) == 3


def test_every_mode_and_setting_runs(fandisk):
    V, F = grid(10, lambda x, y: 0.05 * np.sin(6 * x) * np.cos(5 * y))
    C = np.column_stack([V[:, 0], V[:, 1] ** 2])
    for mode in ('separate', 'coupled', 'attributes', 'geometry'):
        V2, C2, report = af.fair(V, F, attributes=C, attribute_mode=mode, relative_time_step=1e-3,
                                 number_of_iterations=2)
        assert report['status'] == 'success' and C2.shape == C.shape
        if mode == 'attributes':
            assert np.array_equal(V2, V), 'attributes only: the geometry is not written'
        if mode == 'geometry':
            assert np.array_equal(C2, C), 'geometry only: the attributes are not written'
    for extra in (dict(tensor='anisotropic'), dict(flow_order=4, relative_time_step=1e-4),
                  dict(finite_element='linear'), dict(relative_maximum_deviation=0.001),
                  dict(boundary_handling='vertices'), dict(output_positions='control'),
                  dict(tensor='uniform'), dict(linear_solver='cholesky')):
        settings = dict(relative_time_step=1e-3, number_of_iterations=2)
        settings.update(extra)
        V2, _, report = af.fair(V, F, **settings)
        assert report['status'] == 'success', extra
        if 'relative_maximum_deviation' in extra:
            assert np.linalg.norm(V2 - V, axis=1).max() <= report['maximum_deviation'] * (1 + 1e-12)
    held = np.zeros(len(V), dtype=bool)
    held[::3] = True
    V2, _, report = af.fair(V, F, vertex_is_constrained=held, relative_time_step=1e-3, number_of_iterations=2)
    assert np.array_equal(V2[held], V[held]) and report['held_vertices'] == held.sum()


def test_maximum_deviation_is_a_deprecated_spelling(fandisk):
    """maximum_deviation still means relative_maximum_deviation, with a DeprecationWarning naming both spellings"""
    V, F = fandisk
    # the solver given: the automatic choice between conjugate gradients and the factorisation is timed, so two
    # runs of the same settings can solve a step differently and differ in the last digits
    settings = dict(relative_time_step=1e-3, number_of_iterations=2, linear_solver='cholesky')
    V_new, _, r_new = af.fair(V, F, relative_maximum_deviation=0.001, **settings)
    with pytest.warns(DeprecationWarning, match='relative_maximum_deviation'):
        V_old, _, r_old = af.fair(V, F, maximum_deviation=0.001, **settings)
    assert np.array_equal(V_new, V_old) and r_new['maximum_deviation'] == r_old['maximum_deviation']
    with pytest.raises(ValueError, match='absolute_maximum_deviation'):
        af.fair(V, F, relative_maximum_deviation=0.001, absolute_maximum_deviation=0.01, **settings)


def test_strength_scales_the_noise_target(fandisk, tmp_path):
    """strength (the program's --strength): 1 is the default run; 2 keeps the flow the default run keeps (the
    anisotropic one on this CAD part), runs it to twice the noise and moves the surface farther, as the program
    does; a value that is not positive and finite, or a strength where no run stops at the noise level, is refused
    naming it"""
    V, F = fandisk
    V1, _, r1 = af.fair(V, F, quiet=True)
    V1s, _, r1s = af.fair(V, F, quiet=True, strength=1)
    assert np.array_equal(V1, V1s) and r1['choices'] == r1s['choices'] and r1s['strength'] == 1
    V2, _, r2 = af.fair(V, F, quiet=True, strength=2)
    assert r2['status'] == 'success' and r2['strength'] == 2 and r2['tensor'] == r1['tensor'] == 'anisotropic'
    assert abs(r2['noise_displacement'] / (2 * r2['noise_level']) - 1) < 0.02 and 'strength 2' in r2['choices']
    moved = [np.linalg.norm(X - V, axis=1).mean() for X in (V1, V2)]
    assert moved[1] > 1.5 * moved[0], moved
    run_tool([os.path.join(DATA, 'fandisk_noisy.obj'), 'out.off', '--strength', '2', '--report', 'out.json'], tmp_path)
    expected, _ = read_mesh(tmp_path / 'out.off')
    assert np.abs(V2 - expected).max() <= 1e-12 * np.ptp(V, axis=0).max(), 'the program\'s --strength 2'
    assert json.load(open(tmp_path / 'out.json'))['choices'] == r2['choices']
    for bad in (0, -1.0, float('nan'), float('inf')):
        with pytest.raises(ValueError, match='strength'):
            af.fair(V, F, quiet=True, strength=bad)
    with pytest.raises(TypeError, match='strength'):
        af.fair(V, F, quiet=True, strength='more')
    with pytest.raises(ValueError, match='strength'):
        af.fair(V, F, quiet=True, strength=2, relative_time_step=1e-3)   # the paper's criteria: no noise stop


def test_bad_input_raises():
    V, F = grid(3)
    cases = [
        (lambda: af.fair(V[:, :2], F), ValueError, 'V must be an N x 3 array'),
        (lambda: af.fair(V.astype(str), F), TypeError, 'V must hold real numbers'),
        (lambda: af.fair(V, F.astype(float)), TypeError, 'F must hold integer vertex indices'),
        (lambda: af.fair(V, F[:, :2]), ValueError, 'F must be an M x 3 array'),
        (lambda: af.fair(V, np.vstack([F, [[0, 1, 99]]])), ValueError, 'refers to vertex 99, but V has 16 vertices'),
        (lambda: af.fair(V, np.vstack([F, [[0, -1, 2]]])), ValueError, 'refers to vertex -1'),
        (lambda: af.fair(V, F[:0]), ValueError, 'no face'),
        (lambda: af.fair(np.where(np.arange(48).reshape(16, 3) == 7, np.nan, V), F), ValueError,
         'V row 2 is not finite'),
        (lambda: af.fair(V, F, attributes=np.zeros((5, 2))), ValueError,
         'attributes must have one row per vertex (16)'),
        (lambda: af.fair(V, F, time_step=1e-3, relative_time_step=1e-3), ValueError,
         'give either time_step or relative_time_step'),
        (lambda: af.fair(V, F, tensor='bilateral'), ValueError, 'tensor expects isotropic, anisotropic or uniform'),
        (lambda: af.fair(V, F, relative_time_step=-1), ValueError, 'relative_time_step must be positive'),
        (lambda: af.fair(V, F, lambda_=2), ValueError, 'lambda_ needs tensor anisotropic'),
        (lambda: af.fair(V, F, steps=3), TypeError, "unexpected keyword argument 'steps'"),
        (lambda: af.fair(V, F, relative_time_step=True), TypeError, 'relative_time_step expects a number'),
        (lambda: af.limit_surface(V, F).resample(11), ValueError, 'must not exceed 10'),
    ]
    for call, error, text in cases:
        with pytest.raises(error) as e:
            call()
        assert text in str(e.value), (text, str(e.value))


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
            if (min(a, b), max(a, b)) not in middle:
                middle[(min(a, b), max(a, b))] = len(V)
                V.append([(V[a][k] + V[b][k]) / 2 for k in range(3)])
            return middle[(min(a, b), max(a, b))]
        for a, b, c in F:
            G += [[a, mid(a, b), mid(c, a)], [b, mid(b, c), mid(a, b)], [c, mid(c, a), mid(b, c)],
                  [mid(a, b), mid(b, c), mid(c, a)]]
        F = G
    V = np.array(V)
    return V / np.linalg.norm(V, axis=1)[:, None], np.array(F)


def test_non_manifold_vertices_are_split_as_the_program_splits_them(tmp_path):
    # two noisy spheres touching at a vertex (a bow-tie, as raw scans have): faired without asking, the
    # shared vertex returned once, and the result the program's for the same mesh
    A, FA = icosphere(2)
    rng = np.random.default_rng(5)
    A = A * (1 + 0.01 * rng.standard_normal((len(A), 1)))
    B = A - A[3] + A[0]   # B's vertex 3 on A's vertex 0, B outside A
    keep = [j for j in range(len(B)) if j != 3]
    index = {j: len(A) + k for k, j in enumerate(keep)}
    index[3] = 0
    V = np.vstack([A, B[keep]])
    F = np.vstack([FA, [[index[j] for j in f] for f in FA]])
    q = np.arange(len(V), dtype=float)
    write_ply(tmp_path / 'bowtie.ply', V, F, q)
    p = run_tool(['bowtie.ply', 'out.ply', '--report', 'out.json'], tmp_path)
    assert 'non-manifold' in p.stderr
    expected, _ = read_ply_xyzq(tmp_path / 'out.ply')
    V0, F0 = V.copy(), F.copy()
    with pytest.warns(UserWarning, match='vertex 0 is non-manifold.*split 1 non-manifold vertex'):
        V2, _, report = af.fair(V, F)
    assert V2.shape == V.shape and np.array_equal(V, V0) and np.array_equal(F, F0)
    assert np.abs(V2 - expected).max() <= 1e-12 * np.ptp(V, axis=0).max()
    assert report['split_vertices'] == 1 and report['vertices'] == len(V) and report['input_changes']
    assert report['split_vertices'] == json.load(open(tmp_path / 'out.json'))['split_vertices']
    with pytest.raises(ValueError, match='non-manifold'):
        af.limit_surface(V, F)   # the limit surface of a mesh that is not a 2-manifold is not defined


def test_a_failed_run_raises_with_its_report():
    # a tiny closed mesh run far past its collapse: the library reports the failure, the module raises it
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    with pytest.raises(af.FairingError) as e:
        af.fair(V, F, relative_time_step=10, number_of_iterations=50, stopping_criteria='off')
    assert e.value.report['status'] != 'success' and 'fairing failed' in str(e.value)
    assert isinstance(e.value, RuntimeError)


def test_a_run_that_cannot_fit_is_refused_before_it_starts(fandisk):
    V, F = fandisk
    with pytest.raises(af.FairingError) as e:
        af.fair(V, F, memory_limit=1 << 20)
    r = e.value.report
    assert r['status'] == 'insufficient_memory' and r['steps'] == []
    assert r['available_memory_mb'] == 1 and r['predicted_memory_mb'] > 1
    assert r['memory_limited_by'] == 'the memory_limit given' and '1 MB are available' in r['message']
    P, _, report = af.fair(V, F, memory_limit=math.inf, quiet=True)
    assert report['status'] == 'success' and report['available_memory_mb'] is None
    assert report['predicted_memory_mb'] == r['predicted_memory_mb'] and report['peak_memory_mb'] > 0
    with pytest.raises(ValueError, match='memory_limit'):
        af.fair(V, F, memory_limit=-1)
    with pytest.raises(TypeError, match='memory_limit'):
        af.fair(V, F, memory_limit='6G')


def test_callback_and_gil(fandisk):
    V, F = fandisk
    seen = []
    _, _, report = af.fair(V, F, relative_time_step=1e-4, number_of_iterations=10, stopping_criteria='off',
                           callback=lambda s: seen.append(s['step']) or s['step'] < 3)
    assert seen == [1, 2, 3] and report['stop_reason'] == 'callback'

    def boom(step):
        raise KeyError('from the callback')
    with pytest.raises(KeyError):
        af.fair(V, F, relative_time_step=1e-4, number_of_iterations=5, callback=boom)
    # an exception ends the call at once: the default run's comparison makes no further run
    runs = []

    def boom_in_run_2(step):
        runs.append(step['run'])
        if step['run'] == 2:
            raise KeyError('from run 2')
    with pytest.raises(KeyError, match='from run 2'):
        af.fair(V, F, callback=boom_in_run_2)
    assert runs.count(2) == 1 and runs[-1] == 2, runs

    # another Python thread runs while the fairing does: the GIL is released. Without that it would run
    # for a few switch intervals (5 ms each) at most; with it, about as often as while this one sleeps.
    count, running = [0], [True]

    def spin():
        while running[0]:
            count[0] += 1
    t = threading.Thread(target=spin)
    t.start()
    try:
        start, t0 = count[0], time.perf_counter()
        time.sleep(0.3)
        rate = (count[0] - start) / (time.perf_counter() - t0)
        start, t0 = count[0], time.perf_counter()
        af.fair(V, F, relative_time_step=1e-4, number_of_iterations=5, stopping_criteria='off')
        seconds = time.perf_counter() - t0
        during = count[0] - start
    finally:
        running[0] = False
        t.join()
    assert seconds > 0.2, 'the run takes long enough to tell (%.3f s)' % seconds
    assert during > 0.25 * rate * seconds, ('the other thread ran %d times in %.2f s (%.0f per s alone)'
                                            % (during, seconds, rate))


def test_limit_surface():
    # a plane: limit points on it, normals along z, resampling keeps the vertices first and the plane
    V, F = grid(6)
    s = af.limit_surface(V, F)
    P, N = s.positions, s.normals
    assert P.shape == V.shape and np.abs(P[:, 2]).max() == 0 and np.allclose(np.abs(N[:, 2]), 1, atol=1e-15)
    V1, F1 = s.resample(2)
    assert len(F1) == 16 * len(F) and np.array_equal(V1[:len(V)], P) and np.abs(V1[:, 2]).max() == 0
    affine = 2 * V[:, 0] - V[:, 1] + 3
    V1, F1, a1 = s.resample(1, attributes=affine)
    assert np.abs(a1 - (2 * V1[:, 0] - V1[:, 1] + 3)).max() < 1e-13, 'an affine attribute stays affine'
    assert abs(s.area - 1) < 1e-12 or s.area < 1, 'the limit surface of a held grid lies within it'

    # an octahedron refined 3 times, pushed onto the unit sphere: a convex surface whose median mean curvature
    # is -1, principal curvatures near -1 at its regular (valence 6) vertices (next to the six valence-4
    # vertices, where the Loop limit surface has no finite curvature, they stray by up to a fifth), principal
    # directions orthogonal and tangent
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    for _ in range(3):
        V, F, _ = af.limit_surface(V, F).resample(1, attributes=V)
    V = V / np.linalg.norm(V, axis=1)[:, None]
    c = af.limit_surface(V, F).curvatures()
    assert set(c) == {'k1', 'k2', 'mean_curvature', 'd1', 'd2'}
    regular = np.bincount(F.ravel(), minlength=len(V)) == 6
    assert regular.sum() == len(V) - 6 and np.all(c['k1'] <= c['k2'])
    assert abs(np.median(c['mean_curvature']) + 1) < 0.01
    assert np.all((c['k1'][regular] > -1.25) & (c['k2'][regular] < -0.95))
    normals = af.limit_surface(V, F).normals
    for a, b in ((c['d1'], c['d2']), (c['d1'], normals), (c['d2'], normals)):
        assert np.abs(np.einsum('ij,ij->i', a, b)).max() < 1e-9


def test_fair_has_every_parameter_as_a_typed_keyword():
    """the package's fair() names every parameter the compiled part takes, keyword-only, default None"""
    import inspect
    from anisotropic_fairing import _core
    parameters = inspect.signature(af.fair).parameters
    assert list(parameters)[:2] == ['V', 'F']
    keywords = list(parameters)[2:]
    assert keywords == ['attributes', 'vertex_is_constrained', 'callback', 'quiet'] + list(_core.parameter_names)
    for name in keywords:
        default = False if name == 'quiet' else None
        assert parameters[name].kind == inspect.Parameter.KEYWORD_ONLY and parameters[name].default is default, name
    assert 'relative_time_step' in af.fair.__doc__ and af.__version__


def conforms(value, annotation):
    """whether a JSON value has the type `annotation` (the typing forms report.py uses)"""
    import typing
    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Union:
        return any(conforms(value, a) for a in args)
    if origin is list:
        return isinstance(value, list) and all(conforms(v, args[0]) for v in value)
    if annotation is type(None):
        return value is None
    if typing.is_typeddict(annotation):
        hints = typing.get_type_hints(annotation)
        return isinstance(value, dict) and set(value) == set(hints) and all(conforms(value[k], hints[k]) for k in hints)
    if annotation is float:
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if annotation is int:
        return isinstance(value, int) and not isinstance(value, bool)
    return isinstance(value, annotation)


def test_the_report_is_a_fairing_report(fandisk, tmp_path):
    """every report (a run, a run with attributes and a bound, a failed one, the program's) has exactly the
    keys of FairingReport, each value of its type; the callback's dict is a StepInfo"""
    V, F = fandisk
    seen = []
    _, _, default = af.fair(V, F, callback=lambda s: seen.append(s))
    assert conforms(default, af.FairingReport) and len(default['steps']) > 0
    assert seen and all(conforms(s, af.StepInfo) for s in seen)
    # the default run compares flows: each step says which run it belongs to
    assert ({s['run_name'] for s in seen} >= {'anisotropic flow', 'isotropic flow'}
            and seen[-1]['runs'] >= seen[-1]['run'] > 1)
    _, _, bounded = af.fair(V, F, attributes=np.column_stack([V[:, 0], V[:, 1]]), attribute_mode='coupled',
                            relative_maximum_deviation=0.002, number_of_iterations=2)
    assert conforms(bounded, af.FairingReport)
    with pytest.raises(af.FairingError) as e:
        octahedron = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
        faces = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
        af.fair(octahedron, faces, relative_time_step=10, number_of_iterations=50, stopping_criteria='off')
    assert conforms(e.value.report, af.FairingReport)
    run_tool([os.path.join(DATA, 'fandisk_noisy.obj'), 'out.off', '--report', 'out.json', '--resample', '1'], tmp_path)
    assert conforms(json.load(open(tmp_path / 'out.json')), af.FairingReport)
    assert not conforms(dict(default, vertices='many'), af.FairingReport), 'the check can fail'


def progress_of(capsys, call):
    """what a call writes on stderr, and its result"""
    capsys.readouterr()
    result = call()
    return capsys.readouterr().err, result


def test_progress_on_stderr(fandisk, capsys, monkeypatch):
    """a run longer than about a second shows its steps on stderr, through tqdm or without it; quiet=True,
    and a shorter run, show nothing; the result is the same, bit for bit"""
    import tqdm   # noqa: F401 (Debian: python3-tqdm)
    from anisotropic_fairing import _progress
    V, F = fandisk
    settings = dict(relative_time_step=1e-4, number_of_iterations=3, stopping_criteria='off')
    err, _ = progress_of(capsys, lambda: af.fair(*grid(6), **settings))
    assert err == '', 'a run shorter than a second shows nothing'
    monkeypatch.setattr(_progress, 'DELAY', 0.0)   # as if every run lasted longer
    err, (V_tqdm, _, report) = progress_of(capsys, lambda: af.fair(V, F, **settings))
    assert 'anisotropic_fairing: 3 steps [00:0' in err and 'steps/s, done after step 3]' in err, 'tqdm: ' + err
    err, (V_quiet, _, quiet_report) = progress_of(capsys, lambda: af.fair(V, F, quiet=True, **settings))
    assert err == ''
    monkeypatch.setitem(sys.modules, 'tqdm', None)   # without tqdm: a line per step (stderr is not a terminal)
    seen = []
    err, (V_plain, _, _) = progress_of(capsys, lambda: af.fair(V, F, callback=seen.append, **settings))
    lines = [line for line in err.splitlines() if ': step ' in line]
    assert len(lines) == 3 and len(seen) == 3, err
    for k, line in enumerate(lines, 1):
        assert re.fullmatch(r'anisotropic_fairing: step %d \(%d steps in all, [0-9.]+ s\)' % (k, k), line), line
    assert re.fullmatch(r'anisotropic_fairing: done after 3 steps, [0-9.]+ s', err.splitlines()[-1]), err
    assert np.array_equal(V_tqdm, V_quiet) and np.array_equal(V_quiet, V_plain), 'the display does not touch the run'
    assert [s['H_integral'] for s in report['steps']] == [s['H_integral'] for s in quiet_report['steps']]
    # the default run names its runs
    err, _ = progress_of(capsys, lambda: af.fair(V, F, number_of_iterations=12))
    assert 'step 1 of run 2 of at most' in err and 'the isotropic flow' in err, err


def test_progress_on_a_terminal(monkeypatch):
    """without tqdm on a terminal: one line, refreshed in place, also during the set-up before the first step"""
    from anisotropic_fairing._progress import Progress
    monkeypatch.setitem(sys.modules, 'tqdm', None)

    class Terminal(io.StringIO):
        def isatty(self):
            return True
    out = Terminal()
    with Progress(file=out, delay=0.0) as p:
        time.sleep(0.8)   # the set-up: the thread shows it
        p.step(dict(step=1, run=1, runs=1, run_name=''))
    text = out.getvalue()
    assert text.startswith('\ranisotropic_fairing: 0 steps, ') and 'setting up' in text, text
    assert '\ranisotropic_fairing: 1 steps, ' in text and '\ranisotropic_fairing: done after 1 steps' in text, text
    assert text.endswith('\n') and text.count('\n') == 1, text


CHILD = """
import signal, sys, time
import numpy as np
import anisotropic_fairing as af
signal.signal(signal.SIGINT, signal.default_int_handler)   # Python's own, whatever the test runner did
V, F = np.load(sys.argv[1])['V'], np.load(sys.argv[1])['F']
V0, F0 = V.copy(), F.copy()
print('started', flush=True)
try:
    quiet = dict(quiet=True) if sys.argv[2] == 'quiet' else {}   # else the default: the progress shown
    af.fair(V, F, relative_time_step=1e-6, number_of_iterations=100000, stopping_criteria='off', **quiet)
finally:
    print('unchanged' if np.array_equal(V, V0) and np.array_equal(F, F0) else 'modified', flush=True)
"""


@pytest.mark.parametrize('quiet', ['quiet', 'progress'])
def test_ctrl_c_raises_keyboard_interrupt(fandisk, tmp_path, quiet):
    """Ctrl-C during a run without a callback (100000 tiny steps: half an hour or more) raises
    KeyboardInterrupt after the step it arrives in, and the input arrays are as they were"""
    V, F = fandisk
    np.savez(tmp_path / 'mesh.npz', V=V, F=F)
    child = subprocess.Popen([sys.executable, '-c', CHILD, str(tmp_path / 'mesh.npz'), quiet], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert child.stdout.readline() == 'started\n'
        time.sleep(1.5)   # the set-up and a few steps
        child.send_signal(signal.SIGINT)
        sent = time.perf_counter()
        out, err = child.communicate(timeout=30)
    finally:
        child.kill()
        child.wait()
    seconds = time.perf_counter() - sent
    assert 'KeyboardInterrupt' in err.splitlines()[-1], err[-2000:]
    assert out == 'unchanged\n' and seconds < 10, (out, seconds)
