"""Tests of anisotropic_fairing.fair_meshio, fair_open3d and fair_vtk (pytest; Debian: python3-meshio,
python3-open3d, python3-vtk9): each gives fair()'s result on the same arrays, keeps the mesh's order and
data, gives the faired surface's normals as the program does (AF_TOOL), and leaves the input as it was."""
import os
import subprocess

import meshio
import numpy as np
import open3d
import pytest
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import anisotropic_fairing as af

TOOL = os.environ.get('AF_TOOL', '')
DATA = os.environ.get('AF_DATA', '')
SETTINGS = dict(relative_time_step=1e-3, number_of_iterations=2, stopping_criteria='off')
PROGRAM_SETTINGS = ['--relative-time-step', '1e-3', '--steps', '2', '--stop', 'off', '--quiet']


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
    mesh = meshio.Mesh(V.copy(), [('triangle', F.copy())],
                       point_data={'q': q.copy(), 'uv': uv.copy(), 'id': keep.copy()})
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
    mesh = open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(V),
                                        open3d.utility.Vector3iVector(F.astype(np.int32)))
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
    assert (np.array_equal(np.asarray(mesh.vertices), before[0])
            and np.array_equal(np.asarray(mesh.vertex_colors), before[1]))
    # without colours, or with colours left as they are
    plain, report = af.fair_open3d(mesh, colours=False, **SETTINGS)
    assert (np.array_equal(np.asarray(plain.vertices), af.fair(V, F, **SETTINGS)[0])
            and report['attribute_dimension'] == 0)
    assert np.array_equal(np.asarray(plain.vertex_colors), colours)


def unit_face_normals(V, F):
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    return n / np.linalg.norm(n, axis=1)[:, None]


def test_fair_meshio_gives_the_normals_of_the_faired_surface(fandisk, tmp_path):
    """vertex normals (PLY nx/ny/nz, OBJ vn, a 'Normals' array) come back as the program writes them for the
    faired surface, never stale; STL's facet normals too; normals that are not one per point are dropped"""
    V, F = fandisk
    stale = np.tile([0.0, 0.0, 1.0], (len(V), 1))
    meshio.Mesh(V, [('triangle', F.astype(np.int32))],
                point_data={'nx': stale[:, 0], 'ny': stale[:, 1], 'nz': stale[:, 2]}
                ).write(tmp_path / 'in.ply', binary=True)
    for output, normals in (('limit', 'limit_surface'), ('control', 'vertex_normals')):
        p = subprocess.run([TOOL, 'in.ply', 'out.ply', '--output', output] + PROGRAM_SETTINGS, cwd=tmp_path,
                           capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        expected = meshio.read(tmp_path / 'out.ply')
        mesh = meshio.read(tmp_path / 'in.ply')
        faired, report = af.fair_meshio(mesh, output_positions=output, **SETTINGS)
        assert report['normals'] == normals
        assert np.abs(faired.points - expected.points).max() <= 1e-12 * np.ptp(V, axis=0).max()
        N = np.column_stack([faired.point_data[c] for c in ('nx', 'ny', 'nz')])
        N_program = np.column_stack([expected.point_data[c] for c in ('nx', 'ny', 'nz')])
        assert np.abs(N - N_program).max() <= 1e-12 and np.abs(N - stale).max() > 0.5, 'the program\'s normals'
        assert np.array_equal(mesh.point_data['nx'], stale[:, 0]), 'the input mesh is not modified'
        # the same normals under the other names meshio gives them
        for name in ('obj:vn', 'Normals', 'normals'):
            other, _ = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={name: stale}),
                                      output_positions=output, **SETTINGS)
            assert np.array_equal(other.point_data[name], N.astype(float)), name
    # STL: one normal per facet (cell data), recomputed
    meshio.Mesh(V, [('triangle', F)]).write(tmp_path / 'in.stl')
    mesh = meshio.read(tmp_path / 'in.stl')
    faired, _ = af.fair_meshio(mesh, **SETTINGS)
    expected = unit_face_normals(faired.points, faired.get_cells_type('triangle'))
    assert np.abs(faired.cell_data['facet_normals'][0] - expected).max() < 1e-6
    # normals that are not one 3-vector per point are dropped, saying so
    with pytest.warns(UserWarning, match="point data 'normals' .* not one normal per point .* dropped"):
        faired, _ = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={'normals': stale[:, :2]}), **SETTINGS)
    assert 'normals' not in faired.point_data
    # the geometry not faired: the input's normals are right, and kept
    faired, report = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={'Normals': stale, 'q': V[:, 0]}),
                                    attributes='q', attribute_mode='attributes', **SETTINGS)
    assert np.array_equal(faired.point_data['Normals'], stale) and report['normals'] == 'input'


