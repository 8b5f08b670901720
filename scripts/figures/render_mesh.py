#!/usr/bin/python3
"""Renders triangle meshes side by side into one PNG with VTK (Debian's python3-vtk9).

    /usr/bin/python3 render_mesh.py --output FILE.png [--title T]... [--size WxH] [--scalar NAME]
                                    [--range LO HI] [--view AZIMUTH,ELEVATION] [--up X,Y,Z] [--edges]
                                    MESH [MESH...]

One panel per mesh (the n-th --title is its title), all seen by one camera fitted to the first mesh so
that they line up; flat shading (one normal per face), so that noise shows as it is. --scalar NAME
colours the meshes that have the vertex property NAME (PLY: quality, mean_curvature, ...) on one scale
with a colour bar; per-vertex colours of a file are shown otherwise. Reads OFF (colours, texture
coordinates), OBJ (v, vt, f), PLY (ascii and binary, every vertex property) and STL. Without a display
it runs itself again under `xvfb-run -a`. Exit status 0 with the PNG written, 1 with one line on stderr.
make_figures.py imports it: read_mesh(), Panel and render_panels() are the module's interface.
"""
import os
import shutil
import subprocess
import sys

try:
    import numpy as np
except ImportError:
    sys.stderr.write("render_mesh.py: numpy is missing: install python3-numpy, python3-vtk9 and xvfb "
                     "(and run Debian's /usr/bin/python3)\n")
    sys.exit(1)

_XVFB_MARK = "AF_RENDER_UNDER_XVFB"


def fail(message):
    sys.stderr.write("render_mesh.py: %s\n" % message)
    sys.exit(1)


def ensure_display():
    """Runs the current script again under xvfb-run when there is no X display (VTK aborts without one)."""
    if os.environ.get("DISPLAY") or os.environ.get(_XVFB_MARK):
        return
    xvfb = shutil.which("xvfb-run")
    if xvfb is None:
        fail("no display and no xvfb-run: install python3-vtk9 and xvfb (apt-get install python3-vtk9 xvfb xauth)")
    env = dict(os.environ, **{_XVFB_MARK: "1"})
    command = [xvfb, "-a", "-s", "-screen 0 2560x1600x24", sys.executable] + sys.argv
    sys.exit(subprocess.call(command, env=env))


def import_vtk():
    try:
        import vtkmodules.all as vtk   # every module, the OpenGL back end and the text renderer included
    except ImportError:
        fail("VTK's Python bindings are missing: install python3-vtk9 and xvfb (and run Debian's /usr/bin/python3)")
    return vtk


# ---------------------------------------------------------------- reading
# A mesh is a dict: points (n,3) float, faces (list of int arrays, or an (m,k) int array),
# point_data {name: (n,) array}, colors (n,3) uint8 or None, uv (n,2) or None.

def new_mesh(points, faces, point_data=None, colors=None, uv=None):
    return {"points": np.asarray(points, dtype=float), "faces": faces, "point_data": point_data or {},
            "colors": colors, "uv": uv}


def _as_rgb(values):
    values = np.asarray(values, dtype=float)
    if values.size and values.max() <= 1.0:   # colours in [0,1]
        values = values * 255.0
    return np.clip(np.rint(values), 0, 255).astype(np.uint8)


def _data_lines(path):
    with open(path, "r", errors="replace") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                yield line


def read_off(path):
    """OFF with the ST/C/N prefixes: vertex lines x y z [nx ny nz] [r g b [a]] [s t]."""
    lines = _data_lines(path)
    header = next(lines).split()
    keyword = header[0]
    if not keyword.endswith("OFF"):
        raise ValueError("%s: not an OFF file" % path)
    counts = header[1:] if len(header) > 1 else next(lines).split()
    nv, nf = int(counts[0]), int(counts[1])
    has_colors, has_uv = "C" in keyword[:-3], "ST" in keyword[:-3]
    rows = [next(lines).split() for _ in range(nv)]
    points = np.array([[float(x) for x in r[:3]] for r in rows])
    colors = uv = None
    if has_colors or has_uv:
        extra = [r[6 if "N" in keyword[:-3] else 3:] for r in rows]   # after the position and the normal
        if has_uv:
            uv = np.array([[float(x) for x in e[-2:]] for e in extra])
            extra = [e[:-2] for e in extra]
        if has_colors and all(len(e) >= 3 for e in extra):
            colors = _as_rgb([[float(x) for x in e[:3]] for e in extra])
    rows = [next(lines).split() for _ in range(nf)]
    faces = [np.array(r[1:1 + int(r[0])], dtype=np.int64) for r in rows]
    return new_mesh(points, faces, colors=colors, uv=uv)


