"""Tests of anisotropic_fairing.fair_meshio and fair_open3d (pytest; Debian: python3-meshio, python3-open3d):
each gives fair()'s result on the same arrays, keeps the mesh's order and data, and leaves the input as it was."""
import os

import meshio
import numpy as np
import open3d
import pytest

import anisotropic_fairing as af

DATA = os.environ.get('AF_DATA', '')
SETTINGS = dict(relative_time_step=1e-3, number_of_iterations=2, stopping_criteria='off')


@pytest.fixture(scope='module')
def fandisk():
    m = meshio.read(os.path.join(DATA, 'fandisk_noisy.obj'))
    return m.points, m.get_cells_type('triangle')


def test_fair_meshio(fandisk, tmp_path):
    V, F = fandisk
    rng = np.random.default_rng(5)
    q = np.sin(V[:, 0]) + 0.1 * rng.standard_normal(len(V))
    uv = np.column_stack([V[:, 0], V[:, 2]]) + 0.01 * rng.standard_normal((len(V), 2))
    keep = np.arange(len(V), dtype=float)
    mesh = meshio.Mesh(V.copy(), [('triangle', F.copy())], point_data={'q': q.copy(), 'uv': uv.copy(), 'id': keep.copy()})
    faired, report = af.fair_meshio(mesh, attributes=['q', 'uv'], **SETTINGS)
    V2, A2, expected_report = af.fair(V, F, attributes=np.column_stack([q, uv]), **SETTINGS)
    assert np.array_equal(faired.points, V2) and np.array_equal(faired.point_data['q'], A2[:, 0])
    assert np.array_equal(faired.point_data['uv'], A2[:, 1:]) and faired.point_data['q'].shape == q.shape
    assert np.array_equal(faired.point_data['id'], keep), 'data not named is carried over as it was'
    assert np.array_equal(faired.get_cells_type('triangle'), F)
    assert report['attribute_dimension'] == 3 and len(report['steps']) == len(expected_report['steps']) == 2
    assert np.array_equal(mesh.points, V) and np.array_equal(mesh.point_data['q'], q), 'the input mesh is not modified'
    # a file in, a file out: any format meshio reads and writes
    faired.write(tmp_path / 'faired.vtu')
    assert np.array_equal(meshio.read(tmp_path / 'faired.vtu').points, V2)
    # geometry only
    faired, _ = af.fair_meshio(mesh, **SETTINGS)
    assert np.array_equal(faired.points, af.fair(V, F, **SETTINGS)[0]) and np.array_equal(faired.point_data['q'], q)


def test_fair_meshio_refuses_what_it_cannot_fair(fandisk):
    V, F = fandisk
    mesh = meshio.Mesh(V, [('triangle', F), ('quad', np.array([[0, 1, 2, 3]]))])
    with pytest.raises(ValueError, match='cells of type quad'):
        af.fair_meshio(mesh)
    with pytest.raises(ValueError, match='not point data of the mesh: colour'):
        af.fair_meshio(meshio.Mesh(V, [('triangle', F)]), attributes='colour')
    with pytest.raises(ValueError, match='3-D points'):
        af.fair_meshio(meshio.Mesh(V[:, :2], [('triangle', F)]))


def test_fair_open3d(fandisk):
    V, F = fandisk
    rng = np.random.default_rng(7)
    colours = np.clip(0.5 + 0.5 * np.column_stack([np.sin(V[:, 0]), np.cos(V[:, 1]), V[:, 2] / np.abs(V[:, 2]).max()])
                      + 0.1 * rng.standard_normal((len(V), 3)), 0, 1)
    mesh = open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(V), open3d.utility.Vector3iVector(F.astype(np.int32)))
    mesh.vertex_colors = open3d.utility.Vector3dVector(colours)
    mesh.compute_vertex_normals()
    before = np.asarray(mesh.vertices).copy(), np.asarray(mesh.vertex_colors).copy()
    faired, report = af.fair_open3d(mesh, **SETTINGS)
    V2, C2, _ = af.fair(V, F, attributes=colours, **SETTINGS)
    assert np.array_equal(np.asarray(faired.vertices), V2)
    assert np.array_equal(np.asarray(faired.vertex_colors), np.clip(C2, 0, 1))
    assert np.abs(np.asarray(faired.vertex_colors) - colours).max() > 1e-3, 'the colours were faired'
    assert np.array_equal(np.asarray(faired.triangles), F) and report['attribute_dimension'] == 3
    normals = np.asarray(faired.vertex_normals)
    assert normals.shape == V.shape and np.allclose(np.linalg.norm(normals, axis=1), 1), 'normals of the faired surface'
    assert np.array_equal(np.asarray(mesh.vertices), before[0]) and np.array_equal(np.asarray(mesh.vertex_colors), before[1])
    # without colours, or with colours left as they are
    plain, report = af.fair_open3d(mesh, colours=False, **SETTINGS)
    assert np.array_equal(np.asarray(plain.vertices), af.fair(V, F, **SETTINGS)[0]) and report['attribute_dimension'] == 0
    assert np.array_equal(np.asarray(plain.vertex_colors), colours)
