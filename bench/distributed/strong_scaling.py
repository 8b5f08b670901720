#!/usr/bin/env python3
# Strong scaling of anisotropic_fairing_mpi: the same run on 1 and 2 processes (and each preconditioner:
# PETSc's Jacobi, GAMG, hypre BoomerAMG) on a Loop-refined mesh, from the program's JSON reports: seconds
# per phase, CG iterations per solve, peak memory per process and the values a process receives per CG
# iteration (its off-process columns, per column of unknowns; 8 bytes each).
#   python3 bench/distributed/strong_scaling.py --build build [--mesh M.off] [--levels 2] [--work DIR]
# Without --mesh: /work/shared/data/fertility.off refined by anisotropic_fairing --resample LEVELS.
import argparse, json, os, subprocess, sys

def run(command):
    p = subprocess.run(command, capture_output=True, text=True)
    if p.returncode != 0: sys.exit("failed: %s\n%s" % (" ".join(command), p.stderr))

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--mesh")
    ap.add_argument("--levels", type=int, default=2)
    ap.add_argument("--work", default="/tmp/af_strong_scaling")
    ap.add_argument("--steps", default="3")
    ap.add_argument("--relative-time-step", default="1e-3")
    ap.add_argument("--tensor", default="isotropic")
    ap.add_argument("--processes", default="1,2")
    ap.add_argument("--preconditioners", default="jacobi,gamg,hypre")
    a = ap.parse_args()
    # one thread per process: hypre's OpenMP threads would otherwise compete with the other process
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    os.makedirs(a.work, exist_ok=True)
    tool, mpi = os.path.join(a.build, "bin", "anisotropic_fairing"), os.path.join(a.build, "bin", "anisotropic_fairing_mpi")
    mesh = a.mesh
    if not mesh:
        mesh = os.path.join(a.work, "fertility_r%d.off" % a.levels)
        if not os.path.exists(mesh):   # one tiny isotropic step, then the limit surface refined
            run([tool, "/work/shared/data/fertility.off", mesh, "--quiet", "--tensor", "isotropic", "--relative-time-step", "1e-7",
                 "--steps", "1", "--resample", str(a.levels)])
    flags = ["--quiet", "--tensor", a.tensor, "--relative-time-step", a.relative_time_step, "--steps", a.steps, "--stop", "off"]
    if a.tensor == "anisotropic": flags += ["--lambda", "8", "--epsilon", "1e-3"]
    print("mesh %s, %s, %s steps of %s l^2" % (mesh, a.tensor, a.steps, a.relative_time_step))
    print("%3s %-7s %8s %8s %8s %8s %10s %14s %22s" % ("np", "pc", "flow s", "solve s", "assem s", "wall s", "CG its/step", "peak MB/proc",
                                                    "recv doubles/CG it/proc"))
    for pc in a.preconditioners.split(","):
        for np in a.processes.split(","):
            report = os.path.join(a.work, "np%s_%s.json" % (np, pc))
            out = os.path.join(a.work, "np%s_%s.off" % (np, pc))
            run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np, mpi, mesh, out, "--report", report] + flags +
                ["-pc_type", pc])
            j = json.load(open(report))
            s = j["seconds"]
            wall = s["read"] + s["setup"] + s["partition"] + s["flow"] + s["write"]
            per = j["per_process"]
            print("%3s %-7s %8.2f %8.2f %8.2f %8.2f %10.1f %14s %22s" % (np, pc, s["flow"], s["solve"], s["assemble"], wall,
                  j["cg_iterations"] / max(1, j["solves"]), ",".join("%.0f" % m for m in per["peak_memory_mb"]),
                  ",".join(str(c) for c in per["matvec_doubles_received"])))

if __name__ == "__main__":
    main()
