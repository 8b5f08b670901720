#!/usr/bin/env python3
"""side_by_side.py: our command-line tool, GMNF and BNF on the same cases, in one run.

  side_by_side.py --tool TOOL --driver DRIVER --cases DIR --work DIR
                  [--only SUBSTRING[,SUBSTRING...]] [--runs 3] [--out results_all.md] [--redo]
                  [--timeout SECONDS] [--table-only]

DIR (--cases) holds one folder per case with noisy.off and original.off, as written by
bench/write_cases (`write_cases OUT_DIR`). For every case folder whose name contains one of the --only
substrings (all when not given), one process at a time:
  (a) ours:  TOOL noisy.off ours.off --quiet --report ours.json   (whole-process wall time, median of --runs;
             the kept candidate ("selected_tensor", else "tensor"), the number of steps and "stop_reason"
             are read from the report)
  (b) GMNF with the published defaults of the authors' class (whole-process wall time, median of --runs)
  (c) GMNF tuned: best normal error over sigma_r {0.2,0.3,0.35,0.5} x local normal iterations {5,10,20,40},
      one run each (an oracle: chosen against the original)
  (d) BNF (Zheng et al.'s bilateral normal filtering, the authors' class) with its defaults, one run.
Every result is scored with score.py (mean face-normal error in degrees; mean vertex distance, also in units
of the original's mean edge length) and its folded edges are counted (interior edges whose two unit face
normals have a dot product < -0.5), as are those of the noisy input. Results with non-finite vertices are
marked NaN, non-zero exit codes as crashed / failed.

One JSON line per case goes to WORK/side_by_side.jsonl; cases already there are skipped unless --redo
(so an interrupted run resumes). The markdown table (every case of --cases found in the JSONL) goes to
--out (default: results_all.md next to this script). Needs numpy (Debian's /usr/bin/python3).
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import score  # noqa: E402

SIGMAS = [0.2, 0.3, 0.35, 0.5]
ITERS = [5, 10, 20, 40]
ITER_KEY = "local_normal_iteration_num"
FOLD_DOT = -0.5


def folded_edges(v, t):
    """Interior edges (exactly two incident triangles) whose unit face normals have dot < FOLD_DOT."""
    n, ok = score.face_normals(v, t)
    n[~ok] = 0.0
    nf = len(t)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    e.sort(axis=1)
    face = np.tile(np.arange(nf), 3)
    key = e[:, 0] * (int(e.max()) + 1 if len(e) else 1) + e[:, 1]
    order = np.argsort(key, kind="stable")
    key, face = key[order], face[order]
    uniq, start, count = np.unique(key, return_index=True, return_counts=True)
    two = start[count == 2]
    f1, f2 = face[two], face[two + 1]
    with np.errstate(invalid="ignore"):
        d = np.einsum("ij,ij->i", n[f1], n[f2])
    return int((d < FOLD_DOT).sum())


def run_process(args, timeout):
    t0 = time.perf_counter()
    try:
        p = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
        rc, out, err = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired as e:
        rc, out, err = "timeout", (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or ""), "timeout"
    return rc, time.perf_counter() - t0, out, err


def evaluate(out_path, case, rec):
    """Adds the score and the fold count of out_path to rec (in place)."""
    try:
        s = score.score(out_path, case["original_path"], case["original_mesh"])
        v, t = score.read_mesh(out_path)
        rec["score"] = {k: s[k] for k in ("mean_normal_error_deg", "mean_vertex_distance", "mean_vertex_distance_rel",
                                          "non_finite_vertices", "degenerate_faces")}
        rec["folded_edges"] = folded_edges(v, t) if s["non_finite_vertices"] == 0 else None
    except (OSError, ValueError, IndexError) as e:
        rec["score_error"] = str(e)


def run_ours(tool, case, work, runs, timeout):
    out, rep = os.path.join(work, "ours.off"), os.path.join(work, "ours.json")
    times, rec = [], {}
    for _ in range(runs):
        for f in (out, rep):
            if os.path.exists(f):
                os.remove(f)
        rc, wall, _, err = run_process([tool, case["noisy_path"], out, "--quiet", "--report", rep], timeout)
        times.append(wall)
        rec = {"returncode": rc, "stderr": err.strip()[-2000:]}
        if rc != 0:
            break
    rec["process_seconds_all"] = times
    rec["process_seconds"] = statistics.median(times)
    try:
        with open(rep) as f:
            j = json.load(f)
        rec["status"] = j.get("status")
        rec["kept"] = j.get("selected_tensor") or j.get("tensor")
        rec["steps"] = len(j["steps"]) if isinstance(j.get("steps"), list) else j.get("steps")
        rec["stop_reason"] = j.get("stop_reason")
        rec["total_seconds"] = j.get("total_seconds")
    except (OSError, ValueError) as e:
        rec["report_error"] = str(e)
    if rec["returncode"] == 0 and os.path.exists(out):
        evaluate(out, case, rec)
    return rec


def run_peer(driver, algorithm, case, out, params, runs, timeout):
    args = [driver, algorithm, case["noisy_path"], out] + [f"{k}={v}" for k, v in params]
    times, rec = [], {}
    for _ in range(runs):
        if os.path.exists(out):
            os.remove(out)
        rc, wall, stdout, err = run_process(args, timeout)
        times.append(wall)
        rec = {"returncode": rc, "stderr": err.strip()[-2000:]}
        if rc != 0:
            break
        try:
            d = json.loads(stdout.strip().splitlines()[-1])
            rec.setdefault("seconds_all", []).append(d.get("seconds"))
            rec["non_finite_vertices_driver"] = d.get("non_finite_vertices")
        except (ValueError, IndexError) as e:
            rec["driver_output_error"] = str(e)
    rec["overrides"] = dict(params)
    rec["process_seconds_all"] = times
    rec["process_seconds"] = statistics.median(times)
    if rec["returncode"] == 0 and os.path.exists(out):
        evaluate(out, case, rec)
    return rec


def err(rec):
    s = rec.get("score") if rec else None
    if not s or s["mean_normal_error_deg"] is None or s["non_finite_vertices"]:
        return float("nan")
    return s["mean_normal_error_deg"]


def failure(rec):
    """'' for a usable result, else a short word for the table."""
    if not rec:
        return "n/a"
    rc = rec.get("returncode", 0)   # the noisy input's record has no process
    if rc == "timeout":
        return "timeout"
    if rc != 0:
        return f"crash (rc {rc})" if isinstance(rc, int) and rc < 0 else f"failed (rc {rc})"
    s = rec.get("score")
    if not s:
        return "unscored"
    if s["non_finite_vertices"]:
        return f"NaN ({s['non_finite_vertices']} v)"
    return ""


def do_case(a, name):
    cdir = os.path.join(a.cases, name)
    work = os.path.join(a.work, name)
    os.makedirs(work, exist_ok=True)
    orig_path, noisy_path = os.path.join(cdir, "original.off"), os.path.join(cdir, "noisy.off")
    case = {"original_path": orig_path, "noisy_path": noisy_path, "original_mesh": score.read_mesh(orig_path)}
    rec = {"case": name, "runs": a.runs, "date": datetime.datetime.now().isoformat(timespec="seconds")}
    noisy = {}
    evaluate(noisy_path, case, noisy)
    rec["noisy"] = noisy
    rec["faces"] = int(len(case["original_mesh"][1]))
    rec["vertices"] = int(len(case["original_mesh"][0]))
    print(f"== {name}: {rec['faces']} faces, noisy error {err(noisy):.3f}, folds {noisy.get('folded_edges')}", flush=True)

    rec["ours"] = run_ours(a.tool, case, work, a.runs, a.timeout)
    o = rec["ours"]
    print(f"   ours: {failure(o) or format(err(o), '.3f')} ({o['process_seconds']:.2f} s, {o.get('kept')}, "
          f"{o.get('steps')} steps, {o.get('stop_reason')})", flush=True)
    rec["gmnf_default"] = run_peer(a.driver, "gmnf", case, os.path.join(work, "gmnf_default.off"), [], a.runs, a.timeout)
    g = rec["gmnf_default"]
    print(f"   GMNF default: {failure(g) or format(err(g), '.3f')} ({g['process_seconds']:.2f} s)", flush=True)
    grid = []
    best = None
    for s in SIGMAS:
        for n in ITERS:
            out = os.path.join(work, f"gmnf_s{s}_n{n}.off")
            r = run_peer(a.driver, "gmnf", case, out, [("sigma_r", s), (ITER_KEY, n)], 1, a.timeout)
            grid.append(r)
            e = err(r)
            if e == e and (best is None or e < err(best)):
                if best is not None and os.path.exists(best["_out"]):
                    os.remove(best["_out"])
                best = r
                best["_out"] = out
            elif os.path.exists(out):
                os.remove(out)   # keep only the best grid result on disk
    for r in grid:
        r.pop("_out", None)
    rec["gmnf_grid"] = grid
    rec["gmnf_tuned"] = best
    print("   GMNF tuned: " + (f"{err(best):.3f} (sigma_r {best['overrides']['sigma_r']}, iters "
                               f"{best['overrides'][ITER_KEY]})" if best else "none finite"), flush=True)
    rec["bnf_default"] = run_peer(a.driver, "bnf", case, os.path.join(work, "bnf_default.off"), [], 1, a.timeout)
    b = rec["bnf_default"]
    print(f"   BNF default: {failure(b) or format(err(b), '.3f')} ({b['process_seconds']:.2f} s)", flush=True)
    return rec


def f3(x):
    return "n/a" if x is None or x != x else f"{x:.3f}"


def cell_err(rec):
    return failure(rec) or f3(err(rec))


def cell_dist(rec):
    if failure(rec):
        return "–"
    d = rec["score"].get("mean_vertex_distance_rel")
    return "n/a" if d is None else f"{d:.3f}"


def cell_folds(rec):
    if failure(rec):
        return "–"
    f = rec.get("folded_edges")
    return "n/a" if f is None else str(f)


def write_table(a, records, names):
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    rows = [records[n] for n in names if n in records]
    runs = sorted({r["runs"] for r in rows})
    L = []
    L.append("# Ours, GMNF and BNF side by side on every benchmark case")
    L.append("")
    L.append(f"Produced by `bench/gmnf/side_by_side.py` on {datetime.date.today().isoformat()}; machine: "
             f"{os.cpu_count()} cores (`nproc`), {cpu}, {platform.machine()}. GMNF and BNF are the authors' classes "
             "(bldeng/GuidedDenoising) through `gmnf_driver` and are **single threaded**; our tool "
             f"(`anisotropic_fairing`, Release) uses the machine's {os.cpu_count()} threads (TBB). "
             "Cases: `bench/write_cases` (the denoising pairs and 5 models × 7 generated noises).")
    L.append("")
    L.append("* err: mean face-normal error in degrees against original.off (score.py). dist: mean vertex "
             "distance in units of the original's mean edge length. folds: interior edges whose two face normals "
             "have a dot product < -0.5. NaN: result with non-finite vertices; crash/failed: non-zero exit.")
    L.append("* time: whole-process wall time in seconds (read + denoise + write), median of the number of runs "
             "given in the runs column; one process at a time.")
    L.append("* ours default: `anisotropic_fairing noisy.off out.off --quiet --report r.json`; kept = the candidate "
             "kept by the automatic parameters (report `tensor`), steps and stop reason from the report.")
    L.append("* GMNF tuned: best normal error over sigma_r {0.2, 0.3, 0.35, 0.5} × local normal iterations "
             "{5, 10, 20, 40} (other parameters at the defaults; default is sigma_r 0.35, 20), chosen against "
             "the original: an oracle, not a setting a user could pick blind. BNF: defaults.")
    L.append("* ratios: our normal error / GMNF's (lower is better for ours).")
    L.append("")
    L.append("| case | faces | runs | noisy err | noisy folds | ours err | ours dist | ours folds | ours time | kept, steps, stop "
             "| GMNF def. err | GMNF dist | GMNF folds | GMNF time | GMNF tuned err (sigma_r, iters) | BNF def. err "
             "| ours/GMNF def. | ours/GMNF tuned |")
    L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---|---:|---:|---:|")
    n_cmp = n_le = n_cmp_t = n_within = 0
    worse, gmnf_failed, ours_failed = [], [], []
    for r in rows:
        o, g, t, b = r["ours"], r["gmnf_default"], r.get("gmnf_tuned"), r["bnf_default"]
        eo, eg, et = err(o), err(g), err(t)
        if t:
            tuned = f"{f3(et)} ({t['overrides']['sigma_r']}, {t['overrides'][ITER_KEY]})"
        else:
            fails = {failure(x) for x in r["gmnf_grid"]}
            tuned = "all " + "/".join(sorted(x.split(" (")[0] for x in fails))
        r1 = eo / eg if eo == eo and eg == eg and eg > 0 else float("nan")
        r2 = eo / et if eo == eo and et == et and et > 0 else float("nan")
        if r1 == r1:
            n_cmp += 1
            n_le += eo <= eg
            if eo > eg:
                worse.append((r["case"], eo, eg))
        if r2 == r2:
            n_cmp_t += 1
            n_within += r2 <= 1.25
        if failure(g):
            gmnf_failed.append(r["case"])
        if failure(o):
            ours_failed.append(r["case"])
        kept = f"{o.get('kept')}, {o.get('steps')}, {o.get('stop_reason')}"
        L.append("| " + " | ".join([
            r["case"], str(r["faces"]), str(r["runs"]), cell_err(r["noisy"]), cell_folds(r["noisy"]),
            cell_err(o), cell_dist(o), cell_folds(o), f"{o['process_seconds']:.2f}", kept,
            cell_err(g), cell_dist(g), cell_folds(g), f"{g['process_seconds']:.2f}", tuned, cell_err(b),
            "n/a" if r1 != r1 else f"{r1:.2f}", "n/a" if r2 != r2 else f"{r2:.2f}"]) + " |")
    L.append("")
    L.append(f"**Summary ({len(rows)} cases):** ours <= GMNF default on {n_le} of {n_cmp} cases where both gave a "
             f"finite result; ours within 1.25x of the best tuned GMNF on {n_within} of {n_cmp_t}. "
             f"GMNF default failed (NaN/crash) on {len(gmnf_failed)}" + (f" ({', '.join(gmnf_failed)})" if gmnf_failed else "")
             + f"; ours failed on {len(ours_failed)}" + (f" ({', '.join(ours_failed)})" if ours_failed else "") + ".")
    L.append("")
    if worse:
        L.append("Cases where ours is worse than GMNF default (ours vs GMNF): " + "; ".join(
            f"{c} {x:.3f} vs {y:.3f}" for c, x, y in worse) + ".")
        L.append("")
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")
    print("\n".join(L[-4:]))
    print(f"wrote {a.out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--driver", required=True)
    ap.add_argument("--cases", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--only", default="", help="run only cases whose name contains one of these comma-separated substrings")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "results_all.md"))
    ap.add_argument("--redo", action="store_true", help="run cases again even if they are in the JSONL")
    ap.add_argument("--timeout", type=float, default=1800, help="seconds per process")
    ap.add_argument("--table-only", action="store_true", help="only write the table from the JSONL")
    a = ap.parse_args()

    names = sorted(d for d in os.listdir(a.cases)
                   if os.path.isfile(os.path.join(a.cases, d, "noisy.off"))
                   and os.path.isfile(os.path.join(a.cases, d, "original.off")))
    only = [s for s in a.only.split(",") if s]
    todo = [n for n in names if not only or any(s in n for s in only)]
    os.makedirs(a.work, exist_ok=True)
    jsonl = os.path.join(a.work, "side_by_side.jsonl")
    records = {}
    if os.path.exists(jsonl):
        with open(jsonl) as f:
            for line in f:
                line = line.strip()
                if line:
                    r = json.loads(line)
                    records[r["case"]] = r   # a later line (a --redo) replaces an earlier one
    if not a.table_only:
        with open(jsonl, "a") as log:
            for name in todo:
                if name in records and not a.redo:
                    print(f"== {name}: in {jsonl}, skipped", flush=True)
                    continue
                rec = do_case(a, name)
                log.write(json.dumps(rec) + "\n")
                log.flush()
                records[name] = rec
    write_table(a, records, names)


if __name__ == "__main__":
    main()
