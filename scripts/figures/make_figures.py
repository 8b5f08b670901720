#!/usr/bin/python3
"""Makes the manual's figures (doc/Anisotropic_fairing/fig/*.png) from real runs of the package.

    bash scripts/af.sh figures            (installs what is missing, builds, then runs this)
    /usr/bin/python3 scripts/figures/make_figures.py [--program EXE] [--peers EXE] [--data DIR]
                                                     [--output DIR] [--work DIR] [--only NAME,...]

Every mesh shown is written by the command-line program anisotropic_fairing (or, for the peers of the
denoising figure, by bench/figure_peers.cpp) and rendered by render_mesh.py with VTK. The noise added
here is seeded: the figures are the same on every run. See scripts/figures/README.md for the figures.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

sys.dont_write_bytecode = True   # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_mesh as rm  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FIGURES = ["denoising_pair", "face_isocontours", "torus_texture", "deviation_sweep", "curvature_limit", "resampled", "strength"]


def log(message):
    print("[figures] " + message, flush=True)


class Context:
    def __init__(self, args):
        self.program = args.program
        self.peers = args.peers
        self.data = args.data
        self.out = args.output
        self.work = args.work

    def work_file(self, name):
        return os.path.join(self.work, name)

    def figure(self, name):
        return os.path.join(self.out, name + ".png")

    def run(self, command):
        """Runs a command, prints it and its time; its standard output is returned."""
        shown = " ".join(os.path.relpath(c, ROOT) if os.path.isabs(c) and c.startswith(ROOT) else c for c in command)
        start = time.time()
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        log("ran %s (%.1f s)" % (shown, time.time() - start))
        if result.returncode != 0:
            sys.stderr.write(result.stdout + result.stderr)
            raise RuntimeError("failed (exit %d): %s" % (result.returncode, shown))
        return result.stdout

    def fair(self, source, target, *options):
        """The program on `source`; returns its JSON report."""
        report = target + ".json"
        self.run([self.program, source, target, "--quiet", "--report", report] + list(options))
        with open(report) as f:
            return json.load(f)


# ---------------------------------------------------------------- measures and inputs

def unit_face_normals(mesh):
    p, f = mesh["points"], rm.face_array(mesh)
    n = np.cross(p[f[:, 1]] - p[f[:, 0]], p[f[:, 2]] - p[f[:, 0]])
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)


def mean_normal_error(mesh, reference):
    """The denoising benchmark's measure: mean angle (degrees) between corresponding face normals."""
    cosines = np.sum(unit_face_normals(mesh) * unit_face_normals(reference), axis=1)
    return float(np.degrees(np.arccos(np.clip(cosines, -1.0, 1.0))).mean())


def vertex_normals(mesh):
    p, f = mesh["points"], rm.face_array(mesh)
    n = np.cross(p[f[:, 1]] - p[f[:, 0]], p[f[:, 2]] - p[f[:, 0]])   # area-weighted
    normals = np.zeros_like(p)
    for corner in range(3):
        np.add.at(normals, f[:, corner], n)
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)


def mean_edge_length(mesh):
    p, f = mesh["points"], rm.face_array(mesh)
    return float(np.mean([np.linalg.norm(p[f[:, a]] - p[f[:, b]], axis=1).mean() for a, b in ((0, 1), (1, 2), (2, 0))]))


def with_normal_noise(mesh, relative_sigma, seed):
    """Gaussian noise of sigma = relative_sigma x mean edge length along the vertex normals."""
    rng = np.random.default_rng(seed)
    sigma = relative_sigma * mean_edge_length(mesh)
    moved = mesh["points"] + vertex_normals(mesh) * rng.normal(0.0, sigma, (len(mesh["points"]), 1))
    return dict(mesh, points=moved)


