#!/usr/bin/env python3
# The default run (no options) of anisotropic_fairing_mpi on 1 and 2 processes beside the serial program's
# (anisotropic_fairing, TBB on every core), on the same input in one run: median wall seconds of REPEAT runs,
# peak memory per process (the reports' peak_memory_mb), the largest difference of the result to the serial
# program's (relative to the bounding box's diagonal), and the decisions (steps, the tensor kept).
#   python3 bench/distributed/default_run.py --build build [--mesh M]... [--repeat 3] [--work DIR]
# Without --mesh: /work/shared/data/real-scans/rabbit.obj, and fertility refined twice on its limit surface
# (144,000 faces) with Gaussian noise of 0.2 mean edge lengths.
import argparse, json, math, os, random, statistics, subprocess, sys, time

from mesh_files import read_off, run

def noisy_fertility(tool, work):
    """fertility refined twice, with noise (0.2 mean edge lengths, seed 5), as an OFF file"""
    target = os.path.join(work, "fertility_r2_noisy.off")
    if os.path.exists(target): return target
    refined = os.path.join(work, "fertility_r2.off")
    run([tool, "/work/shared/data/fertility.off", refined, "--quiet", "--tensor", "isotropic", "--relative-time-step", "1e-7",
         "--steps", "1", "--resample", "2"])
    points, faces = read_off(refined)
    edge = sum(math.dist(points[t[k]], points[t[(k + 1) % 3]]) for t in faces for k in range(3)) / (3 * len(faces))
    rng = random.Random(5)
    with open(target, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points: out.write("%.17g %.17g %.17g\n" % tuple(x + 0.2 * edge * rng.gauss(0, 1) for x in p))
        for t in faces: out.write("3 %d %d %d\n" % tuple(t))
    return target

def vertices_of(path):
    """the vertex rows of an OFF or OBJ file written by the programs (--text)"""
    if path.endswith(".obj"):
        return [[float(x) for x in l.split()[1:4]] for l in open(path) if l.startswith("v ")]
    return read_off(path)[0]

def difference(a, b):
    diagonal = math.sqrt(sum((max(r[c] for r in b) - min(r[c] for r in b)) ** 2 for c in range(3)))
    return max(abs(x[c] - y[c]) for x, y in zip(a, b) for c in range(3)) / diagonal

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--mesh", action="append")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--processes", default="1,2")
    ap.add_argument("--work", default="/tmp/af_distributed_default")
    a = ap.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    os.makedirs(a.work, exist_ok=True)
    tool, mpi = os.path.join(a.build, "bin", "anisotropic_fairing"), os.path.join(a.build, "bin", "anisotropic_fairing_mpi")
    meshes = a.mesh or ["/work/shared/data/real-scans/rabbit.obj", noisy_fertility(tool, a.work)]
    print("| mesh | program | processes | wall s (median of %d) | peak MB per process | steps | kept | difference to serial |" % a.repeat)
    print("|---|---|---:|---:|---|---:|---|---:|")
    for mesh in meshes:
        name, ext = os.path.splitext(os.path.basename(mesh))
        serial = os.path.join(a.work, name + "_serial" + ext)
        configs = [("anisotropic_fairing", 0)] + [("anisotropic_fairing_mpi", int(np)) for np in a.processes.split(",")]
        for program, np in configs:
            out = os.path.join(a.work, "%s_%s%s" % (name, "serial" if np == 0 else "np%d" % np, ext))
            report = out + ".json"
            command = [tool, mesh, out, "--quiet", "--report", report] if np == 0 else \
                ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np), mpi, mesh, out, "--quiet", "--report", report]
            times = [run(command) for _ in range(a.repeat)]
            j = json.load(open(report))
            peak = [j["peak_memory_mb"]] if np == 0 else j["per_process"]["peak_memory_mb"]
            kept = j["tensor"] if np == 0 else j["selected_tensor"]
            d = 0.0 if np == 0 else difference(vertices_of(out), vertices_of(serial))
            print("| %s | %s | %s | %.2f | %s | %d | %s | %.2g |" % (name, program, "-" if np == 0 else np, statistics.median(times),
                  ", ".join("%.0f" % m for m in peak), len(j["steps"]), kept, d))
            sys.stdout.flush()

if __name__ == "__main__":
    main()