def test_fair_open3d_keeps_textures(fandisk):
    """texture coordinates, textures and material ids are kept; vertex normals are the program's for the
    faired surface, triangle normals recomputed"""
    V, F = fandisk
    rng = np.random.default_rng(11)
    uvs = rng.random((3 * len(F), 2))
    mesh = open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(V),
                                        open3d.utility.Vector3iVector(F.astype(np.int32)))
    mesh.triangle_uvs = open3d.utility.Vector2dVector(uvs)
    mesh.textures = [open3d.geometry.Image(np.full((8, 8, 3), 200, dtype=np.uint8))]
    mesh.triangle_material_ids = open3d.utility.IntVector(np.arange(len(F), dtype=np.int32) % 2)
    mesh.compute_vertex_normals()
    mesh.compute_triangle_normals()
    before = np.asarray(mesh.vertices).copy(), np.asarray(mesh.vertex_normals).copy()
    faired, report = af.fair_open3d(mesh, **SETTINGS)
    assert np.array_equal(np.asarray(faired.vertices), af.fair(V, F, **SETTINGS)[0])
    assert faired.has_triangle_uvs() and np.array_equal(np.asarray(faired.triangle_uvs), uvs)
    assert len(faired.textures) == 1 and np.array_equal(np.asarray(faired.textures[0]), np.asarray(mesh.textures[0]))
    assert np.array_equal(np.asarray(faired.triangle_material_ids), np.arange(len(F)) % 2)
    with_normals, _ = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={'Normals': before[1]}), **SETTINGS)
    assert (np.array_equal(np.asarray(faired.vertex_normals), with_normals.point_data['Normals'])
            and report['normals'] == 'limit_surface')
    assert np.abs(np.asarray(faired.triangle_normals) - unit_face_normals(np.asarray(faired.vertices), F)).max() < 1e-12
    assert (np.array_equal(np.asarray(mesh.vertices), before[0])
            and np.array_equal(np.asarray(mesh.vertex_normals), before[1]))
    assert np.array_equal(np.asarray(mesh.triangle_uvs), uvs), 'the input mesh is not modified'
    with pytest.raises(TypeError, match='open3d.geometry.TriangleMesh'):
        af.fair_open3d(meshio.Mesh(V, [('triangle', F)]))


# ---- fair_vtk ----------------------------------------------------------------------------------------

def polydata(V, F, cls=vtkPolyData, points_type=np.float64, lines=(), verts=()):
    """a vtkPolyData (or subclass) with these points and triangles, lines and vertex cells"""
    mesh = cls()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(V, dtype=points_type), deep=True))
    mesh.SetPoints(points)
    for setter, cells in ((mesh.SetPolys, F), (mesh.SetLines, lines), (mesh.SetVerts, verts)):
        if len(cells):
            setter(cell_array(cells))
    return mesh


def cell_array(cells):
    cells = [list(c) for c in cells]
    a = vtkCellArray()
    a.SetData(numpy_to_vtkIdTypeArray(np.cumsum([0] + [len(c) for c in cells]).astype(np.int64), deep=True),
              numpy_to_vtkIdTypeArray(np.concatenate(cells).astype(np.int64), deep=True))
    return a


def add_array(data, name, values):
    array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
    array.SetName(name)
    data.AddArray(array)
    return array


def arrays_of(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)).copy() for i in range(data.GetNumberOfArrays())}