def read_obj(path):
    """OBJ: v (with optional r g b), vt and f (v, v/t, v/t/n, v//n; negative indices); one uv per vertex."""
    points, colors, texcoords, faces, vt_of = [], [], [], [], {}
    for line in _data_lines(path):
        tokens = line.split()
        if tokens[0] == "v":
            points.append([float(x) for x in tokens[1:4]])
            if len(tokens) >= 7:
                colors.append([float(x) for x in tokens[4:7]])
        elif tokens[0] == "vt":
            texcoords.append([float(x) for x in tokens[1:3]])
        elif tokens[0] == "f":
            face = []
            for corner in tokens[1:]:
                parts = corner.split("/")
                v = int(parts[0])
                v = v - 1 if v > 0 else len(points) + v
                face.append(v)
                if len(parts) > 1 and parts[1]:
                    t = int(parts[1])
                    vt_of[v] = t - 1 if t > 0 else len(texcoords) + t
            faces.append(np.array(face, dtype=np.int64))
    uv = None
    if texcoords and vt_of:
        uv = np.zeros((len(points), 2))
        for v, t in vt_of.items():
            uv[v] = texcoords[t]
    return new_mesh(points, faces, colors=_as_rgb(colors) if len(colors) == len(points) and colors else None, uv=uv)


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def _ply_header(f):
    if f.readline().strip() != b"ply":
        raise ValueError("not a PLY file")
    form, elements = None, []
    while True:
        line = f.readline()
        if not line:
            raise ValueError("PLY header without end_header")
        tokens = line.decode("ascii", "replace").split()
        if not tokens:
            continue
        if tokens[0] == "format":
            form = tokens[1]
        elif tokens[0] == "element":
            elements.append((tokens[1], int(tokens[2]), []))
        elif tokens[0] == "property":
            if tokens[1] == "list":   # (name, count type, item type)
                elements[-1][2].append((tokens[4], _PLY_TYPES[tokens[2]], _PLY_TYPES[tokens[3]]))
            else:
                elements[-1][2].append((tokens[2], None, _PLY_TYPES[tokens[1]]))
        elif tokens[0] == "end_header":
            return form, elements


def _ply_binary_rows(data, offset, count, properties, endian):
    """One element of a binary PLY at numpy speed, when it has at most one list and that list has the same
    length in every row (triangles: the usual case); None otherwise."""
    lists = [p for p in properties if p[1] is not None]
    if len(lists) > 1:
        return None
    k, first = 0, 0
    if lists and count:
        for _, c, t in properties:   # the byte position of the list's count in the first row
            if c is not None:
                break
            first += np.dtype(t).itemsize
        k = int(np.frombuffer(data, endian + lists[0][1], 1, offset + first)[0])
    dtype = np.dtype(sum(([(n, endian + t)] if c is None else [(n + "#count", endian + c), (n, endian + t, (k,))]
                          for n, c, t in properties), []))
    if offset + dtype.itemsize * count > len(data):
        return None
    rows = np.frombuffer(data, dtype=dtype, count=count, offset=offset)
    if lists and not np.all(rows[lists[0][0] + "#count"] == k):
        return None
    return {n: rows[n] for n, _, _ in properties}, offset + dtype.itemsize * count