def write_ply(path, mesh, properties=()):
    """Binary PLY with double positions and the named per-vertex double properties of point_data."""
    p, f = mesh["points"], rm.face_array(mesh)
    fields = [("x", "<f8"), ("y", "<f8"), ("z", "<f8")] + [(n, "<f8") for n in properties]
    vertices = np.zeros(len(p), dtype=fields)
    vertices["x"], vertices["y"], vertices["z"] = p.T
    for name in properties:
        vertices[name] = mesh["point_data"][name]
    faces = np.zeros(len(f), dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"], faces["v"] = 3, f
    header = ["ply", "format binary_little_endian 1.0", "element vertex %d" % len(p)]
    header += ["property double %s" % n for n, _ in fields]
    header += ["element face %d" % len(f), "property list uchar int vertex_indices", "end_header"]
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode("ascii"))
        out.write(vertices.tobytes())
        out.write(faces.tobytes())


def write_off(path, mesh):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(mesh["points"]), len(rm.face_array(mesh))))
        np.savetxt(out, mesh["points"], fmt="%.17g")
        np.savetxt(out, np.column_stack([np.full(len(rm.face_array(mesh)), 3), rm.face_array(mesh)]), fmt="%d")


def moved_distance(result, source):
    return np.linalg.norm(result["points"] - source["points"], axis=1)


# ---------------------------------------------------------------- the figures

def denoising_pair(ctx):
    """Noisy / CGAL smooth_shape / isotropic / anisotropic on a CAD pair of the denoising benchmark."""
    pair = os.path.join(ctx.data, "denoising", "Block0.4")
    noisy_path, clean_path = os.path.join(pair, "Noisy.obj"), os.path.join(pair, "Original.obj")
    anisotropic = ctx.work_file("block_anisotropic.off")
    report = ctx.fair(noisy_path, anisotropic)   # the default run: the product
    smooth, isotropic = ctx.work_file("block_smooth_shape.off"), ctx.work_file("block_isotropic.off")
    settings = {}
    for line in ctx.run([ctx.peers, noisy_path, clean_path, smooth, isotropic]).splitlines():
        words = line.split(None, 3)
        if len(words) == 4 and words[0] in ("smooth_shape", "isotropic"):
            settings[words[0]] = words[3]
    clean = rm.read_mesh(clean_path)
    meshes = [rm.read_mesh(p) for p in (noisy_path, smooth, isotropic, anisotropic)]
    errors = [mean_normal_error(m, clean) for m in meshes]
    labels = ["noisy input (Block, sigma 0.4 h)",
              "CGAL smooth_shape, best of sweep\n(%s)" % settings.get("smooth_shape", "?"),
              "isotropic Loop, best of sweep\n(%s)" % settings.get("isotropic", "?"),
              "anisotropic: the default run\n(%d steps, no parameters)" % len(report.get("steps", []))]
    titles = [("%s\nmean normal error %.2f\u00b0" % (label, error)) for label, error in zip(labels, errors)]
    for label, error in zip(labels, errors):
        log("  %-40s mean normal error %.2f deg" % (label.replace("\n", " "), error))
    rm.render_panels([rm.Panel(m, t) for m, t in zip(meshes, titles)], ctx.figure("denoising_pair"),
                     size=(2400, 820), view=(30.0, 20.0), zoom=1.08)


