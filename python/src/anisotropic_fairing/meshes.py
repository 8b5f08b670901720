"""Meshes of other Python libraries in and out of :func:`anisotropic_fairing.fair`: a ``meshio.Mesh``
(Debian: python3-meshio; any file format meshio reads), an Open3D ``TriangleMesh`` with its vertex colours
(Debian: python3-open3d) and a VTK ``vtkPolyData``, which a PyVista ``PolyData`` is (Debian:
python3-vtk9). Each library is imported only when its function is called.

The contract is the same for the three: the result is :func:`fair`'s on the mesh's arrays; a new mesh comes
back, with the input's vertex order, triangles and data, positions and the attributes named replaced by
their faired values; vertex normals are those of the faired surface, as the program writes them (the
exact normals of the Loop limit surface, or ``compute_vertex_normals`` of the mesh written for the control
points or the linear element; the input's when only the attributes are faired, ``report['normals']`` says
which), never the stale input ones; what cannot be kept is dropped with a warning; the input is not
modified. ``parameters`` are :func:`fair`'s keyword parameters (``quiet``, ``callback``, ... too).
"""
import warnings

import numpy as np

__all__ = ['fair_meshio', 'fair_open3d', 'fair_vtk']

# Names of vertex normals in a meshio.Mesh's point data (lower case): the OBJ reader's vn, and what the
# XML formats (VTU, XDMF) and writers commonly call them; PLY's are three arrays (nx, ny, nz).
_NORMAL_NAMES = ('normals', 'normal', 'obj:vn', 'vertex_normals', 'point_normals')
_NORMAL_TRIPLES = (('nx', 'ny', 'nz'), ('normal_x', 'normal_y', 'normal_z'))
_FACE_NORMAL_NAMES = ('facet_normals', 'face_normals', 'normals', 'normal')   # cell data (STL: facet_normals)


def _fair(V, F, attributes, parameters, vertex_normals=False):
    """fair() with the adapters' keyword parameters: ``(V2, attributes2, report, normals)``, the normals the
    program would write for the faired surface when asked for (None when the geometry was not faired)."""
    from . import _run
    keywords = dict(parameters)
    vertex_is_constrained = keywords.pop('vertex_is_constrained', None)
    callback = keywords.pop('callback', None)
    quiet = keywords.pop('quiet', False)
    result = _run(V, F, attributes, vertex_is_constrained, callback, quiet, keywords, vertex_normals)
    return result if vertex_normals else result + (None,)


def _face_normals(V, F):
    """unit normals of the triangles F of positions V (0 for a degenerate triangle)"""
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 0)


def _as_type(values, dtype):
    """faired values in an array's own type: integers rounded and clamped to their range (as the program does)"""
    dtype = np.dtype(dtype)
    if dtype.kind in 'iu':
        limits = np.iinfo(dtype)
        return np.clip(np.rint(values), limits.min, limits.max).astype(dtype)
    return np.asarray(values).astype(dtype)


def _dropped(what, why, stacklevel=3):
    warnings.warn('%s: %s, so dropped (it would be stale after fairing)' % (what, why), UserWarning,
                  stacklevel=stacklevel)