def _ply_binary_loop(data, offset, count, properties, endian):
    """One element of a binary PLY row by row (lists of varying length: polygons, strips)."""
    columns = {n: [] for n, _, _ in properties}
    for _ in range(count):
        for name, count_type, item_type in properties:
            if count_type is None:
                columns[name].append(np.frombuffer(data, endian + item_type, 1, offset)[0])
                offset += np.dtype(item_type).itemsize
            else:
                k = int(np.frombuffer(data, endian + count_type, 1, offset)[0])
                offset += np.dtype(count_type).itemsize
                columns[name].append(np.frombuffer(data, endian + item_type, k, offset).astype(np.int64))
                offset += k * np.dtype(item_type).itemsize
    return {n: (np.array(columns[n]) if c is None else columns[n]) for n, c, _ in properties}, offset


def _strips_to_triangles(strips):
    """Triangle strips (-1 restarts a strip) as triangles, every other one turned to keep the orientation."""
    triangles = []
    for strip in strips:
        for run in np.split(strip, np.flatnonzero(strip < 0)):
            run = run[run >= 0]
            for i in range(len(run) - 2):
                a, b, c = run[i:i + 3] if i % 2 == 0 else (run[i + 1], run[i], run[i + 2])
                if a != b and b != c and a != c:
                    triangles.append(np.array([a, b, c], dtype=np.int64))
    return triangles


def read_ply(path):
    with open(path, "rb") as f:
        form, elements = _ply_header(f)
        body = f.read()
    tables = {}
    if form == "ascii":
        tokens = body.split()
        at = 0
        for name, count, properties in elements:
            columns = {n: [] for n, _, _ in properties}
            for _ in range(count):
                for n, c, _ in properties:
                    if c is None:
                        columns[n].append(float(tokens[at]))
                        at += 1
                    else:
                        k = int(tokens[at])
                        columns[n].append(np.array(tokens[at + 1:at + 1 + k], dtype=np.int64))
                        at += 1 + k
            tables[name] = {n: (np.array(columns[n]) if c is None else columns[n]) for n, c, _ in properties}
    else:
        endian = "<" if form == "binary_little_endian" else ">"
        offset = 0
        for name, count, properties in elements:
            tables[name], offset = (_ply_binary_rows(body, offset, count, properties, endian)
                                    or _ply_binary_loop(body, offset, count, properties, endian))
    vertex = tables.get("vertex", {})
    points = np.column_stack([vertex[c] for c in ("x", "y", "z")]).astype(float)
    faces = []
    if "face" in tables:
        face = tables["face"]
        faces = face.get("vertex_indices", face.get("vertex_index"))
        faces = faces.astype(np.int64) if isinstance(faces, np.ndarray) else list(faces)
    if "tristrips" in tables:
        faces = list(faces) + _strips_to_triangles(tables["tristrips"]["vertex_indices"])
    colors = None
    if all(c in vertex for c in ("red", "green", "blue")):
        rgb = np.column_stack([vertex[c] for c in ("red", "green", "blue")])
        colors = _as_rgb(rgb) if rgb.dtype.kind == "f" else np.clip(rgb, 0, 255).astype(np.uint8)
    uv = None
    for su, sv in (("s", "t"), ("u", "v"), ("texture_u", "texture_v")):
        if su in vertex and sv in vertex:
            uv = np.column_stack([vertex[su], vertex[sv]]).astype(float)
    point_data = {n: np.asarray(a, dtype=float) for n, a in vertex.items()
                  if n not in ("x", "y", "z") and isinstance(a, np.ndarray) and a.ndim == 1}
    return new_mesh(points, faces, point_data=point_data, colors=colors, uv=uv)