def test_fair_vtk(fandisk):
    """fair()'s result on the points and triangles; the point-data arrays named faired in their own type,
    the others carried over, the normals the program's; cell and field data, lines and vertex cells kept"""
    V, F = fandisk
    rng = np.random.default_rng(13)
    q = np.sin(V[:, 0]) + 0.1 * rng.standard_normal(len(V))
    colour = np.clip(128 + 60 * np.column_stack([np.sin(V[:, 0]), np.cos(V[:, 1]), V[:, 2]])
                     + 20 * rng.standard_normal((len(V), 3)), 0, 255).astype(np.uint8)
    mesh = polydata(V, F, lines=[[0, 1, 2]], verts=[[5]])
    pd = mesh.GetPointData()
    add_array(pd, 'q', q)
    add_array(pd, 'colour', colour)
    add_array(pd, 'id', np.arange(len(V), dtype=np.int32))
    pd.SetNormals(add_array(pd, 'Normals', np.tile(np.float32([0, 0, 1]), (len(V), 1))))
    pd.SetTCoords(add_array(pd, 'uv', V[:, :2].astype(np.float32)))
    add_array(mesh.GetCellData(), 'cell_id', np.arange(mesh.GetNumberOfCells(), dtype=np.int64))
    meta = vtkIntArray()
    meta.SetName('meta')
    meta.InsertNextValue(42)
    mesh.GetFieldData().AddArray(meta)
    before = arrays_of(pd), vtk_to_numpy(mesh.GetPoints().GetData()).copy()

    faired, report = af.fair_vtk(mesh, attributes=['q', 'colour'], **SETTINGS)
    V2, A2, _ = af.fair(V, F, attributes=np.column_stack([q, colour]), **SETTINGS)
    assert type(faired) is vtkPolyData and faired is not mesh and report['attribute_dimension'] == 4
    assert np.array_equal(vtk_to_numpy(faired.GetPoints().GetData()), V2)
    out = arrays_of(faired.GetPointData())
    assert np.array_equal(out['q'], A2[:, 0]) and out['colour'].dtype == np.uint8
    assert np.array_equal(out['colour'], np.clip(np.rint(A2[:, 1:]), 0, 255).astype(np.uint8)), 'rounded, clamped'
    assert np.array_equal(out['id'], np.arange(len(V))) and np.array_equal(out['uv'], before[0]['uv'])
    assert (faired.GetPointData().GetTCoords().GetName() == 'uv'
            and faired.GetPointData().GetNormals().GetName() == 'Normals')
    with_normals, _ = af.fair_meshio(meshio.Mesh(V, [('triangle', F)], point_data={'Normals': before[0]['Normals']}),
                                     **SETTINGS)
    assert out['Normals'].dtype == np.float32 and np.array_equal(out['Normals'], with_normals.point_data['Normals'])
    assert report['normals'] == 'limit_surface'
    assert np.array_equal(vtk_to_numpy(faired.GetCellData().GetArray('cell_id')), np.arange(len(F) + 2))
    assert faired.GetFieldData().GetArray('meta').GetValue(0) == 42
    assert np.array_equal(vtk_to_numpy(faired.GetLines().GetConnectivityArray()), [0, 1, 2])
    assert np.array_equal(vtk_to_numpy(faired.GetVerts().GetConnectivityArray()), [5])
    assert np.array_equal(vtk_to_numpy(faired.GetPolys().GetConnectivityArray()), F.ravel())
    # the input is as it was
    assert np.array_equal(vtk_to_numpy(mesh.GetPoints().GetData()), before[1])
    for name, values in arrays_of(mesh.GetPointData()).items():
        assert np.array_equal(values, before[0][name]), name
    # geometry only; the attributes only (positions and normals as they were)
    faired, _ = af.fair_vtk(mesh, **SETTINGS)
    assert np.array_equal(vtk_to_numpy(faired.GetPoints().GetData()), af.fair(V, F, **SETTINGS)[0])
    faired, report = af.fair_vtk(mesh, attributes='q', attribute_mode='attributes', **SETTINGS)
    assert np.array_equal(vtk_to_numpy(faired.GetPoints().GetData()), V) and report['normals'] == 'input'
    assert np.array_equal(arrays_of(faired.GetPointData())['Normals'], before[0]['Normals'])