def fair_meshio(mesh, *, attributes=(), **parameters):
    """Fairs a ``meshio.Mesh`` of triangles; returns ``(faired_mesh, report)``.

    ``attributes``: names of ``mesh.point_data`` arrays (N or N x k values) faired with the surface, as
    :func:`fair`'s attributes; the faired mesh has the same cells, point order and data, these arrays
    replaced by their faired values. Vertex normals in the point data (``obj:vn`` of an OBJ file,
    ``nx``/``ny``/``nz`` of a PLY file, arrays named ``normals`` or ``Normals``) are recomputed for the
    faired surface, as the program does, and face normals in the cell data (``facet_normals`` of an STL
    file) too; one of these names whose array is not one 3-vector per point (or cell) is dropped with a
    warning. ``parameters``: :func:`fair`'s keyword parameters. The input mesh is not modified. Raises
    ValueError for cells that are not triangles, points that are not 3-D and names that are not point data.
    """
    import meshio
    others = sorted({block.type for block in mesh.cells} - {'triangle'})
    if others:
        raise ValueError('fair_meshio fairs triangle meshes; this mesh also has cells of type %s' % ', '.join(others))
    points = np.asarray(mesh.points, dtype=float)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError('fair_meshio needs 3-D points, not an array of shape %s' % (points.shape,))
    F = np.vstack([block.data for block in mesh.cells]) if mesh.cells else np.zeros((0, 3), dtype=np.int64)
    names = [attributes] if isinstance(attributes, str) else list(attributes)
    missing = [name for name in names if name not in mesh.point_data]
    if missing:
        raise ValueError('not point data of the mesh: %s (it has: %s)'
                         % (', '.join(missing), ', '.join(sorted(mesh.point_data)) or 'none'))
    n = len(points)
    # the normals, unless faired as attributes: single arrays, triples of 1-D arrays, face normals
    normals = [name for name in mesh.point_data if name.lower() in _NORMAL_NAMES and name not in names]
    triples = [triple for triple in _NORMAL_TRIPLES
               if all(c in mesh.point_data for c in triple) and not any(c in names for c in triple)]
    face_normals = [name for name in mesh.cell_data if name.lower() in _FACE_NORMAL_NAMES and name not in names]
    columns = [np.asarray(mesh.point_data[name], dtype=float).reshape(n, -1) for name in names]
    A = np.hstack(columns) if columns else None
    V2, A2, report, N2 = _fair(points, F, A, parameters, vertex_normals=bool(normals or triples or face_normals))
    point_data = {name: np.array(values, copy=True) for name, values in mesh.point_data.items()}
    first = 0
    for name, block in zip(names, columns):
        values = A2[:, first:first + block.shape[1]]
        point_data[name] = values.reshape(np.shape(mesh.point_data[name]))
        first += block.shape[1]
    geometry_faired = report['mode'] != 'attributes'
    for name in normals:
        if np.shape(point_data[name]) != (n, 3):
            del point_data[name]
            _dropped("point data '%s' (vertex normals)" % name,
                     'it is an array of shape %s, not one normal per point (%d x 3)'
                     % (np.shape(mesh.point_data[name]), n))
        elif N2 is not None:
            point_data[name] = _as_type(N2, point_data[name].dtype)
    for triple in triples:
        if any(np.shape(point_data[c]) != (n,) for c in triple):
            for c in triple:
                del point_data[c]
            _dropped("point data %s (vertex normals)" % '/'.join(triple), 'they are not one value per point each')
        elif N2 is not None:
            for k, c in enumerate(triple):
                point_data[c] = _as_type(N2[:, k], point_data[c].dtype)
    cell_data = {name: [np.array(d, copy=True) for d in data] for name, data in mesh.cell_data.items()}
    for name in face_normals:
        blocks = cell_data[name]
        if len(blocks) != len(mesh.cells) or any(np.shape(d) != (len(c.data), 3) for d, c in zip(blocks, mesh.cells)):
            del cell_data[name]
            _dropped("cell data '%s' (face normals)" % name, 'it is not one normal per triangle')
        elif geometry_faired:
            cell_data[name] = [_as_type(_face_normals(V2, np.asarray(c.data)), d.dtype)
                               for d, c in zip(blocks, mesh.cells)]
    cells = [(block.type, np.array(block.data, copy=True)) for block in mesh.cells]
    faired = meshio.Mesh(V2, cells, point_data=point_data, cell_data=cell_data, field_data=dict(mesh.field_data))
    return faired, report


