#!/usr/bin/env python3
# Tests of anisotropic_fairing_mpi (distributed/): its result on 1, 2 and 3 processes, the default run's
# included, equals the serial library's, the program anisotropic_fairing's with the same options and an
# exact solver (--solver cholesky), to 1e-9 relative (the distributed CG iterates to 1e-13); a failing
# process fails the run with a message naming the element (or itself, out of memory) and no output; what is
# not supported is refused.
#   distributed_test.py --tool anisotropic_fairing --mpi anisotropic_fairing_mpi --mpiexec mpirun
#                       --data DIR --example-data DIR --work DIR --case NAME
import argparse, json, math, os, random, shutil, subprocess, sys, tempfile

TIGHT = ["-ksp_rtol", "1e-13", "-prefilter_ksp_rtol", "1e-14", "-ksp_max_it", "20000", "-prefilter_ksp_max_it", "20000"]
TOLERANCE = 1e-9

def read_mesh(path):
    """Vertex rows (all numbers of each vertex line) of an ASCII OFF, PLY or OBJ file."""
    lines = open(path).read().split("\n")
    if path.endswith(".obj"):
        return [[float(x) for x in l.split()[1:]] for l in lines if l.startswith("v ")]
    if lines[0].startswith("ply"):
        count, k = 0, 1
        while not lines[k].startswith("end_header"):
            if lines[k].startswith("element vertex"): count = int(lines[k].split()[2])
            k += 1
        return [[float(x) for x in lines[k + 1 + i].split()] for i in range(count)]
    words = [l.split("#")[0].split() for l in lines]
    words = [w for w in words if w]
    n = int(words[1][0])
    return [[float(x) for x in words[2 + i]] for i in range(n)]

def relative_difference(a, b):
    """Largest difference per column over the column's range (coordinates: over the bounding box's diagonal)."""
    assert len(a) == len(b) and len(a[0]) == len(b[0]), "different sizes"
    columns = len(a[0])
    coord_range = math.sqrt(sum((max(r[c] for r in b) - min(r[c] for r in b)) ** 2 for c in range(3)))
    worst = 0.0
    for c in range(columns):
        scale = coord_range if c < 3 else max(max(r[c] for r in b) - min(r[c] for r in b), 1e-300)
        worst = max(worst, max(abs(x[c] - y[c]) for x, y in zip(a, b)) / scale)
    return worst

def run(command, expect_code=0):
    p = subprocess.run(command, capture_output=True, text=True, timeout=300)
    if p.returncode != expect_code:
        sys.exit("FAIL: %s exited %d (expected %d)\nstdout: %s\nstderr: %s" % (" ".join(command), p.returncode, expect_code, p.stdout, p.stderr))
    return p

OPEN_MPI_FLAGS = None

def mpi(args, np, *rest):
    """mpiexec -np NP PROGRAM ...; with Open MPI as root (CI) and more processes than cores allowed."""
    global OPEN_MPI_FLAGS
    if OPEN_MPI_FLAGS is None:
        version = subprocess.run([args.mpiexec, "--version"], capture_output=True, text=True).stdout
        OPEN_MPI_FLAGS = ["--allow-run-as-root", "--oversubscribe"] if "Open MPI" in version or "OpenRTE" in version else []
    return [args.mpiexec] + OPEN_MPI_FLAGS + ["-np", str(np), args.mpi] + list(rest)

def make_valued_ply(source, target):
    """source's mesh (OFF) with a double vertex property 'value': height plus deterministic noise."""
    words = [l.split() for l in open(source).read().split("\n") if l.split()]
    n, f = int(words[1][0]), int(words[1][1])
    rng = random.Random(7)
    with open(target, "w") as out:
        out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                  "property double value\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (n, f))
        for i in range(n):
            x, y, z = (float(t) for t in words[2 + i][:3])
            out.write("%.17g %.17g %.17g %.17g\n" % (x, y, z, z + 0.05 * rng.uniform(-1, 1)))
        for j in range(f):
            out.write(" ".join(words[2 + n + j][:4]) + "\n")

