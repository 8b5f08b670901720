#!/usr/bin/env python3
# The plot of strong_scaling.py's runs: per preconditioner, the flow's seconds (assembly and solve) and the
# peak memory of each process against the number of processes, from the JSON reports in its --work folder.
#   /usr/bin/python3 bench/distributed/plot_scaling.py WORK_DIR OUT.png   (Debian python3-matplotlib)
import glob, json, os, re, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

def main():
    work, out = sys.argv[1], sys.argv[2]
    runs = {}
    for path in glob.glob(os.path.join(work, "np*_*.json")):
        m = re.match(r"np(\d+)_(\w+)\.json", os.path.basename(path))
        runs.setdefault(m.group(2), {})[int(m.group(1))] = json.load(open(path))
    fig, (time_ax, memory_ax) = plt.subplots(1, 2, figsize=(9, 3.6))
    for pc, by_np in sorted(runs.items()):
        nps = sorted(by_np)
        solve = [by_np[n]["seconds"]["solve"] for n in nps]
        assemble = [by_np[n]["seconds"]["assemble"] for n in nps]
        line, = time_ax.plot(nps, [a + s for a, s in zip(assemble, solve)], "o-", label=pc + ": assembly + solve")
        time_ax.plot(nps, assemble, "s--", color=line.get_color(), alpha=0.6, label=pc + ": assembly")
        memory_ax.plot(nps, [max(by_np[n]["per_process"]["peak_memory_mb"]) for n in nps], "o-", color=line.get_color(), label=pc)
    time_ax.set(xlabel="processes", ylabel="seconds (3 steps)", title="one run, strong scaling")
    memory_ax.set(xlabel="processes", ylabel="MB", title="peak memory of a process")
    for ax in (time_ax, memory_ax):
        ax.set_xticks(sorted({n for r in runs.values() for n in r}))
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)

if __name__ == "__main__":
    main()