def fair_open3d(mesh, *, colours=True, **parameters):
    """Fairs an Open3D ``TriangleMesh``; returns ``(faired_mesh, report)``.

    With ``colours`` (and a mesh that has vertex colours), the colours are faired with the surface as
    three attributes (in :func:`fair`'s ``attribute_mode``, by default each on its own) and clipped to
    [0, 1], Open3D's range. The faired mesh is a copy of the input with the faired positions (and colours):
    the same triangles and vertex order, texture coordinates (``triangle_uvs``), ``textures`` and
    ``triangle_material_ids`` kept; its vertex normals, if the input had them, are those of the faired
    surface as the program writes them, its triangle normals recomputed. ``parameters``: :func:`fair`'s
    keyword parameters. The input mesh is not modified.
    """
    import open3d
    if not isinstance(mesh, open3d.geometry.TriangleMesh):
        raise TypeError('fair_open3d fairs an open3d.geometry.TriangleMesh, not a %s (a tensor mesh: mesh.to_legacy())'
                        % type(mesh).__name__)
    V = np.asarray(mesh.vertices, dtype=float)
    F = np.asarray(mesh.triangles, dtype=np.int64)
    C = np.asarray(mesh.vertex_colors, dtype=float) if colours and mesh.has_vertex_colors() else None
    V2, C2, report, N2 = _fair(V, F, C, parameters, vertex_normals=mesh.has_vertex_normals())
    faired = open3d.geometry.TriangleMesh(mesh)   # a copy: triangles, texture coordinates, textures, material ids, ...
    faired.vertices = open3d.utility.Vector3dVector(V2)
    if C2 is not None:
        faired.vertex_colors = open3d.utility.Vector3dVector(np.clip(C2, 0.0, 1.0))
    if N2 is not None:
        faired.vertex_normals = open3d.utility.Vector3dVector(N2)
    if mesh.has_triangle_normals():   # (not compute_triangle_normals(), which normalises the vertex normals again)
        faired.triangle_normals = open3d.utility.Vector3dVector(_face_normals(V2, F))
    if mesh.has_triangle_uvs() and len(mesh.triangle_uvs) != 3 * len(F):
        warnings.warn('the mesh has %d texture coordinates (triangle_uvs), not 3 per triangle (%d): kept as they are, '
                      'though Open3D will not use them' % (len(mesh.triangle_uvs), 3 * len(F)),
                      UserWarning, stacklevel=2)
    return faired, report


def fair_vtk(mesh, *, attributes=(), **parameters):
    """Fairs a VTK ``vtkPolyData`` (a PyVista ``PolyData`` too); returns ``(faired_mesh, report)``.

    ``attributes``: names of point-data arrays (any number of components, any numeric type) faired with
    the surface, as :func:`fair`'s attributes, and written back in their own type (integers rounded and
    clamped to their range, as the program does). The faired mesh is a new object of the input's class
    (a ``pyvista.PolyData`` for one) with the input's points (in their own precision: float32 for most VTK
    readers), cells, point, cell and field data, the positions and the attributes named replaced by their
    faired values. Vertex normals (the active normals of the point data, or arrays named ``Normals``) are
    those of the faired surface, as the program writes them, and face normals in the cell data recomputed.
    Polygons that are not triangles and triangle strips are triangulated (by ``vtkTriangleFilter``; the
    program uses CGAL's ``triangulate_faces``) with a warning, and come back as triangles, each polygon's
    cell data copied to its triangles. Vertices and lines (``GetVerts``, ``GetLines``) are carried over
    (split into single vertices and segments when the polygons are triangulated); a point on none of the
    triangles stays where it is. ``parameters``: :func:`fair`'s keyword parameters. The input is not
    modified. Raises TypeError for what is not a ``vtkPolyData``, ValueError for a mesh without polygons
    and names that are not point-data arrays.
    """
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    names = _vtk_names(mesh, attributes)
    source = _vtk_triangles(mesh)
    try:
        faired = type(mesh)()
    except Exception:   # a subclass that wants arguments
        faired = vtkPolyData()
    faired.DeepCopy(source)
    polys = faired.GetPolys()
    if polys.GetNumberOfCells() == 0:
        raise ValueError('fair_vtk fairs a surface: no triangle is left of the polygons of this vtkPolyData')
    F = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64).reshape(-1, 3)
    points = vtk_to_numpy(faired.GetPoints().GetData())   # the copy's: written in place, in its own type
    V = points.astype(float)
    n = len(V)
    columns = [vtk_to_numpy(faired.GetPointData().GetArray(name)).astype(float).reshape(n, -1) for name in names]
    A = np.hstack(columns) if columns else None
    point_normals = _vtk_normals(faired.GetPointData(), n, 'point', names)
    cell_normals = _vtk_normals(faired.GetCellData(), faired.GetNumberOfCells(), 'cell', names)
    V2, A2, report, N2 = _fair(V, F, A, parameters, vertex_normals=bool(point_normals or cell_normals))

    points[:] = V2
    faired.GetPoints().Modified()
    first = 0
    for name, block in zip(names, columns):
        target = vtk_to_numpy(faired.GetPointData().GetArray(name))
        target[:] = _as_type(A2[:, first:first + block.shape[1]].reshape(target.shape), target.dtype)
        faired.GetPointData().GetArray(name).Modified()
        first += block.shape[1]
    faired_geometry = report['mode'] != 'attributes'
    _vtk_write_normals(faired, point_normals, cell_normals, N2 if faired_geometry else None,
                       _face_normals(V2, F) if faired_geometry and cell_normals else None)
    faired.Modified()
    return faired, report