def face_isocontours(ctx):
    """Paper Fig. 13: isocontours of f = |x|^2 on a noisy face scan, before and after fairing with the geometry."""
    face = rm.read_mesh(os.path.join(ctx.data, "face.obj"))
    noisy = with_normal_noise(face, 0.35, seed=13)
    points = noisy["points"]
    radius = 0.5 * float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    centred = points - points.mean(axis=0)
    # f = |x - c|^2 / R: a length, so that coupled mode weighs it like a coordinate
    noisy["point_data"] = {"quality": np.sum(centred ** 2, axis=1) / radius}
    source = ctx.work_file("face_noisy.ply")
    write_ply(source, noisy, ["quality"])
    levels = np.linspace(*np.percentile(noisy["point_data"]["quality"], [0.5, 99.5]), 30)
    panels = [rm.Panel(noisy, "noisy face scan (sigma 0.35 h along the normals)\nf = |x - c|^2 / R of the noisy x, 0 steps",
                       scalars="quality", contours=levels)]
    # the paper's Fig. 13 shows the function faired with the geometry after 0, 1 and 4 iterations: here the
    # default run stopped after 1 step, and run to its end; coupled mode fairs (x, f) as one surface in R^4
    for steps in (1, None):
        name = "face_coupled_%s.ply" % ("all" if steps is None else steps)
        report = ctx.fair(source, ctx.work_file(name), "--attributes", "quality", "--mode", "coupled",
                          *([] if steps is None else ["--steps", str(steps)]))
        count = len(report.get("steps", []))
        log("  coupled, %s: %d step(s), tensor %s" % ("default stop" if steps is None else "--steps 1", count, report.get("tensor")))
        panels.append(rm.Panel(ctx.work_file(name), "default run, --attributes quality --mode coupled\n%s: %d step%s (%s tensor)"
                               % ("--steps 1" if steps is not None else "to its own stop", count, "" if count == 1 else "s",
                                  report.get("tensor")), scalars="quality", contours=levels))
    # separate mode, for the record: the function faired with the operator of the faired geometry
    separate = ctx.work_file("face_separate.ply")
    ctx.fair(source, separate, "--attributes", "quality", "--mode", "separate")
    difference = rm.read_mesh(separate)["point_data"]["quality"] - panels[-1].mesh["point_data"]["quality"]
    log("  separate vs coupled: RMS difference of f %.3g (contour spacing %.3g)"
        % (float(np.sqrt(np.mean(difference ** 2))), levels[1] - levels[0]))
    rm.render_panels(panels, ctx.figure("face_isocontours"), size=(2400, 900), view=(0.0, 0.0),
                     scalar_range=(levels[0], levels[-1]), colormap="pastel", colorbar_title="f")