def test_fair_vtk_keeps_the_class_and_the_precision(fandisk):
    """a subclass (as pyvista.PolyData is) comes back as itself; float32 points stay float32"""
    V, F = fandisk

    class PolyData(vtkPolyData):
        pass
    mesh = polydata(V, F, cls=PolyData, points_type=np.float32)
    faired, _ = af.fair_vtk(mesh, **SETTINGS)
    assert type(faired) is PolyData
    points = vtk_to_numpy(faired.GetPoints().GetData())
    assert points.dtype == np.float32
    assert np.array_equal(points, af.fair(V.astype(np.float32), F, **SETTINGS)[0].astype(np.float32))


def grid_of_quads(n=8):
    """a bumpy (n+1) x (n+1) grid of points and its n x n quads, counter-clockwise"""
    V = np.array([[i / n, j / n, 0.05 * np.sin(6 * i / n) * np.cos(5 * j / n)]
                  for j in range(n + 1) for i in range(n + 1)])
    quads = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return V, quads


def test_fair_vtk_triangulates_polygons_and_strips():
    """polygons and triangle strips come back as triangles (with a warning), each one's cell data copied to
    its triangles; the result is fair()'s on those triangles"""
    n = 8
    V, quads = grid_of_quads(n)
    mesh = polydata(V, np.zeros((0, 3), dtype=np.int64))
    mesh.SetPolys(cell_array(quads))
    add_array(mesh.GetCellData(), 'quad', np.arange(len(quads), dtype=np.int32))
    with pytest.warns(UserWarning, match='64 polygons of the vtkPolyData are not triangles: triangulated'):
        faired, report = af.fair_vtk(mesh, **SETTINGS)
    F = vtk_to_numpy(faired.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    assert len(F) == 2 * len(quads) and np.all(np.diff(vtk_to_numpy(faired.GetPolys().GetOffsetsArray())) == 3)
    assert np.array_equal(vtk_to_numpy(faired.GetCellData().GetArray('quad')), np.repeat(np.arange(len(quads)), 2))
    assert np.array_equal(vtk_to_numpy(faired.GetPoints().GetData()), af.fair(V, F, **SETTINGS)[0])
    assert mesh.GetPolys().GetNumberOfCells() == len(quads), 'the input is not modified'
    # each row of the grid as a triangle strip
    strips = [[p for i in range(n + 1) for p in (j * (n + 1) + i, (j + 1) * (n + 1) + i)] for j in range(n)]
    mesh = polydata(V, np.zeros((0, 3), dtype=np.int64))
    mesh.SetStrips(cell_array(strips))
    with pytest.warns(UserWarning, match='0 polygons of the vtkPolyData are not triangles and 8 are triangle strips'):
        faired, _ = af.fair_vtk(mesh, **SETTINGS)
    F = vtk_to_numpy(faired.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    assert len(F) == 2 * n * n and faired.GetNumberOfStrips() == 0
    assert np.array_equal(vtk_to_numpy(faired.GetPoints().GetData()), af.fair(V, F, **SETTINGS)[0])


def test_fair_vtk_refuses_what_it_cannot_fair(fandisk):
    V, F = fandisk
    with pytest.raises(TypeError, match='vtkPolyData'):
        af.fair_vtk(meshio.Mesh(V, [('triangle', F)]))
    with pytest.raises(ValueError, match='has no polygon'):
        af.fair_vtk(polydata(V, np.zeros((0, 3)), lines=[[0, 1, 2]]))
    with pytest.raises(ValueError, match='not point-data arrays of the mesh: colour'):
        af.fair_vtk(polydata(V, F), attributes='colour')


def test_the_adapters_show_progress_unless_quiet(fandisk, capsys, monkeypatch):
    from anisotropic_fairing import _progress
    V, F = fandisk
    monkeypatch.setattr(_progress, 'DELAY', 0.0)   # as if the run lasted longer than a second
    F_int32 = F.astype(np.int32)
    for call in (lambda **k: af.fair_meshio(meshio.Mesh(V, [('triangle', F)]), **k),
                 lambda **k: af.fair_vtk(polydata(V, F), **k),
                 lambda **k: af.fair_open3d(open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(V),
                                                                         open3d.utility.Vector3iVector(F_int32)), **k)):
        capsys.readouterr()
        call(**SETTINGS)
        assert 'anisotropic_fairing' in capsys.readouterr().err
        call(quiet=True, **SETTINGS)
        assert capsys.readouterr().err == ''
