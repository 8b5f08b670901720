#!/usr/bin/python3
"""The two raw scans (no clean mesh) side by side: the default run, the default run at --strength 2 and GMNF's defaults.

    /usr/bin/python3 bench/gmnf/real_scans.py --tool TOOL --driver GMNF_DRIVER --scans DIR --work DIR [--figures DIR]

DIR holds rabbit.obj and angel.obj (`shared/data/real-scans`, from bldeng/GuidedDenoising's RealData). For each scan
and each result: how far the normals turned and the vertices moved off the input (score.py against the input: mean
face-normal change in degrees, mean vertex distance in units of the input's mean edge), folded edges (as
side_by_side.py counts them), our report's steps and noise level; one Markdown table on stdout. With --figures, one
PNG per scan (scripts/figures/render_mesh.py: input, default run, --strength 2, GMNF's defaults), named
real_scan_<scan>.png. Wall times are not measured here: time the runs with farm-bench side by side.
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import score  # noqa: E402
from side_by_side import folded_edges  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RENDER = os.path.join(HERE, "..", "..", "scripts", "figures", "render_mesh.py")
# camera per scan: (azimuth, elevation), view-up (the angel's range image is seen from -z, head down in y)
VIEWS = {"rabbit": ("25,20", "0,1,0"), "angel": ("180,-30", "0,-1,0")}


def run(args):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(args), p.stderr[-2000:]))
    return p.stdout


def measured(result, scan_path):
    s = score.score(result, scan_path)
    v, t = score.read_mesh(result)
    return s["mean_normal_error_deg"], s["mean_vertex_distance_rel"], folded_edges(v, t)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--driver", required=True)
    ap.add_argument("--scans", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--figures", default="")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    print("| scan | result | normals turned (deg) | moved (h) | folded edges | steps, noise level (h) |")
    print("|---|---|---:|---:|---:|---|")
    for name in ("rabbit", "angel"):
        scan = os.path.join(a.scans, name + ".obj")
        v, t = score.read_mesh(scan)
        print("| %s | input (%d vertices) | - | - | %d | - |" % (name, len(v), folded_edges(v, t)))
        outputs = []
        for label, extra in (("default run", []), ("--strength 2", ["--strength", "2"])):
            out = os.path.join(a.work, "%s_%s.off" % (name, "default" if not extra else "strength2"))
            report = out[:-4] + ".json"
            run([a.tool, scan, out, "--quiet", "--report", report] + extra)
            r = json.load(open(report))
            turned, moved, folds = measured(out, scan)
            print("| %s | %s | %.2f | %.3f | %d | %d, %.4f |" % (name, label, turned, moved, folds, len(r["steps"]),
                                                             r["noise_level"]))
            outputs.append((label, out))
        out = os.path.join(a.work, "%s_gmnf.off" % name)
        run([a.driver, "gmnf", scan, out])
        turned, moved, folds = measured(out, scan)
        print("| %s | GMNF's defaults | %.2f | %.3f | %d | - |" % (name, turned, moved, folds))
        outputs.append(("GMNF defaults", out))
        if a.figures:
            view, up = VIEWS[name]
            titles = [x for label, _ in [("input", scan)] + outputs for x in ("--title", label)]
            run(["/usr/bin/python3", RENDER, "--output", os.path.join(a.figures, "real_scan_%s.png" % name),
                 "--size", "2000x560", "--view", view, "--up", up] + titles + [scan] + [o for _, o in outputs])


if __name__ == "__main__":
    main()