def noisy_scan(source, target, normals):
    """source's mesh (OFF) with Gaussian noise of 0.2 mean edge lengths along random directions, as a PLY, with
    vertex normals (nx, ny, nz: the noisy surface's, as a scanner writes them) or without."""
    words = [l.split() for l in open(source).read().split("\n") if l.split()]
    n, f = int(words[1][0]), int(words[1][1])
    points = [[float(x) for x in w[:3]] for w in words[2:2 + n]]
    faces = [[int(x) for x in w[1:4]] for w in words[2 + n:2 + n + f]]
    edge = sum(math.dist(points[t[k]], points[t[(k + 1) % 3]]) for t in faces for k in range(3)) / (3 * f)
    rng = random.Random(11)
    points = [[x + 0.2 * edge * rng.gauss(0, 1) for x in p] for p in points]
    normal = [[0.0, 0.0, 0.0] for _ in range(n)]
    for a, b, c in faces:
        u = [points[b][k] - points[a][k] for k in range(3)]
        v = [points[c][k] - points[a][k] for k in range(3)]
        w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        for i in (a, b, c): normal[i] = [normal[i][k] + w[k] for k in range(3)]
    with open(target, "w") as out:
        out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n" % n)
        if normals: out.write("property double nx\nproperty double ny\nproperty double nz\n")
        out.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % f)
        for p, m in zip(points, normal):
            length = math.sqrt(sum(x * x for x in m)) or 1.0
            out.write(" ".join("%.17g" % x for x in p + ([x / length for x in m] if normals else [])) + "\n")
        for t in faces: out.write("3 %d %d %d\n" % tuple(t))

def equal_to_serial(args, name, mesh, flags, processes=(1, 2, 3), petsc=()):
    ext = os.path.splitext(mesh)[1]
    serial = os.path.join(args.work, name + "_serial" + ext)
    run([args.tool, mesh, serial, "--quiet", "--solver", "cholesky", "--report", serial + ".json"] + flags)
    reference = read_mesh(serial)
    expected = json.load(open(serial + ".json"))
    for np in processes:
        out = os.path.join(args.work, "%s_np%d%s" % (name, np, ext))
        run(mpi(args, np, mesh, out, "--quiet", "--report", out + ".json") + flags + TIGHT + list(petsc))
        d = relative_difference(read_mesh(out), reference)
        got = json.load(open(out + ".json"))
        print("%s, %d process(es): largest relative difference to the serial library %.3g; %d steps, %d rejected, stopped: %s"
              % (name, np, d, len(got["steps"]), got["rejected_steps"], got["stop_reason"]))
        if not d <= TOLERANCE:
            sys.exit("FAIL: %s on %d processes differs from the serial result by %.3g > %g" % (name, np, d, TOLERANCE))
        # the work was divided: every process assembled faces, each face once
        faces = got["per_process"]["faces"]
        if len(faces) != np or min(faces) == 0 or sum(faces) != got["faces"]:
            sys.exit("FAIL: %s on %d processes: faces per process %s of %d" % (name, np, faces, got["faces"]))
        # the same decisions: steps taken, steps rejected, why it stopped
        decisions = [("stop_reason", got["stop_reason"]), ("rejected_steps", got["rejected_steps"]), ("steps", len(got["steps"])),
                     ("normals", got["normals"])]
        if got["selected_tensor"]: decisions.append(("tensor", got["selected_tensor"]))   # the default run's choice
        for key, value in decisions:
            want = len(expected["steps"]) if key == "steps" else expected[key]
            if value != want: sys.exit("FAIL: %s on %d processes: %s %s, the serial run's %s" % (name, np, key, value, want))

def fails_cleanly(args, name, mesh, flags, np, code, words):
    out = os.path.join(args.work, name + os.path.splitext(mesh)[1])
    if os.path.exists(out): os.remove(out)
    p = run(mpi(args, np, mesh, out, "--quiet") + flags, expect_code=code)
    line = p.stderr.strip().split("\n")[0]
    print("%s: exit %d: %s" % (name, code, line))
    for w in words:
        if w not in line: sys.exit("FAIL: %s: the message does not say '%s': %s" % (name, w, line))
    if os.path.exists(out): sys.exit("FAIL: %s: the output %s was written" % (name, out))

def with_isolated_vertex(source, target):
    """source (OFF) with one more vertex on no face (held, written unchanged)."""
    words = [l for l in open(source).read().split("\n") if l.split()]
    n, f = (int(x) for x in words[1].split()[:2])
    open(target, "w").write("\n".join(["OFF", "%d %d 0" % (n + 1, f)] + words[2:2 + n] + ["5 5 5"] + words[2 + n:2 + n + f]) + "\n")

