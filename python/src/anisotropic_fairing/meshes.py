"""Meshes of other Python libraries in and out of :func:`anisotropic_fairing.fair`: a ``meshio.Mesh``
(Debian: python3-meshio; any file format meshio reads) and an Open3D ``TriangleMesh`` with its vertex
colours (Debian: python3-open3d). Each library is imported only when its function is called.
"""
import numpy as np

__all__ = ['fair_meshio', 'fair_open3d']


def _fair(V, F, attributes, parameters):
    from . import fair
    return fair(V, F, attributes=attributes, **parameters)


def fair_meshio(mesh, *, attributes=(), **parameters):
    """Fairs a ``meshio.Mesh`` of triangles; returns ``(faired_mesh, report)``.

    ``attributes``: names of ``mesh.point_data`` arrays (N or N x k values) faired with the surface, as
    :func:`fair`'s attributes; the faired mesh has the same cells, point order and data, these arrays
    replaced by their faired values. ``parameters``: :func:`fair`'s keyword parameters. The input mesh is
    not modified. Raises ValueError for cells that are not triangles, points that are not 3-D and names
    that are not point data.
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
        raise ValueError('not point data of the mesh: %s (it has: %s)' % (', '.join(missing), ', '.join(sorted(mesh.point_data)) or 'none'))
    columns = [np.asarray(mesh.point_data[name], dtype=float).reshape(len(points), -1) for name in names]
    A = np.hstack(columns) if columns else None
    V2, A2, report = _fair(points, F, A, parameters)
    point_data = {name: np.array(values, copy=True) for name, values in mesh.point_data.items()}
    first = 0
    for name, block in zip(names, columns):
        values = A2[:, first:first + block.shape[1]]
        point_data[name] = values.reshape(np.shape(mesh.point_data[name]))
        first += block.shape[1]
    faired = meshio.Mesh(V2, [(block.type, np.array(block.data, copy=True)) for block in mesh.cells], point_data=point_data,
                         cell_data={name: [np.array(d, copy=True) for d in data] for name, data in mesh.cell_data.items()},
                         field_data=dict(mesh.field_data))
    return faired, report


def fair_open3d(mesh, *, colours=True, **parameters):
    """Fairs an Open3D ``TriangleMesh``; returns ``(faired_mesh, report)``.

    With ``colours`` (and a mesh that has vertex colours), the colours are faired with the surface as
    three attributes (in :func:`fair`'s ``attribute_mode``, by default each on its own) and clipped to
    [0, 1], Open3D's range. The faired mesh has the same triangles and vertex order; its vertex normals, if
    the input had them, are recomputed. ``parameters``: :func:`fair`'s keyword parameters. The input mesh
    is not modified.
    """
    import open3d
    V = np.asarray(mesh.vertices, dtype=float)
    F = np.asarray(mesh.triangles, dtype=np.int64)
    C = np.asarray(mesh.vertex_colors, dtype=float) if colours and mesh.has_vertex_colors() else None
    V2, C2, report = _fair(V, F, C, parameters)
    faired = open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(V2), open3d.utility.Vector3iVector(F.astype(np.int32)))
    if mesh.has_vertex_colors():
        kept = np.clip(C2, 0.0, 1.0) if C2 is not None else np.asarray(mesh.vertex_colors)
        faired.vertex_colors = open3d.utility.Vector3dVector(kept)
    if mesh.has_vertex_normals():
        faired.compute_vertex_normals()
    return faired, report