def checker_image(size=512, squares=8):
    """The paper's Fig. 14 texture: alternating blue and green squares with a red disc in each."""
    y, x = np.mgrid[0:size, 0:size] + 0.5
    cell = size / squares
    even = ((x // cell + y // cell) % 2) == 0
    image = np.where(even[..., None], [40, 90, 200], [60, 170, 80]).astype(np.uint8)
    cx, cy = (x % cell) / cell - 0.5, (y % cell) / cell - 0.5
    image[cx ** 2 + cy ** 2 < 0.3 ** 2] = [210, 40, 40]
    return image


def torus_patch(nu=64, nv=32, major=1.0, minor=0.4, seed=14):
    """A bordered patch of a torus (3/4 around, the outer 4/5 of the tube) with continuous uv, and noisy uv.

    A closed torus has no continuous uv with one value per vertex (a seam), so the patch stops short of it;
    the noise is added to the interior vertices only, since the program keeps the border's values.
    """
    theta = np.linspace(0.0, 1.5 * np.pi, nu + 1)
    phi = np.linspace(-0.8 * np.pi, 0.8 * np.pi, nv + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    ring = major + minor * np.cos(p)
    points = np.column_stack([(ring * np.cos(t)).ravel(), (minor * np.sin(p)).ravel(), (ring * np.sin(t)).ravel()])
    uv = np.column_stack([(t / theta[-1] * 3.0).ravel(), ((p - phi[0]) / (phi[-1] - phi[0])).ravel()])
    index = np.arange((nu + 1) * (nv + 1)).reshape(nu + 1, nv + 1)
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    faces = np.vstack([np.column_stack([a, c, b]), np.column_stack([a, d, c])])
    interior = np.zeros((nu + 1, nv + 1), dtype=bool)
    interior[1:-1, 1:-1] = True
    rng = np.random.default_rng(seed)
    spacing = min(3.0 / nu, 1.0 / nv)
    noisy_uv = uv + rng.normal(0.0, 0.8 * spacing, uv.shape) * interior.ravel()[:, None]
    return rm.new_mesh(points, faces, uv=uv), rm.new_mesh(points, faces, uv=noisy_uv)


def write_obj_with_uv(path, mesh):
    with open(path, "w") as out:
        np.savetxt(out, mesh["points"], fmt="v %.17g %.17g %.17g")
        np.savetxt(out, mesh["uv"], fmt="vt %.17g %.17g")
        corners = rm.face_array(mesh) + 1
        np.savetxt(out, np.column_stack([corners, corners])[:, [0, 3, 1, 4, 2, 5]], fmt="f %d/%d %d/%d %d/%d")


def torus_texture(ctx):
    """Paper Fig. 14: noisy texture coordinates on a torus faired on the fixed surface, shown with a checker."""
    clean, noisy = torus_patch()
    source = ctx.work_file("torus_noisy_uv.obj")
    write_obj_with_uv(source, noisy)
    image = checker_image()
    panels = [rm.Panel(clean, "noise-free uv", texture=image),
              rm.Panel(noisy, "noisy uv (sigma 0.8 grid spacing)\nRMS uv error %.4f" % uv_error(noisy, clean), texture=image)]
    for steps in (1, 5):
        target = ctx.work_file("torus_uv_%d.obj" % steps)
        ctx.fair(source, target, "--attributes", "uv", "--mode", "attributes", "--time-step", "0.001",
                 "--steps", str(steps), "--stop", "off")
        result = rm.read_mesh(target)
        error = uv_error(result, clean)
        log("  %d step(s): RMS uv error %.4f" % (steps, error))
        panels.append(rm.Panel(result, "faired uv, %d step%s (tau 0.001)\nRMS uv error %.4f"
                               % (steps, "" if steps == 1 else "s", error), texture=image))
    rm.render_panels(panels, ctx.figure("torus_texture"), size=(2400, 760), view=(-20.0, 40.0), zoom=1.05)


def uv_error(mesh, clean):
    """Root-mean-square distance of the texture coordinates to the noise-free ones."""
    return float(np.sqrt(np.mean(np.sum((mesh["uv"] - clean["uv"]) ** 2, axis=1))))


def deviation_sweep(ctx):
    """Paper Fig. 15 / Table I: a long isotropic run held within --relative-maximum-deviation R of the input."""
    noisy = with_normal_noise(rm.read_mesh(os.path.join(ctx.data, "bumpy.off")), 0.3, seed=15)
    source = ctx.work_file("bumpy_noisy.off")
    write_off(source, noisy)
    flow = ["--tensor", "isotropic", "--relative-time-step", "0.002", "--steps", "40", "--stop", "off"]
    runs = []
    for bound in (0.02, 0.05, 0.1, None):
        target = ctx.work_file("bumpy_bound_%s.off" % ("none" if bound is None else bound))
        report = ctx.fair(source, target, *(flow + ([] if bound is None else ["--relative-maximum-deviation", str(bound)])))
        moved = moved_distance(rm.read_mesh(target), noisy)
        runs.append((bound, target, moved, report))
    scale = float(runs[0][3].get("scale") or 1.0)
    log("  Table I analogue (l = %.4g): R | max moved / l | mean moved / l | area of the result" % scale)
    panels = [rm.Panel(noisy, "input: bumpy + noise (sigma 0.3 h)\nisotropic, 40 steps of 0.002 l^2")]
    for bound, target, moved, report in runs:
        area = report["steps"][-1]["area"] if report.get("steps") else float("nan")
        log("  %s | %.4f | %.4f | %.4g (input %.4g)" % ("unbounded" if bound is None else "%g" % bound,
            moved.max() / scale, moved.mean() / scale, area, report["initial"]["area"]))
        title = ("unbounded" if bound is None else "R = %g" % bound) + \
                "\nmax moved %.3f l, area %.1f" % (moved.max() / scale, area)
        panels.append(rm.Panel(target, title, scalars=moved / scale))
    # one scale up to the largest bound: the bounded runs show how they use it, the unbounded one saturates
    largest = max(bound for bound, _, _, _ in runs if bound is not None)
    rm.render_panels(panels, ctx.figure("deviation_sweep"), size=(2400, 640), view=(30.0, 25.0), zoom=1.35,
                     scalar_range=(0.0, largest), colormap="viridis", colorbar_title="moved / l")


def curvature_limit(ctx):
    """The default run on a raw scan, its faired limit surface coloured by mean curvature."""
    scan = os.path.join(ctx.data, "real-scans", "angel.obj")
    target = ctx.work_file("angel_curvature.ply")
    report = ctx.fair(scan, target, "--curvature", "--repair")   # the raw scan has a bow-tie vertex
    result = rm.read_mesh(target)
    curvature = result["point_data"]["mean_curvature"]
    bound = float(np.percentile(np.abs(curvature), 95))   # robust: a few extreme values do not set the scale
    log("  %d step(s); mean curvature 5/50/95 percentiles %.3g %.3g %.3g" % (
        len(report.get("steps", [])), *np.percentile(curvature, [5, 50, 95])))
    steps = len(report.get("steps", []))
    panels = [rm.Panel(scan, "raw scan (angel, real scanner noise)"),
              rm.Panel(result, "default run (%d step%s): the limit surface\ncoloured by its mean curvature (--curvature)"
                       % (steps, "" if steps == 1 else "s"), scalars="mean_curvature")]
    # the scan's y axis points down: seen from +z with -y up
    rm.render_panels(panels, ctx.figure("curvature_limit"), size=(2000, 900), view=(0.0, 0.0), up=(0.0, -1.0, 0.0),
                     scalar_range=(-bound, bound), colormap="coolwarm", colorbar_title="H")


def resampled(ctx):
    """The faired control mesh and the faired limit surface resampled at 1 and 2 levels of Loop refinement."""
    help_text = ctx.run([ctx.program, "--help"])
    if "--resample" not in help_text:
        log("  skipped: this build of the program has no --resample")
        return
    noisy = with_normal_noise(rm.read_mesh(os.path.join(ctx.data, "bumpy.off")), 0.3, seed=16)
    source = ctx.work_file("bumpy_noisy_resample.off")
    write_off(source, noisy)
    control = ctx.work_file("bumpy_control.off")
    ctx.fair(source, control, "--output", "control")
    panels = [rm.Panel(control, "faired control mesh (--output control)\n%d faces" % len(rm.face_array(rm.read_mesh(control))),
                       edges=True)]
    for levels in (1, 2):
        target = ctx.work_file("bumpy_resample_%d.off" % levels)
        ctx.fair(source, target, "--resample", str(levels))
        mesh = rm.read_mesh(target)
        panels.append(rm.Panel(mesh, "limit surface, --resample %d\n%d faces" % (levels, len(rm.face_array(mesh))),
                               edges=True, edge_color=(0.15, 0.15, 0.2) if levels == 1 else (0.45, 0.45, 0.5)))
    rm.render_panels(panels, ctx.figure("resampled"), size=(2400, 860), view=(30.0, 25.0), zoom=1.45)


def stack_rows(rows, output):
    """The PNG images `rows` (of one width) stacked top to bottom into `output`."""
    vtk = rm.import_vtk()
    append = vtk.vtkImageAppend()
    append.SetAppendAxis(1)
    for path in reversed(rows):   # VTK's images start at the bottom row
        reader = vtk.vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        append.AddInputData(reader.GetOutput())
    append.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetCompressionLevel(9)
    writer.SetFileName(output)
    writer.SetInputData(append.GetOutput())
    writer.Write()


def strength(ctx):
    """The default run at --strength 0.5, 1 and 2 on a face scan and a CAD part of the denoising benchmark."""
    cases = [("Julius0.2", "face scan (Julius, sigma 0.2 h)", dict(view=(-75.0, 5.0), zoom=1.1)),
             ("Fandisk0.3", "CAD part (Fandisk, sigma 0.3 h)", dict(view=(150.0, 30.0), zoom=0.98))]
    rows = []
    for name, label, camera in cases:
        pair = os.path.join(ctx.data, "denoising", name)
        noisy_path, clean = os.path.join(pair, "Noisy.obj"), rm.read_mesh(os.path.join(pair, "Original.obj"))
        noisy = rm.read_mesh(noisy_path)
        h = mean_edge_length(noisy)
        panels = [None]   # the input's, once its noise is estimated
        for value in (0.5, 1, 2):
            target = ctx.work_file("strength_%s_%g.off" % (name, value))
            report = ctx.fair(noisy_path, target, *([] if value == 1 else ["--strength", "%g" % value]))
            result = rm.read_mesh(target)
            error = mean_normal_error(result, clean)
            moved = float(moved_distance(result, noisy).mean()) / h
            steps = len(report.get("steps", []))
            log("  %s, strength %g: %s flow kept, %d step(s) of its last run (%s), moved %.3f h along the normals "
                "(noise %.3f h), %.3f h per vertex; mean normal error %.2f deg; %.1f s"
                % (name, value, report["tensor"], steps, report["stop_reason"], report["noise_displacement"],
                   report["noise_level"], moved, error, report["wall_seconds"]))
            title = "%s: %s flow, %d step%s\nmoved %.2f h, mean normal error %.2f\u00b0" % (
                "default run (strength 1)" if value == 1 else "--strength %g" % value, report["tensor"], steps,
                "" if steps == 1 else "s", report["noise_displacement"], error)
            panels.append(rm.Panel(result, title))
            panels[0] = rm.Panel(noisy, "noisy %s, noise estimated %.2f h\nmean normal error %.2f\u00b0" % (
                label, report["noise_level"], mean_normal_error(noisy, clean)))
        rows.append(ctx.work_file("strength_%s.png" % name))
        rm.render_panels(panels, rows[-1], size=(2400, 800), **camera)
    stack_rows(rows, ctx.figure("strength"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    build = os.path.join(ROOT, "build-figures")
    parser.add_argument("--program", default=os.path.join(build, "bin", "anisotropic_fairing"))
    parser.add_argument("--peers", default=os.path.join(build, "bench", "figure_peers"))
    parser.add_argument("--data", default=os.path.normpath(os.path.join(ROOT, "..", "shared", "data")))
    parser.add_argument("--output", default=os.path.join(ROOT, "doc", "Anisotropic_fairing", "fig"))
    parser.add_argument("--work", default=os.path.join(build, "figures-work"))
    parser.add_argument("--only", default=",".join(FIGURES), help="comma-separated: " + ", ".join(FIGURES))
    args = parser.parse_args()
    chosen = [n for n in args.only.split(",") if n]
    unknown = [n for n in chosen if n not in FIGURES]
    if unknown:
        parser.error("unknown figure(s): %s" % ", ".join(unknown))
    for tool in (args.program,) + ((args.peers,) if "denoising_pair" in chosen else ()):
        if not os.access(tool, os.X_OK):
            parser.error("%s is not built (bash scripts/af.sh figures builds it)" % tool)
    rm.import_vtk()
    rm.ensure_display()   # the whole script under xvfb-run when there is no display
    os.makedirs(args.output, exist_ok=True)
    os.makedirs(args.work, exist_ok=True)
    ctx = Context(args)
    start = time.time()
    for name in chosen:
        began = time.time()
        log("%s ..." % name)
        globals()[name](ctx)
        log("%s: %.1f s -> %s" % (name, time.time() - began, os.path.relpath(ctx.figure(name), ROOT)))
    log("all done in %.1f s" % (time.time() - start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