def read_stl(path):
    """ASCII or binary STL; the corners of the triangles that coincide are merged into one vertex."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:5].lower() == b"solid" and b"facet" in data[:1024]:
        corners = np.array([line.split()[1:4] for line in data.decode("ascii", "replace").splitlines()
                            if line.strip().startswith("vertex")], dtype=float)
    else:
        count = int(np.frombuffer(data, "<u4", 1, 80)[0])
        rows = np.frombuffer(data, np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]), count, 84)
        corners = rows["v"].reshape(-1, 3).astype(float)
    points, index = np.unique(corners, axis=0, return_inverse=True)
    return new_mesh(points, index.reshape(-1, 3).astype(np.int64))


def read_mesh(path):
    if not os.path.isfile(path):
        raise ValueError("%s: no such file" % path)
    extension = os.path.splitext(path)[1].lower()
    readers = {".off": read_off, ".obj": read_obj, ".ply": read_ply, ".stl": read_stl}
    if extension not in readers:
        raise ValueError("%s: unknown mesh format (OFF, OBJ, PLY or STL)" % path)
    try:
        return readers[extension](path)
    except StopIteration:
        raise ValueError("%s: the file ends early" % path)
    except (IndexError, KeyError, TypeError, ValueError) as error:
        raise ValueError("%s: cannot read it as %s (%s)" % (path, extension[1:].upper(), error or type(error).__name__))


def face_array(mesh):
    """The faces as an (m,3) array when the mesh has only triangles, else None."""
    faces = mesh["faces"]
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        return faces
    if faces and all(len(f) == 3 for f in faces):
        return np.array(faces, dtype=np.int64)
    return None


def to_polydata(mesh, scalars=None):
    """vtkPolyData of the mesh; `scalars`: a per-vertex array set as the active point scalars."""
    vtk = import_vtk()
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    polydata = vtk.vtkPolyData()
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(mesh["points"], dtype=float), deep=True))
    polydata.SetPoints(points)
    triangles = face_array(mesh)   # cells: the corner count, then the corners, face after face
    cells = (np.hstack([np.full((len(triangles), 1), 3), triangles]).ravel() if triangles is not None else
             np.concatenate([np.concatenate([[len(f)], f]) for f in mesh["faces"]])).astype(np.int64)
    polys = vtk.vtkCellArray()
    polys.SetCells(len(mesh["faces"]), numpy_to_vtkIdTypeArray(cells, deep=True))
    polydata.SetPolys(polys)
    def array(values, dtype):
        return numpy_to_vtk(np.ascontiguousarray(values, dtype=dtype), deep=True)
    if scalars is not None:
        polydata.GetPointData().SetScalars(array(scalars, float))
    elif mesh.get("colors") is not None:
        polydata.GetPointData().SetScalars(array(mesh["colors"], np.uint8))
    if mesh.get("uv") is not None:
        polydata.GetPointData().SetTCoords(array(mesh["uv"], float))
    return polydata


class Panel:
    """One viewport: a mesh (dict or file name) with how to show it.

    scalars: a vertex property name or a per-vertex array, coloured through the figure's colour map;
    contours: iso-values (or a count) of the scalars drawn as black lines; texture: an (h,w,3) uint8
    image mapped through the mesh's uv; edges: draw the mesh edges (in edge_color; a lighter one keeps a
    fine mesh from turning dark); color: the surface's RGB in [0,1].
    """

    def __init__(self, mesh, title="", scalars=None, contours=None, texture=None, edges=False,
                 color=(0.80, 0.82, 0.86), edge_color=(0.15, 0.15, 0.2)):
        self.mesh = read_mesh(mesh) if isinstance(mesh, str) else mesh
        self.title, self.scalars, self.contours, self.texture = title, scalars, contours, texture
        self.edges, self.edge_color, self.color = edges, edge_color, color

    def scalar_values(self):
        data = self.mesh["point_data"]
        if isinstance(self.scalars, str) and self.scalars not in data:
            raise ValueError("no vertex property '%s' (the mesh has: %s)" % (self.scalars, ", ".join(sorted(data)) or "none"))
        return data[self.scalars] if isinstance(self.scalars, str) else \
            None if self.scalars is None else np.asarray(self.scalars, dtype=float)


def lookup_table(value_range, colormap="viridis", n=256):
    """A colour map as a vtkLookupTable: 'viridis' (sequential), 'coolwarm' (diverging) or 'pastel'."""
    vtk = import_vtk()
    stops = {
        "viridis": [(0.0, (0.267, 0.005, 0.329)), (0.25, (0.230, 0.322, 0.546)), (0.5, (0.128, 0.567, 0.551)),
                    (0.75, (0.369, 0.789, 0.383)), (1.0, (0.993, 0.906, 0.144))],
        "coolwarm": [(0.0, (0.230, 0.299, 0.754)), (0.5, (0.865, 0.865, 0.865)), (1.0, (0.706, 0.016, 0.150))],
        "pastel": [(0.0, (0.55, 0.70, 0.95)), (0.5, (0.95, 0.95, 0.85)), (1.0, (0.98, 0.65, 0.55))],
    }[colormap]
    transfer = vtk.vtkColorTransferFunction()
    for t, rgb in stops:
        transfer.AddRGBPoint(t, *rgb)
    table = vtk.vtkLookupTable()
    table.SetNumberOfTableValues(n)
    for i in range(n):
        table.SetTableValue(i, *transfer.GetColor((i + 0.5) / n), 1.0)
    table.SetRange(*value_range)
    table.Build()
    return table


def _texture(image):
    vtk = import_vtk()
    from vtkmodules.util.numpy_support import numpy_to_vtk
    image = np.ascontiguousarray(np.flipud(image)[:, :, :3], dtype=np.uint8)   # VTK's rows go up
    data = vtk.vtkImageData()
    data.SetDimensions(image.shape[1], image.shape[0], 1)
    array = numpy_to_vtk(image.reshape(-1, 3), deep=True)
    array.SetNumberOfComponents(3)
    data.GetPointData().SetScalars(array)
    texture = vtk.vtkTexture()
    texture.SetInputData(data)
    texture.InterpolateOff()   # crisp checker edges
    texture.RepeatOn()
    return texture


def _lights(renderer):
    """Lights that move with the camera: a soft headlight, a key light above left of the viewer and a weak
    fill from the right, so that faces turned away from the key are not black."""
    vtk = import_vtk()
    renderer.AutomaticLightCreationOff()
    for position, intensity in (((0.0, 0.0, 1.0), 0.45), ((-1.0, 1.2, 1.0), 0.6), ((1.5, -0.3, 0.6), 0.2)):
        light = vtk.vtkLight()
        light.SetLightTypeToCameraLight()
        light.SetPosition(*position)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        light.SetIntensity(intensity)
        renderer.AddLight(light)


def _mesh_actors(panel, table):
    vtk = import_vtk()
    values = panel.scalar_values()
    polydata = to_polydata(panel.mesh, values)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(polydata)
    mapper.SetResolveCoincidentTopologyToPolygonOffset()   # contour lines and edges stay in front
    if values is not None:
        mapper.SetLookupTable(table)
        mapper.UseLookupTableScalarRangeOn()
    elif panel.mesh.get("colors") is not None:
        mapper.SetColorModeToDirectScalars()
    else:
        mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetInterpolationToFlat()   # one normal per face: noise is not smoothed away by the shading
    prop.SetColor(*panel.color)
    prop.SetAmbient(0.2)
    prop.SetDiffuse(0.85)
    prop.SetSpecular(0.15)
    prop.SetSpecularPower(25)
    if panel.edges:
        prop.EdgeVisibilityOn()
        prop.SetEdgeColor(*panel.edge_color)
        prop.SetLineWidth(1.0)
    if panel.texture is not None:
        actor.SetTexture(_texture(panel.texture))
        mapper.ScalarVisibilityOff()
        prop.SetColor(1, 1, 1)
    actors = [actor]
    if panel.contours is not None and values is not None:
        contour = vtk.vtkContourFilter()
        contour.SetInputData(polydata)
        levels = np.linspace(values.min(), values.max(), int(panel.contours)) if np.isscalar(panel.contours) \
            else panel.contours
        for i, value in enumerate(levels):
            contour.SetValue(i, float(value))
        lines = vtk.vtkPolyDataMapper()
        lines.SetInputConnection(contour.GetOutputPort())
        lines.ScalarVisibilityOff()
        lines.SetResolveCoincidentTopologyToPolygonOffset()
        actors.append(vtk.vtkActor())
        actors[-1].SetMapper(lines)
        style = actors[-1].GetProperty()
        style.SetColor(0.05, 0.05, 0.05)
        style.SetLineWidth(1.6)
        style.LightingOff()
    return actors


def robust_range(arrays, low=2.0, high=98.0):
    """The [low, high] percentiles of the values of all arrays: outliers do not flatten the colours."""
    values = np.concatenate([np.asarray(a, dtype=float).ravel() for a in arrays])
    lo, hi = np.percentile(values, [low, high])
    return (float(lo), float(hi) if hi > lo else float(lo) + 1e-12)


def render_panels(panels, output, size=(2000, 700), view=(25.0, 20.0), scalar_range=None, colormap="viridis",
                  colorbar_title=None, zoom=1.0, up=(0.0, 1.0, 0.0)):
    """Renders the panels side by side into the PNG `output`.

    One camera for all, fitted to the first panel's mesh, seen from the direction that is the +z axis
    turned by `view` = (azimuth, elevation) degrees with `up` the view-up. Panels with scalars share
    `scalar_range` (default: the robust range of all) and one colour bar on the right.
    """
    vtk = import_vtk()
    width, height = size
    scalar_panels = [p for p in panels if p.scalars is not None]
    table = None
    if scalar_panels:
        if scalar_range is None:
            scalar_range = robust_range([p.scalar_values() for p in scalar_panels])
        table = lookup_table(scalar_range, colormap)
    bar_width = 0.075 * (2000.0 / width) * (height / 700.0) ** 0.5 if table is not None and colorbar_title != "" else 0.0
    columns = len(panels)
    band = min(0.16, 0.075 * (700.0 / height) * (1 + max(p.title.count("\n") for p in panels)))   # the titles'
    # one font size for all titles, small enough that the longest line fits its panel (~0.55 em a glyph)
    longest = max(len(line) for p in panels for line in (p.title or " ").split("\n"))
    font = max(8, min(int(round(min(height * 0.045, width / columns * 0.04))) + 6,
                      int(0.95 * width * (1.0 - 0.08) / columns / (0.55 * longest))))
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    window.SetMultiSamples(8)
    camera = vtk.vtkCamera()
    for column, panel in enumerate(panels):
        x0, x1 = (1.0 - bar_width) * column / columns, (1.0 - bar_width) * (column + 1) / columns
        renderer = vtk.vtkRenderer()
        renderer.SetViewport(x0, 0.0, x1, 1.0 - band)
        renderer.SetBackground(1, 1, 1)
        renderer.SetActiveCamera(camera)
        _lights(renderer)
        for actor in _mesh_actors(panel, table):
            renderer.AddActor(actor)
        window.AddRenderer(renderer)
        titles = vtk.vtkRenderer()
        titles.SetViewport(x0, 1.0 - band, x1, 1.0)
        titles.SetBackground(1, 1, 1)
        text = vtk.vtkTextActor()
        text.SetInput(panel.title)
        style = text.GetTextProperty()
        style.SetFontSize(font)
        style.SetColor(0.05, 0.05, 0.05)
        style.SetJustificationToCentered()
        style.SetVerticalJustificationToCentered()
        text.SetPosition(0.5 * (x1 - x0) * width, 0.5 * band * height)   # the middle of the title band, in pixels
        titles.AddActor2D(text)
        window.AddRenderer(titles)
    if bar_width > 0:
        bar_renderer = vtk.vtkRenderer()
        bar_renderer.SetViewport(1.0 - bar_width, 0.0, 1.0, 1.0)
        bar_renderer.SetBackground(1, 1, 1)
        bar = vtk.vtkScalarBarActor()
        bar.SetLookupTable(table)
        bar.SetTitle(colorbar_title or (scalar_panels[0].scalars if isinstance(scalar_panels[0].scalars, str) else ""))
        bar.SetNumberOfLabels(5)
        bar.SetLabelFormat("%.3g")
        bar.UnconstrainedFontSizeOn()
        for style in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            style.SetColor(0.05, 0.05, 0.05)
            style.SetFontSize(int(max(font * 0.8, height * 0.024)))
            style.ItalicOff()
            style.ShadowOff()
        title_fit = int(0.95 * bar_width * width / (0.6 * max(1, len(bar.GetTitle()))))   # a long name fits
        bar.GetTitleTextProperty().SetFontSize(min(bar.GetTitleTextProperty().GetFontSize(), title_fit))
        bar.SetPosition(0.04, 0.05)
        bar.SetPosition2(0.92, 0.78)   # width, height
        bar.SetBarRatio(0.28)
        bar.SetVerticalTitleSeparation(int(font * 0.4))
        bar_renderer.AddActor2D(bar)
        window.AddRenderer(bar_renderer)
    # the camera: fitted to the first mesh, looking at it from +z turned by view=(azimuth, elevation)
    low, high = panels[0].mesh["points"].min(axis=0), panels[0].mesh["points"].max(axis=0)
    center = 0.5 * (low + high)
    camera.SetFocalPoint(*center)
    camera.SetPosition(*(center + np.array([0.0, 0.0, 1.0])))
    camera.SetViewUp(*up)
    camera.Azimuth(view[0])
    camera.Elevation(view[1])
    camera.OrthogonalizeViewUp()
    first = window.GetRenderers().GetFirstRenderer()
    first.ResetCamera([float(v) for pair in zip(low, high) for v in pair])   # the clipping range: at each Render
    camera.Zoom(1.25 * zoom)

    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetCompressionLevel(9)   # the figures live in the repository
    writer.SetFileName(output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(description="Render meshes side by side into a PNG with VTK.")
    parser.add_argument("meshes", nargs="+", metavar="MESH", help="OFF, OBJ, PLY or STL files, one panel each")
    parser.add_argument("--output", required=True, metavar="FILE.png")
    parser.add_argument("--title", action="append", default=[], help="a panel's title (repeat, in panel order)")
    parser.add_argument("--size", default=None, help="image size WxH (default: 800 px per panel x 700)")
    parser.add_argument("--scalar", default=None, metavar="NAME", help="colour by this PLY vertex property")
    parser.add_argument("--range", nargs=2, type=float, default=None, metavar=("LO", "HI"))
    parser.add_argument("--view", default="25,20", metavar="AZ,EL", help="camera azimuth,elevation in degrees")
    parser.add_argument("--up", default="0,1,0", metavar="X,Y,Z", help="the view-up before the turn (default 0,1,0)")
    parser.add_argument("--edges", action="store_true", help="draw the mesh edges")
    args = parser.parse_args(argv)
    try:
        size = tuple(int(x) for x in args.size.lower().split("x")) if args.size else (800 * len(args.meshes), 700)
        view = tuple(float(x) for x in args.view.split(","))
        up = tuple(float(x) for x in args.up.split(","))
        assert len(size) == 2 and min(size) > 0 and len(view) == 2 and len(up) == 3 and any(up)
    except (ValueError, AssertionError):
        fail("--size %s / --view %s / --up %s: expected WxH (e.g. 1600x700), AZIMUTH,ELEVATION and X,Y,Z (not zero)"
             % (args.size, args.view, args.up))
    import_vtk()   # a clear message before anything else when VTK is missing
    ensure_display()
    try:
        panels = [Panel(path, args.title[i] if i < len(args.title) else os.path.basename(path), edges=args.edges)
                  for i, path in enumerate(args.meshes)]
        for panel in panels:   # --scalar colours the meshes that have the property (an input may not)
            panel.scalars = args.scalar if args.scalar in panel.mesh["point_data"] else None
        if args.scalar and all(p.scalars is None for p in panels):
            raise ValueError("no mesh has the vertex property '%s'" % args.scalar)
        render_panels(panels, args.output, size=size, view=view, up=up,
                      scalar_range=tuple(args.range) if args.range else None)
    except (ValueError, KeyError, IndexError, StopIteration, OSError) as error:
        fail(str(error) or type(error).__name__)
    if not os.path.isfile(args.output):
        fail("VTK wrote no image to %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