def two_components(source, target):
    """source (OFF) and a copy of it a tenth of its size beside it: two components, each in its own units."""
    words = [l.split() for l in open(source).read().split("\n") if l.split()]
    n, f = int(words[1][0]), int(words[1][1])
    points = [[float(x) for x in w[:3]] for w in words[2:2 + n]]
    faces = [[int(x) for x in w[1:4]] for w in words[2 + n:2 + n + f]]
    lines = ["OFF", "%d %d 0" % (2 * n, 2 * f)] + ["%.17g %.17g %.17g" % tuple(p) for p in points]
    lines += ["%.17g %.17g %.17g" % (0.1 * p[0] + 20, 0.1 * p[1], 0.1 * p[2]) for p in points]
    lines += ["3 %d %d %d" % tuple(t) for t in faces] + ["3 %d %d %d" % tuple(i + n for i in t) for t in faces]
    open(target, "w").write("\n".join(lines) + "\n")

def main():
    os.environ.setdefault("OMP_NUM_THREADS", "1")   # hypre's threads would compete with the other process
    # Open MPI keeps its session directory under TMPDIR/ompi.HOST.UID and removes that directory when a run
    # ends; two tests running at once (ctest -j) then race on it ("A call to mkdir was unable to create the
    # desired directory", seen in CI). Each test gets a private, short TMPDIR (socket paths are limited).
    session = tempfile.mkdtemp(prefix="af-mpi-")
    os.environ["TMPDIR"] = session
    try:
        run_case()
    finally:
        shutil.rmtree(session, ignore_errors=True)

def run_case():
    ap = argparse.ArgumentParser()
    for a in ("--tool", "--mpi", "--mpiexec", "--data", "--example-data", "--work", "--case"): ap.add_argument(a, required=True)
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    closed, bordered = os.path.join(args.data, "bumpy.off"), os.path.join(args.data, "hemisphere.off")
    iso = ["--tensor", "isotropic", "--relative-time-step", "1e-3", "--steps", "3"]
    aniso = ["--tensor", "anisotropic", "--lambda", "8", "--epsilon", "1e-3", "--relative-time-step", "5e-4", "--steps", "3"]
    case = args.case
    if case == "closed_isotropic":
        equal_to_serial(args, case, closed, iso + ["--relative-fidelity", "10"])
        # the preconditioner is PETSc's option: algebraic multigrid gives the same result
        for pc in ("gamg", "hypre"):
            equal_to_serial(args, case + "_" + pc, closed, iso + ["--relative-fidelity", "10"], (2,), ("-pc_type", pc))
    elif case == "closed_anisotropic":
        equal_to_serial(args, case, closed, aniso)
        pair = os.path.join(args.work, "bumpy_two_components.off")
        two_components(closed, pair)
        equal_to_serial(args, case + "_two_components", pair, aniso)
    elif case == "bordered_isotropic":
        equal_to_serial(args, case, bordered, iso)
        lonely = os.path.join(args.work, "hemisphere_isolated_vertex.off")
        with_isolated_vertex(bordered, lonely)
        equal_to_serial(args, case + "_isolated_vertex", lonely, iso)
    elif case == "bordered_anisotropic": equal_to_serial(args, case, bordered, aniso)
    elif case == "coupled_attributes":
        valued = os.path.join(args.work, "bumpy_value.ply")
        make_valued_ply(closed, valued)
        equal_to_serial(args, case, valued, ["--attributes", "value", "--mode", "coupled", "--attribute-weight", "2"] + aniso)
        equal_to_serial(args, case + "_separate", valued, ["--attributes", "value", "--mode", "separate"] + iso)
    elif case == "step_control":
        # the paper's criterion (29) ends the run; a flow that folds the surface: six rejected steps, then
        # the fall-back to the last surface without new folds
        equal_to_serial(args, "displacement_stop", closed, ["--tensor", "isotropic", "--relative-time-step", "1e-2", "--steps", "30"])
        equal_to_serial(args, "folding_fallback", os.path.join(args.data, "bunny.off"),
                        ["--tensor", "anisotropic", "--lambda", "4", "--epsilon", "1e-3", "--relative-time-step", "1e-1", "--steps", "6"])
    elif case == "default_run":
        # no options: the noise estimate, the candidates and their comparison, the stop at the noise level; a
        # scan's PLY with vertex normals gets the faired surface's, as the serial program writes them
        for normals in (False, True):
            scan = os.path.join(args.work, "bunny_noisy%s.ply" % ("_normals" if normals else ""))
            noisy_scan(os.path.join(args.data, "bunny.off"), scan, normals)
            equal_to_serial(args, case + ("_normals" if normals else ""), scan, [])
    elif case == "flow_options":
        # the fourth-order flow (automatic, to the noise level), the stop at the noise level with a given time
        # step, held vertices (a file of indices) and the curvature written (PLY: k1, k2, mean_curvature compared
        # as every other column)
        scan = os.path.join(args.work, "bunny_noisy.ply")
        noisy_scan(os.path.join(args.data, "bunny.off"), scan, False)
        held = os.path.join(args.work, "held.txt")
        open(held, "w").write("\n".join(str(i) for i in range(0, 3485, 7)) + "\n")
        equal_to_serial(args, "fourth_order", scan, ["--order", "4", "--tensor", "isotropic"])
        equal_to_serial(args, "noise_stop", scan, ["--tensor", "isotropic", "--relative-time-step", "0.1", "--stop", "noise"])
        equal_to_serial(args, "held_curvature", scan, aniso + ["--hold", held, "--curvature"])
        # deviation bounds: the default run's, and the attributes-only mode's on its fixed surface
        equal_to_serial(args, "bounded", scan, ["--relative-maximum-deviation", "0.05"])   # 53 rows held, 4 clamped
        valued = os.path.join(args.work, "bumpy_value.ply")
        make_valued_ply(os.path.join(args.data, "bumpy.off"), valued)
        equal_to_serial(args, "attributes_only", valued, ["--attributes", "value", "--mode", "attributes"])
        equal_to_serial(args, "attributes_bounded", valued,
                        ["--attributes", "value", "--mode", "attributes", "--attribute-maximum-deviation", "0.01"])
        for name in ("bounded", "attributes_bounded"):   # the bound held rows: the case tests what it names
            held_rows = json.load(open(os.path.join(args.work, name + "_serial.ply.json")))["bound_held_vertices"]
            if held_rows == 0: sys.exit("FAIL: %s: the bound held no row" % name)
    elif case == "failures": failures(args, closed)
    elif case == "parts":
        import part_cases
        part_cases.parts(args, run, mpi, {"two_components": two_components, "with_isolated_vertex": with_isolated_vertex,
                                          "read_mesh": read_mesh, "relative_difference": relative_difference,
                                          "noisy_scan": noisy_scan})
    elif case == "mesh_part":
        # --mpi names the test program test_mesh_part here: its own checks, on 1, 2 and 3 processes
        for np in (1, 2, 3): print(run(mpi(args, np, args.data)).stdout)
    else: sys.exit("unknown case " + case)

