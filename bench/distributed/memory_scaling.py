#!/usr/bin/env python3
# What a process of anisotropic_fairing_mpi holds, and how it scales: the same run on 1 and 2 processes
# (strong scaling: p1, p2 the peak of a process; what every process holds whatever their number, R = 2 p2 - p1,
# and the part divided among them, D = p1 - R, give the model p(P) = R + D / P), and the mesh doubled with the
# processes (weak scaling: the mesh beside a translated copy of itself, on 2 processes: each copy one part, so
# no value crosses between the parts in a CG product); with the values a
# process receives per CG iteration (its off-process columns, per column of unknowns) and per refresh of the
# rows every process holds (Whole_rows.h). With --parts the meshes are binary PLY files, which each process reads by
# blocks and holds its part of (distributed/Part_run.cpp); else every process holds the whole mesh.
#   python3 bench/distributed/memory_scaling.py --build build [--levels 3] [--work DIR] [--flags "..."] [--parts]
# The mesh: /work/shared/data/fertility.off refined LEVELS times on its limit surface, with Gaussian noise of
# 0.2 mean edge lengths; the doubled mesh: it and its copy. Default run: one isotropic step (--flags).
import argparse, json, math, os, random, subprocess, sys, time

from mesh_files import read_off, run, write_binary_ply, write_off

def meshes(tool, work, levels):
    """the noisy refined fertility and its doubled copy"""
    single, double = os.path.join(work, "fertility_r%d_noisy.off" % levels), os.path.join(work, "fertility_r%d_noisy_x2.off" % levels)
    if os.path.exists(single) and os.path.exists(double): return single, double
    refined = os.path.join(work, "fertility_r%d.off" % levels)
    run([tool, "/work/shared/data/fertility.off", refined, "--quiet", "--tensor", "isotropic", "--relative-time-step", "1e-7",
         "--steps", "1", "--resample", str(levels)])
    points, faces = read_off(refined)
    edge = sum(math.dist(points[t[0]], points[t[1]]) for t in faces[:20000]) / min(len(faces), 20000)
    rng = random.Random(5)
    points = [[x + 0.2 * edge * rng.gauss(0, 1) for x in p] for p in points]
    write_off(single, points, faces)
    width = max(p[0] for p in points) - min(p[0] for p in points)
    n = len(points)
    write_off(double, points + [[p[0] + 1.5 * width, p[1], p[2]] for p in points],
              faces + [[a + n, b + n, c + n] for a, b, c in faces])
    return single, double

def as_binary_ply(off):
    target = os.path.splitext(off)[0] + ".ply"
    if not os.path.exists(target): write_binary_ply(target, *read_off(off))
    return target

def measure(mpi, mesh, processes, flags, work):
    out = os.path.join(work, "out_np%d_%s" % (processes, os.path.basename(mesh)))
    report = out + ".json"
    wall = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(processes), mpi, mesh, out, "--quiet",
                "--report", report] + flags)
    j = json.load(open(report))
    os.remove(out)
    return wall, j

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--levels", type=int, default=3)
    ap.add_argument("--work", default="/tmp/af_memory_scaling")
    ap.add_argument("--flags", default="--tensor isotropic --relative-time-step 1e-3 --steps 1 --stop off")
    ap.add_argument("--parts", action="store_true", help="the meshes as binary PLY: each process holds its part")
    a = ap.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    os.makedirs(a.work, exist_ok=True)
    tool, mpi = os.path.join(a.build, "bin", "anisotropic_fairing"), os.path.join(a.build, "bin", "anisotropic_fairing_mpi")
    single, double = meshes(tool, a.work, a.levels)
    if a.parts: single, double = as_binary_ply(single), as_binary_ply(double)
    flags = a.flags.split()
    print("run: %s (%s)" % (a.flags, "each process holds its part of the mesh" if a.parts else "every process holds the whole mesh"))
    print("| mesh | faces | processes | wall s | flow s | peak MB per process | CG its | values received per CG product, per process "
          "| doubles received per refresh of the whole rows, per process |")
    print("|---|---:|---:|---:|---:|---|---:|---|---:|")
    peaks = {}
    for mesh, processes in ((single, 1), (single, 2), (double, 2)):
        wall, j = measure(mpi, mesh, processes, flags, a.work)
        if (j["mesh_held"] == "parts") != a.parts: sys.exit("the mesh was held %s: %s" % (j["mesh_held"], j.get("whole_mesh_why")))
        per = j["per_process"]
        peaks[(mesh, processes)] = per["peak_memory_mb"]
        refresh = max(per["overlap_doubles_received"]) / max(1, j["overlap_refreshes"])
        print("| %s | %d | %d | %.1f | %.1f | %s | %d | %s | %.0f |" % (os.path.basename(mesh), j["faces"], processes, wall,
              j["seconds"]["flow"], ", ".join("%.0f" % m for m in per["peak_memory_mb"]), j["cg_iterations"],
              ", ".join(str(c) for c in per["matvec_doubles_received"]), refresh))
        sys.stdout.flush()
    p1, p2 = peaks[(single, 1)][0], max(peaks[(single, 2)])
    held = 2 * p2 - p1
    divided = p1 - held
    print("\nstrong scaling on %s: p1 %.0f MB, p2 %.0f MB: every process holds R = 2 p2 - p1 = %.0f MB (%.0f%% of p1), "
          "D = p1 - R = %.0f MB is divided" % (os.path.basename(single), p1, p2, held, 100 * held / p1, divided))
    for P in (64, 1024):
        print("model p(%d) = R + D / %d = %.0f MB per process" % (P, P, held + divided / P))
    print("weak scaling: 1 process on %s %.0f MB, 2 processes on %s %s MB" % (os.path.basename(single), peaks[(single, 1)][0],
          os.path.basename(double), ", ".join("%.0f" % m for m in peaks[(double, 2)])))

if __name__ == "__main__":
    main()
