# The distributed program with no process holding the whole mesh (distributed/Part_run.cpp): binary PLY files read
# and written by blocks, each process's part of the mesh given to the library. On 1, 2 and 3 processes the result
# equals the serial program's to 1e-9 (the vertices' other properties and the faces unchanged, byte for byte), with
# the same decisions and the same measures of the whole mesh (components, border loops and vertices, vertices on
# no face, the noise level; the default run's spikes, noise model and choice), while each process holds fewer vertices
# than the mesh has (a file not read by blocks, or a binary PLY file whose blocks cannot make the parts: read by
# process 0 and scattered, and the report says why).
import json, math, os, random, struct, sys

def binary_ply(source, target, noise=0.0, seed=3, spikes=0.0, lattice=0.0, normals=False, attributes=False):
    """source's mesh (OFF) as a binary little-endian PLY: double x, y, z and a float `quality` per vertex (which
    must come back unchanged), with Gaussian noise of `noise` mean edge lengths on each coordinate; a share `spikes`
    of the vertices thrown 1.5 mean edge lengths off in a random direction (impulsive noise); the coordinates
    rounded to multiples of `lattice` mean edge lengths (a quantised scan); with `normals`, double nx, ny, nz: the
    noisy surface's area-weighted vertex normals, as a scanner writes them; with `attributes`, a noisy function on
    the surface (double value) and a noisy colour (uchar red, green, blue)."""
    words = [w for l in open(source) for w in l.split("#")[0].split()]
    n, m = int(words[1]), int(words[2])
    points = [[float(x) for x in words[4 + 3 * i:7 + 3 * i]] for i in range(n)]
    at = 4 + 3 * n
    faces = [[int(x) for x in words[at + 4 * j + 1:at + 4 * j + 4]] for j in range(m)]
    edge = sum(math.dist(points[a], points[b]) for a, b, _ in faces) / max(m, 1)
    rng = random.Random(seed)
    moved = []
    for p in points:
        q = [x + noise * edge * rng.gauss(0, 1) for x in p]
        if rng.random() < spikes:
            d = [rng.gauss(0, 1) for _ in range(3)]
            q = [x + 1.5 * edge * y / math.hypot(*d) for x, y in zip(q, d)]
        moved.append([round(x / (lattice * edge)) * lattice * edge for x in q] if lattice > 0 else q)
    normal = [[0.0] * 3 for _ in moved]
    for f in faces:
        a, b, c = (moved[k] for k in f)
        u, v = [b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)]
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        for k in f: normal[k] = [x + y for x, y in zip(normal[k], cross)]
    with open(target, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                   "property double z\nproperty float quality\n%s%selement face %d\nproperty list uchar int vertex_indices\n"
                   "end_header\n" % (n, "property double nx\nproperty double ny\nproperty double nz\n" if normals else "",
                                     "property double value\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                                     if attributes else "", m)).encode())
        for i, q in enumerate(moved):
            out.write(struct.pack("<3df", *q, float(i % 97)))
            if normals: out.write(struct.pack("<3d", *[x / (math.hypot(*normal[i]) or 1) for x in normal[i]]))
            if attributes:
                p = points[i]
                byte = lambda x: max(0, min(255, int(round(127.5 + 100 * x + 20 * rng.gauss(0, 1)))))
                out.write(struct.pack("<d3B", math.sin(3 * p[0] / edge / 10) + 0.2 * rng.gauss(0, 1),
                                      byte(math.sin(p[1] / edge / 8)), byte(math.cos(p[2] / edge / 8)), byte(0)))
        for f in faces: out.write(struct.pack("<B3i", 3, *f))

def with_bowtie(source, target):
    """source (OFF) with a small tetrahedron sharing its vertex 0: a vertex whose faces make two fans."""
    words = [l.split() for l in open(source).read().split("\n") if l.split()]
    n, f = int(words[1][0]), int(words[1][1])
    x, y, z = (float(v) for v in words[2][:3])
    tip = ["%.17g %.17g %.17g" % (x + a, y + b, z + c) for a, b, c in ((0.01, 0, 0), (0, 0.01, 0), (0.01, 0.01, 0.01))]
    tetra = ["3 0 %d %d" % (n, n + 1), "3 0 %d %d" % (n + 1, n + 2), "3 0 %d %d" % (n + 2, n), "3 %d %d %d" % (n, n + 2, n + 1)]
    lines = ["OFF", "%d %d 0" % (n + 3, f + 4)] + [" ".join(w) for w in words[2:2 + n]] + tip
    lines += [" ".join(w) for w in words[2 + n:2 + n + f]] + tetra
    open(target, "w").write("\n".join(lines) + "\n")

def ply_vertex_records(path):
    """The vertex properties' names, the vertex records and the face section's bytes of a PLY file of scalar vertex
    properties (binary little endian or ascii: then the face section's text)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode().split("\n")
    at = [i for i, l in enumerate(lines) if l.startswith("element vertex")][0]
    n, names, record = int(lines[at].split()[2]), [], "<"
    for l in lines[at + 1:]:
        if not l.startswith("property"): break
        record += {"double": "d", "float": "f", "float64": "d", "float32": "f", "uchar": "B", "uint8": "B", "char": "b",
                   "int8": "b", "short": "h", "int16": "h", "ushort": "H", "uint16": "H", "int": "i", "int32": "i",
                   "uint": "I", "uint32": "I"}[l.split()[1]]
        names.append(l.split()[2])
    if "format ascii 1.0" in lines:
        rows = data[end:].decode().split("\n")
        return names, [tuple(float(x) for x in r.split()) for r in rows[:n]], "\n".join(rows[n:]).encode()
    size = struct.calcsize(record)
    return names, [struct.unpack_from(record, data, end + size * i) for i in range(n)], data[end + size * n:]

def ascii_ply(source, target):
    """The binary PLY file `source` as an ascii PLY file of the same properties (integers as integers)."""
    names, records, faces = ply_vertex_records(source)
    data = open(source, "rb").read()
    header = data[:data.index(b"end_header\n")].decode().replace("binary_little_endian", "ascii")
    m = int([l for l in header.split("\n") if l.startswith("element face")][0].split()[2])
    corners = [struct.unpack_from("<B3i", faces, 13 * j)[1:] for j in range(m)]
    text = ["%s" % " ".join("%d" % x if x == int(x) and abs(x) < 256 else "%.17g" % x for x in r) for r in records]
    open(target, "w").write(header + "end_header\n" + "\n".join(text) + "\n" + "".join("3 %d %d %d\n" % c for c in corners))

def same_attributes(name, np, out, serial, mesh):
    """The attributes faired and the curvature written (those of `serial`) in `out` as in `serial`: bytes to the rounding
    of a value within 1e-9 of it, the curvature to 1e-7 of the largest; a faired `value` differs from `mesh`'s (None:
    the attributes are not faired)."""
    got_attributes = attribute_columns(out)
    for key, want_values in attribute_columns(serial).items():
        got_values = got_attributes.get(key, [float("nan")] * len(want_values))
        span = (max(want_values) - min(want_values) if key == "value" else max(abs(x) for x in want_values)) or 1
        worst = max(abs(a - b) if a == a else float("inf") for a, b in zip(got_values, want_values))
        tolerance = 1 if key in ("red", "green", "blue") else 1e-9 * span if key == "value" else 1e-7 * span
        if worst > tolerance or (mesh and key == "value" and got_values == attribute_columns(mesh)[key]):
            sys.exit("FAIL: %s on %d processes: attribute %s differs from the serial program's by %.3g, or was not faired"
                     % (name, np, key, worst))

def ply_sections(path):
    """The vertex records (x, y, z, quality and nx, ny, nz if there) and the face section's bytes."""
    names, records, faces = ply_vertex_records(path)
    order = [names.index(k) for k in ("x", "y", "z", "quality", "nx", "ny", "nz") if k in names]
    return [[r[k] for k in order] for r in records], faces

def attribute_columns(path):
    """The attribute properties value, red, green, blue and the curvature k1, k2, mean_curvature of a binary PLY file,
    by name (those it has)."""
    names, records, _ = ply_vertex_records(path)
    return {k: [r[names.index(k)] for r in records] for k in ("value", "red", "green", "blue", "k1", "k2", "mean_curvature")
            if k in names}

def equal_on_parts(args, run, mpi, name, mesh, flags, processes=(1, 2, 3)):
    """`flags` on `mesh` (a binary PLY) by the serial program and on parts: the same result and decisions."""
    serial = os.path.join(args.work, name + "_serial.ply")
    run([args.tool, mesh, serial, "--quiet", "--solver", "cholesky", "--report", serial + ".json"] + flags)
    expected = json.load(open(serial + ".json"))
    reference = [r[:3] for r in ply_sections(serial)[0]]
    diagonal = math.dist([min(r[c] for r in reference) for c in range(3)], [max(r[c] for r in reference) for c in range(3)])
    rows_in, faces_in = ply_sections(mesh)
    for np in processes:
        out = os.path.join(args.work, "%s_np%d.ply" % (name, np))
        run(mpi(args, np, mesh, out, "--quiet", "--report", out + ".json", "-ksp_rtol", "1e-13",
                "-prefilter_ksp_rtol", "1e-14", "-ksp_max_it", "20000") + flags)
        got = json.load(open(out + ".json"))
        rows, faces = ply_sections(out)
        d = max(math.dist(r[:3], q) for r, q in zip(rows, reference)) / diagonal
        normals = max((math.dist(r[4:7], q[4:7]) for r, q in zip(rows, ply_sections(serial)[0]) if len(r) > 4), default=0)
        if not normals <= 1e-9: sys.exit("FAIL: %s on %d processes: the normals differ from the serial program's by %.3g" % (name, np, normals))
        if len(rows[0]) > 4 and got["normals"] != expected["normals"]: sys.exit("FAIL: %s: normals %s" % (name, got["normals"]))
        held = got["per_process"]["part_vertices"]
        print("%s, %d process(es): held in parts %s of %d vertices; largest difference to the serial program %.3g of "
              "the diagonal; %d steps, stopped: %s" % (name, np, held, len(rows), d, len(got["steps"]), got["stop_reason"]))
        if got["mesh_held"] != "parts": sys.exit("FAIL: %s: run with the whole mesh (%s)" % (name, got.get("whole_mesh_why")))
        if np > 1 and max(held) >= len(rows): sys.exit("FAIL: %s on %d processes: a process held the whole mesh" % (name, np))
        if not d <= 1e-9: sys.exit("FAIL: %s on %d processes differs from the serial result by %.3g" % (name, np, d))
        if faces != faces_in or any(r[3] != q[3] for r, q in zip(rows, rows_in)) or (len(rows[0]) > 4 and rows[0][4:] == rows_in[0][4:]):
            sys.exit("FAIL: %s on %d processes: the faces or the vertices' quality were not written as read, or the normals were" % (name, np))
        for key in ("stop_reason", "rejected_steps", "boundary_vertices", "boundary_held_vertices", "boundary_loops",
                    "isolated_vertices", "components", "held_vertices", "bound_held_vertices", "clamped_vertices",
                    "bound_retaken_steps"):
            if got[key] != expected[key]: sys.exit("FAIL: %s on %d processes: %s %s, the serial run's %s" % (name, np, key, got[key], expected[key]))
        if len(got["steps"]) != len(expected["steps"]): sys.exit("FAIL: %s on %d processes: other steps" % (name, np))
        same_attributes(name, np, out, serial, mesh if "--attributes" in flags else None)
        for key in ("noise_level", "mean_edge_length"):
            if abs(got[key] - expected[key]) > 1e-9 * abs(expected[key]):
                sys.exit("FAIL: %s on %d processes: %s %.17g, the serial run's %.17g" % (name, np, key, got[key], expected[key]))
        if flags: continue
        # the default run: the same spikes, noise model, estimates and choice, said alike
        model, want = got["noise_model"], expected["noise_model"]
        for key in want:
            a, b = (model[key], want[key]) if key != "lattice_step" else (max(model[key]), max(want[key]))
            if abs(a - b) > 1e-6 * abs(b): sys.exit("FAIL: %s on %d processes: noise model %s %s, the serial run's %s" % (name, np, key, model[key], want[key]))
        for key, serial_key in (("removed_spikes", "removed_spikes"), ("choices", "choices"), ("selected_tensor", "tensor")):
            if got[key] != expected[serial_key]:
                sys.exit("FAIL: %s on %d processes: %s '%s', the serial run's '%s'" % (name, np, key, got[key], expected[serial_key]))

def equal_on_scattered_parts(args, run, mpi, helpers, name, mesh, output, flags):
    """`flags` on `mesh` in a format process 0 reads whole and scatters (Scattered_mesh.h), the output `output`'s
    format: the serial program's result and decisions, each process holding its part."""
    serial = os.path.join(args.work, name + "_serial" + output)
    run([args.tool, mesh, serial, "--quiet", "--solver", "cholesky", "--report", serial + ".json"] + flags)
    expected = json.load(open(serial + ".json"))
    for np in (1, 2, 3):
        out = os.path.join(args.work, "%s_np%d%s" % (name, np, output))
        run(mpi(args, np, mesh, out, "--quiet", "--report", out + ".json", "-ksp_rtol", "1e-13",
                "-prefilter_ksp_rtol", "1e-14", "-ksp_max_it", "20000") + flags)
        got = json.load(open(out + ".json"))
        d = helpers["relative_difference"](helpers["read_mesh"](out), helpers["read_mesh"](serial))
        held = got["per_process"]["part_vertices"]
        print("%s, %d process(es), read by process 0 and scattered: held in parts %s of %d vertices; largest difference "
              "to the serial program %.3g; %d steps, stopped: %s" % (name, np, held, got["vertices"], d, len(got["steps"]), got["stop_reason"]))
        if got["mesh_held"] != "parts": sys.exit("FAIL: %s: run with the whole mesh (%s)" % (name, got.get("whole_mesh_why")))
        if np > 1 and max(held) >= got["vertices"]: sys.exit("FAIL: %s on %d processes: a process held the whole mesh" % (name, np))
        if not d <= 1e-9: sys.exit("FAIL: %s on %d processes differs from the serial result by %.3g" % (name, np, d))
        for key in ("stop_reason", "normals", "choices", "held_vertices", "vertices"):
            if got[key] != expected[key]: sys.exit("FAIL: %s on %d processes: %s %s, the serial run's %s" % (name, np, key, got[key], expected[key]))
        if output == ".ply": same_attributes(name, np, out, serial, mesh if "--attributes" in flags else None)

def read_by_process_0(args, run, mpi, name, mesh, flags, why):
    """A binary PLY file whose blocks cannot make the parts is read whole by process 0 and scattered, the report
    says why, and the result is the serial program's."""
    serial = os.path.join(args.work, name + "_serial.ply")
    run([args.tool, mesh, serial, "--quiet", "--solver", "cholesky"] + flags)
    names, records, _ = ply_vertex_records(serial)
    reference = [[r[names.index(k)] for k in "xyz"] for r in records]
    diagonal = math.dist([min(r[c] for r in reference) for c in range(3)], [max(r[c] for r in reference) for c in range(3)])
    out = os.path.join(args.work, name + "_np2.ply")
    run(mpi(args, 2, mesh, out, "--quiet", "--report", out + ".json", "-ksp_rtol", "1e-13") + flags)
    got = json.load(open(out + ".json"))
    names, records, _ = ply_vertex_records(out)
    d = max(math.dist([r[names.index(k)] for k in "xyz"], q) for r, q in zip(records, reference)) / diagonal
    print("%s, 2 processes: read by %s (%s); largest difference to the serial program %.3g of the diagonal"
          % (name, got.get("mesh_read"), got.get("mesh_read_why"), d))
    if got["mesh_held"] != "parts" or got.get("mesh_read") != "process 0" or why not in got.get("mesh_read_why", ""):
        sys.exit("FAIL: %s: mesh_held %s, read by %s, why %s (expected: %s)" % (name, got["mesh_held"], got.get("mesh_read"),
                                                                           got.get("mesh_read_why"), why))
    if len(records) != len(reference) or not d <= 1e-9: sys.exit("FAIL: %s differs from the serial result by %.3g" % (name, d))

def parts(args, run, mpi, helpers):
    iso = ["--tensor", "isotropic", "--relative-time-step", "1e-3", "--steps", "3"]
    aniso = ["--tensor", "anisotropic", "--lambda", "8", "--epsilon", "1e-3", "--relative-time-step", "5e-4", "--steps", "3"]
    meshes = {}
    for name, source in (("bumpy", "bumpy.off"), ("hemisphere", "hemisphere.off")):
        meshes[name] = os.path.join(args.work, name + ".ply")
        binary_ply(os.path.join(args.data, source), meshes[name])
    equal_on_parts(args, run, mpi, "closed_isotropic", meshes["bumpy"], iso)
    equal_on_parts(args, run, mpi, "closed_anisotropic", meshes["bumpy"], aniso)
    equal_on_parts(args, run, mpi, "bordered_anisotropic", meshes["hemisphere"], aniso)
    equal_on_parts(args, run, mpi, "bordered_fourth_order", meshes["hemisphere"], ["--order", "4", "--tensor", "isotropic",
                                                                                  "--relative-time-step", "1e-3", "--steps", "4"])
    # noise, and the stop at its level: the noise estimate's samples and the discrepancy's median over the parts
    noisy = os.path.join(args.work, "hemisphere_noisy.ply")
    binary_ply(os.path.join(args.data, "hemisphere.off"), noisy, noise=0.2)
    equal_on_parts(args, run, mpi, "noise_stop", noisy, ["--tensor", "isotropic", "--relative-time-step", "0.1", "--stop", "noise"])
    # components joined over the parts; a vertex on no face
    pair, lonely = os.path.join(args.work, "pair.off"), os.path.join(args.work, "lonely.off")
    helpers["two_components"](os.path.join(args.data, "bumpy.off"), pair)
    helpers["with_isolated_vertex"](os.path.join(args.data, "hemisphere.off"), lonely)
    for name, source in (("two_components", pair), ("isolated_vertex", lonely)):
        meshes[name] = os.path.join(args.work, name + ".ply")
        binary_ply(source, meshes[name], noise=0.05)
        equal_on_parts(args, run, mpi, name, meshes[name], iso)
    # held vertices: a file of the whole mesh's indices, and a vertex property (quality: all but every 97th)
    held = os.path.join(args.work, "held.txt")
    open(held, "w").write("# every seventh vertex\n" + "\n".join(str(i) for i in range(0, 1250, 7)) + "\n")
    equal_on_parts(args, run, mpi, "held_file", meshes["bumpy"], aniso + ["--hold", held])
    equal_on_parts(args, run, mpi, "held_property", meshes["two_components"], iso + ["--hold", "quality"])
    # a vertex of two fans (a tetrahedron hung on a vertex): read whole, and split there, as the serial program does
    bowtie = os.path.join(args.work, "bowtie.off")
    with_bowtie(os.path.join(args.data, "bumpy.off"), bowtie)
    meshes["bowtie"] = os.path.join(args.work, "bowtie.ply")
    binary_ply(bowtie, meshes["bowtie"])
    read_by_process_0(args, run, mpi, "bowtie", meshes["bowtie"], iso, "not a manifold surface")
    # the default run: the spikes, the noise model (its lattice too) and the comparison of flows over the parts
    for name, source, noise in (("default_closed", "bunny.off", dict(noise=0.3)), ("default_bordered", "hemisphere.off", dict(noise=0.2)),
                                ("default_spikes", "bumpy.off", dict(noise=0.02, spikes=0.05)),
                                ("default_lattice", "bumpy.off", dict(noise=0.1, lattice=0.125)),
                                ("default_normals", "bunny.off", dict(noise=0.3, normals=True))):
        meshes[name] = os.path.join(args.work, name + ".ply")
        binary_ply(os.path.join(args.data, source), meshes[name], **noise)
        equal_on_parts(args, run, mpi, name, meshes[name], [])
    # deviation bounds: the default run's (each vertex held by its own fidelity) and a run of given steps to a
    # steady state (the uniform weight too), their decisions over the parts
    equal_on_parts(args, run, mpi, "bounded", meshes["default_closed"], ["--relative-maximum-deviation", "0.05"])
    equal_on_parts(args, run, mpi, "bounded_steps", noisy, ["--tensor", "isotropic", "--relative-time-step", "0.05",
                                                            "--steps", "12", "--relative-maximum-deviation", "0.01"])
    for name in ("bounded", "bounded_steps"):   # the bound held rows: the case tests what it names
        report = json.load(open(os.path.join(args.work, name + "_serial.ply.json")))
        if report["bound_held_vertices"] == 0 or (name == "bounded_steps" and not report["bound_uniform_weight"]):
            sys.exit("FAIL: %s: the bound held no row, or gave no uniform weight" % name)
    # attributes: a function and a colour with the geometry (coupled, the anisotropic flow), after it (separate), on
    # the fixed surface (attributes only), under a bound of their own, and the default run with them
    valued = os.path.join(args.work, "valued.ply")
    binary_ply(os.path.join(args.data, "bumpy.off"), valued, noise=0.05, attributes=True)
    equal_on_parts(args, run, mpi, "attributes_coupled", valued, ["--attributes", "value,color", "--mode", "coupled",
                                                                  "--attribute-weight", "2"] + aniso)
    equal_on_parts(args, run, mpi, "attributes_separate", valued, ["--attributes", "value", "--mode", "separate"] + iso)
    equal_on_parts(args, run, mpi, "attributes_only", valued, ["--attributes", "value,red", "--mode", "attributes"])
    equal_on_parts(args, run, mpi, "attributes_bounded", valued, ["--attributes", "value", "--mode", "attributes",
                                                                  "--attribute-maximum-deviation", "0.01"])
    noisy_valued = os.path.join(args.work, "noisy_valued.ply")
    binary_ply(os.path.join(args.data, "bunny.off"), noisy_valued, noise=0.3, attributes=True)
    equal_on_parts(args, run, mpi, "attributes_default", noisy_valued, ["--attributes", "value,color"])
    for name in ("attributes_bounded", "attributes_default"):   # the bound held rows; the default run took steps
        report = json.load(open(os.path.join(args.work, name + "_serial.ply.json")))
        if (report["bound_held_vertices"] if name == "attributes_bounded" else len(report["steps"])) == 0:
            sys.exit("FAIL: %s: the bound held no row, or no step was taken" % name)
    # a name the file lacks: the serial program's message (the mesh read whole, as it reads it), nothing written
    out = os.path.join(args.work, "unknown_out.ply")
    p = run(mpi(args, 2, valued, out, "--quiet", "--attributes", "value,colour") + iso, expect_code=1)
    print("an attribute the file lacks, on 2 processes: %s" % p.stderr.strip().split("\n")[0])
    if "has no such vertex attribute" not in p.stderr or os.path.exists(out): sys.exit("FAIL: an unknown attribute")
    # attributes and held vertices of a mesh read whole by process 0: an ascii PLY file (held: all but every 97th vertex)
    valued_ascii = os.path.join(args.work, "valued_ascii.ply")
    ascii_ply(valued, valued_ascii)
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_attributes", valued_ascii, ".ply",
                             ["--attributes", "value,color", "--mode", "coupled"] + aniso)
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_held", valued_ascii, ".ply", iso + ["--hold", "quality"])
    # the curvature written (k1, k2, mean_curvature added to the vertex records), with the normals of a scan
    equal_on_parts(args, run, mpi, "curvature", meshes["default_normals"], aniso + ["--curvature"])
    # --repair: the mesh read whole by process 0 (its lone vertex removed), as the serial program reads it
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_repair", lonely, ".off", iso + ["--repair"])
    # a bad vertex is named by its number in the file, not in a part; nothing is written
    bad = os.path.join(args.work, "nan.ply")
    binary_ply(os.path.join(args.data, "bumpy.off"), bad)
    data = bytearray(open(bad, "rb").read())
    at = data.index(b"end_header\n") + len(b"end_header\n") + 28 * 700 + 8
    data[at:at + 8] = struct.pack("<d", float("nan"))
    open(bad, "wb").write(bytes(data))
    out = os.path.join(args.work, "nan_out.ply")
    p = run(mpi(args, 2, bad, out, "--quiet") + iso, expect_code=1)
    print("a vertex with a NaN, on 2 processes: %s" % p.stderr.strip().split("\n")[0])
    if "vertex 700 " not in p.stderr or os.path.exists(out): sys.exit("FAIL: the bad vertex is not named as the file numbers it, or an output was written")
    # other formats: read whole by process 0 and scattered, written by it; the default run on an ASCII PLY scan with
    # vertex normals; a bow-tie OFF, its vertex split as the serial program splits it and merged back
    scan = os.path.join(args.work, "scan_ascii.ply")
    helpers["noisy_scan"](os.path.join(args.data, "bunny.off"), scan, True)
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_default", scan, ".ply", [])
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_bowtie", bowtie, ".off", iso)
    # held vertices of a mesh whose vertex 0 is split: its copy held with it, counted once
    held0 = os.path.join(args.work, "held0.txt")
    open(held0, "w").write("0\n5\n")
    equal_on_scattered_parts(args, run, mpi, helpers, "scattered_bowtie_held", bowtie, ".off", iso + ["--hold", held0])