def with_flat_component(source, target):
    """source (OFF) and one more connected component, an octahedron whose vertices coincide: a part of
    the mesh whose limit surface has no area, which only the process assembling it can see."""
    words = [l.split() for l in open(source).read().split("\n") if l.split()]
    n, f = int(words[1][0]), int(words[1][1])
    octahedron = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    with open(target, "w") as out:
        out.write("OFF\n%d %d 0\n" % (n + 6, f + 8))
        for i in range(n): out.write(" ".join(words[2 + i][:3]) + "\n")
        for k in range(6): out.write("10 0 0\n")
        for j in range(f): out.write(" ".join(words[2 + n + j][:4]) + "\n")
        for a, b, c in octahedron: out.write("3 %d %d %d\n" % (n + a, n + b, n + c))
    return f

LIMITED = """import os, resource, sys
# process RANK of the run may allocate at most LIMIT bytes of data (RLIMIT_DATA: the heap and private mappings, not
# the MPI library's shared memory), then it is the program: limited.py RANK LIMIT PROGRAM ARGUMENTS...
if os.environ.get("OMPI_COMM_WORLD_RANK", os.environ.get("PMI_RANK")) == sys.argv[1]:
    resource.setrlimit(resource.RLIMIT_DATA, (int(sys.argv[2]), int(sys.argv[2])))
os.execv(sys.argv[3], sys.argv[3:])
"""