def _vtk_names(mesh, attributes):
    """fair_vtk's attribute names, each a point-data array of the mesh, which must have polygons"""
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    if not isinstance(mesh, vtkPolyData):
        raise TypeError('fair_vtk fairs a vtkPolyData (or a pyvista.PolyData), not a %s' % type(mesh).__name__)
    names = [attributes] if isinstance(attributes, str) else list(attributes)
    point_data = mesh.GetPointData()
    missing = [name for name in names if point_data.GetArray(name) is None]
    if missing:
        arrays = sorted(point_data.GetArrayName(i) or '' for i in range(point_data.GetNumberOfArrays()))
        raise ValueError('not point-data arrays of the mesh: %s (it has: %s)'
                         % (', '.join(missing), ', '.join(arrays) or 'none'))
    if mesh.GetNumberOfPolys() + mesh.GetNumberOfStrips() == 0:
        raise ValueError('fair_vtk fairs a surface: this vtkPolyData has no polygon '
                         '(%d points, %d vertex and %d line cells)'
                         % (mesh.GetNumberOfPoints(), mesh.GetNumberOfVerts(), mesh.GetNumberOfLines()))
    return names


def _vtk_triangles(mesh):
    """the triangles of fair_vtk's mesh: its polygons as they are, or triangulated as a copy (with a warning
    for fair_vtk's caller)"""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter
    polys = mesh.GetPolys()
    sizes = np.diff(vtk_to_numpy(polys.GetOffsetsArray())) if mesh.GetNumberOfPolys() else np.zeros(0, dtype=int)
    polygons, strips = int(np.count_nonzero(sizes != 3)), mesh.GetNumberOfStrips()
    if not polygons and not strips:
        return mesh
    triangulate = vtkTriangleFilter()
    triangulate.SetInputData(mesh)
    triangulate.PassVertsOn()
    triangulate.PassLinesOn()
    triangulate.Update()
    warnings.warn('%d polygons of the vtkPolyData are not triangles%s: triangulated (vtkTriangleFilter) and given back '
                  'as triangles, their cell data copied to each triangle' %
                  (polygons, ' and %d are triangle strips' % strips if strips else ''), UserWarning, stacklevel=3)
    return triangulate.GetOutput()


def _vtk_normals(data, count, per, names):
    """the 3-component arrays of `data` that are its normals: the active ones, or named so (the name of one
    that is not one 3-vector per `per`, which is dropped, with a warning for fair_vtk's caller); not the
    attributes `names`"""
    from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
    found = []
    for i in range(data.GetNumberOfArrays()):
        array = data.GetArray(i)
        named = (data.GetArrayName(i) or '').lower() in ('normals', 'normal')
        if array is not None and (data.IsArrayAnAttribute(i) == vtkDataSetAttributes.NORMALS or named) and \
           data.GetArrayName(i) not in names:
            if array.GetNumberOfComponents() == 3 and array.GetNumberOfTuples() == count:
                found.append(array)
            else:
                _dropped("the normals '%s' of the vtkPolyData" % data.GetArrayName(i),
                         'they are not one 3-vector per ' + per, stacklevel=4)
                found.append(data.GetArrayName(i))
    return found


def _vtk_write_normals(faired, point_normals, cell_normals, N2, face_normals):
    """the faired normals into fair_vtk's copy (None: the geometry was not faired, the input's are kept);
    the names of normals that could not be kept are removed"""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    for data, arrays, per_point in ((faired.GetPointData(), point_normals, True),
                                    (faired.GetCellData(), cell_normals, False)):
        for array in arrays:
            if isinstance(array, str):
                data.RemoveArray(array)
            elif N2 is not None:
                target = vtk_to_numpy(array)
                if per_point:
                    target[:] = _as_type(N2, target.dtype)
                else:   # the triangles' cells come after the vertices' and the lines'
                    start = faired.GetNumberOfVerts() + faired.GetNumberOfLines()
                    target[start:start + len(face_normals)] = _as_type(face_normals, target.dtype)
                array.Modified()
