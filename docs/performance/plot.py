#!/usr/bin/python3
"""Plot docs/performance/benchmark.csv (written by run.sh): median over
repeats of the neighbour-list build time (half stencil, full stencil, brute
force) and of the full step time against N, one and two threads.
Writes search-vs-N.png and prints the medians as a Markdown table."""
import csv
import os
import statistics
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, "benchmark.csv"))))

groups = defaultdict(list)
for r in rows:
    key = (r["case"], r["integrator"], int(r["N"]), int(r["threads"]), float(r["attractionCutoff"]))
    groups[key].append(r)


def med(rs, col):
    vals = [float(r[col]) for r in rs if r[col] not in ("nan", "")]
    return statistics.median(vals) if vals else float("nan")


cols = ["build_half_ms", "build_full_ms", "build_brute_ms", "step_ms",
        "ns_per_particle_step", "dt", "s_per_strain", "cg_iterations",
        "pairs_per_particle", "list_bytes_per_particle",
        "paper_NxM_bytes_per_particle", "time_v_max_rss_MB"]
print("| case | integrator | N | threads | attraction cut-off | " + " | ".join(cols) + " |")
print("|" + "---|" * (5 + len(cols)))
for key in sorted(groups):
    rs = groups[key]
    print("| %s | %s | %d | %d | %g | " % key + " | ".join("%.4g" % med(rs, c) for c in cols) + " |")

fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for threads, style in ((1, "-"), (2, "--")):
    sel = sorted((k for k in groups if k[0] == "table3" and k[3] == threads and k[4] == 0.5),
                 key=lambda k: k[2])
    N = [k[2] for k in sel]
    for col, label, color in (("build_half_ms", "list build, half stencil", "C0"),
                              ("build_full_ms", "list build, full stencil", "C1"),
                              ("build_brute_ms", "list build, brute force", "C3"),
                              ("step_ms", "full step (all forces)", "k")):
        y = [med(groups[k], col) for k in sel]
        ax[0].loglog(N, y, style, marker="o", color=color,
                     label="%s, %d thread%s" % (label, threads, "s" if threads > 1 else ""))
    ax[1].semilogx(N, [med(groups[k], "ns_per_particle_step") for k in sel], style,
                   marker="o", color="k", label="%d thread%s" % (threads, "s" if threads > 1 else ""))
ax[0].set_xlabel("N")
ax[0].set_ylabel("wall time [ms]")
ax[0].set_title("Table 3 suspension (a2/a1 = 3, phi = 0.5)")
ax[0].legend(fontsize=7)
ax[1].set_xlabel("N")
ax[1].set_ylabel("ns per particle-step")
ax[1].axhline(1000, color="gray", lw=0.8)
ax[1].set_ylim(bottom=0)
ax[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "search-vs-N.png"), dpi=120)
print("wrote search-vs-N.png")