def out_of_memory(args):
    """A process runs out of memory (its data limited) on the armadillo: process 1 holding its part (60 MB), process 0
    holding the whole mesh beside its part (150 MB: a bow-tie PLY file, read whole by process 0; about 200 MB needed):
    the run ends on every process, saying which one ran out; nothing is written."""
    import part_cases
    wrapper = os.path.join(args.work, "limited.py")
    open(wrapper, "w").write(LIMITED)
    mesh = os.path.join(args.data, "armadillo.obj")
    lines = [l.split() for l in open(mesh) if l.startswith(("v ", "f "))]
    points, faces = [l[1:4] for l in lines if l[0] == "v"], [[w.split("/")[0] for w in l[1:]] for l in lines if l[0] == "f"]
    off, bowtie, whole = (os.path.join(args.work, "armadillo" + e) for e in (".off", "_bowtie.off", "_bowtie.ply"))
    open(off, "w").write("OFF\n%d %d 0\n" % (len(points), len(faces)) + "".join(" ".join(p) + "\n" for p in points) +
                         "".join("%d %s\n" % (len(f), " ".join(str(int(i) - 1) for i in f)) for f in faces))
    part_cases.with_bowtie(off, bowtie)
    part_cases.binary_ply(bowtie, whole)
    for rank, megabytes, source in ((1, 60, mesh), (0, 150, whole)):
        mesh = source
        out = os.path.join(args.work, "out_of_memory_%d%s" % (megabytes, os.path.splitext(source)[1]))
        command = mpi(args, 2, mesh, out, "--quiet", "--relative-time-step", "1e-3", "--steps", "2")
        at = command.index(args.mpi)
        command[at:at] = [sys.executable, wrapper, str(rank), str(megabytes << 20)]
        p = subprocess.run(command, capture_output=True, text=True, timeout=300)
        said = [l for l in p.stderr.split("\n") if l.startswith("anisotropic_fairing_mpi: ")]
        print("out of memory (%d MB of data on process %d): exit %d: %s" % (megabytes, rank, p.returncode, said))
        if p.returncode == 0 or not any("out of memory on process %d of 2" % rank in l for l in said):
            sys.exit("FAIL: process 1 out of memory: exit %d, no line naming it\n%s" % (p.returncode, p.stderr))
        if os.path.exists(out): sys.exit("FAIL: out of memory: the output %s was written" % out)

def failures(args, closed):
    # a NaN coordinate in the second half of the vertices
    words = [l for l in open(closed).read().split("\n")]
    bad = os.path.join(args.work, "bumpy_nan.off")
    n = int(words[1].split()[0])
    victim = 3 * n // 4
    words[2 + victim] = "nan 0 0"
    open(bad, "w").write("\n".join(words))
    fails_cleanly(args, "nan_coordinate", bad, ["--relative-time-step", "1e-3", "--steps", "2"], 2, 1, ["line %d" % (victim + 3), "nan"])
    flat = os.path.join(args.work, "bumpy_flat_part.off")
    with_flat_component(closed, flat)
    flags = ["--relative-time-step", "1e-3", "--steps", "2"]
    serial = run([args.tool, flat, os.path.join(args.work, "flat_serial.off"), "--quiet"] + flags, expect_code=1)
    # the same words as the serial library's, which name the component and the face, and the part: with the
    # faces divided in contiguous blocks of the run's order, the flat component's faces (the last) are process 1's
    said = serial.stderr.strip().split("\n")[0].split(": ", 1)[1]
    fails_cleanly(args, "flat_part", flat, flags + ["-mat_partitioning_type", "average"], 2, 1,
                  ["degenerate_metric", "connected component 1", said, "(in the part of process 1)"])
    # every retry of the first step folds the surface: the run fails as the serial one does
    camel = os.path.join(args.data, "camelhead.off")
    flags = ["--tensor", "isotropic", "--relative-time-step", "1", "--steps", "4"]
    serial = run([args.tool, camel, os.path.join(args.work, "camel_serial.off"), "--quiet"] + flags, expect_code=1)
    fails_cleanly(args, "folded_first_step", camel, flags, 2, 1, [serial.stderr.strip().split("\n")[0].split(": ", 1)[1]])
    fails_cleanly(args, "linear_element_refused", closed, ["--element", "linear"], 2, 2, ["--element linear"])
    fails_cleanly(args, "resample_refused", closed, ["--resample", "1"], 1, 2, ["--resample is not supported"])
    out_of_memory(args)
    fails_cleanly(args, "memory_limit_refused", closed, ["--relative-time-step", "1e-3", "--memory-limit", "1G"], 1, 2,
                  ["--memory-limit is not supported"])

if __name__ == "__main__":
    main()
