#!/usr/bin/env python3
"""Table of docs/performance.md from engine-v2.csv (docs/performance/engine-v2.sh):
per case the medians of the v2 and reference runs, the median of the paired
ratios reference/v2 with its range, and the thread speed-up of v2.
    docs/performance/engine-v2.py > docs/performance/engine-v2.md
"""
import csv
import os
import statistics

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, "engine-v2.csv"))))


def key(r):
    return (r["case"], r["integrator"], r["N"], r["threads"], r["attractionCutoff"])


def label(k):
    case, integrator, N, threads, cutoff = k
    s = f"{case}, {integrator}, N = {N}, {threads} thread{'s' if threads != '1' else ''}"
    if case == "table3":
        s += f", attraction cut-off {cutoff} a0"
    return s


def med(xs):
    return statistics.median(xs)


cases = []
for r in rows:
    if key(r) not in cases:
        cases.append(key(r))

print("| case | quantity | v2 median | reference median | reference/v2, paired: median (min-max) |")
print("|---|---|---|---|---|")
for k in cases:
    v2 = [r for r in rows if key(r) == k and r["engine"] == "v2"]
    ref = [r for r in rows if key(r) == k and r["engine"] == "reference"]
    if not ref:
        continue
    quantities = [("ns per particle-step (median step, wall)", "ns_per_particle_step", "%.0f"),
                  ("process CPU s", "cpu_s", "%.2f"),
                  ("process wall s", "wall_s", "%.2f"),
                  ("peak RSS MB", "time_v_max_rss_MB", "%.1f"),
                  ("list bytes per particle", "list_bytes_per_particle", "%.0f")]
    if k[1] != "velocityVerlet":
        quantities.insert(1, ("s per strain (median step/dt)", "s_per_strain", "%.1f"))
    for name, col, fmt in quantities:
        a = [float(r[col]) for r in v2]
        b = [float(r[col]) for r in ref]
        ratios = [y/x for x, y in zip(a, b)]
        print(f"| {label(k)} | {name} | {fmt % med(a)} | {fmt % med(b)} | "
              f"{med(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f}) |")

# Thread scaling of v2: runs with 1 and 2 threads of the same case, in turn
print()
print("| case | 1 thread ns per particle-step | 2 threads | speed-up, paired: median (min-max) |")
print("|---|---|---|---|")
base = {}
for r in rows:
    if r["engine"] != "v2":
        continue
    k = (r["case"], r["integrator"], r["N"], r["attractionCutoff"])
    base.setdefault(k, {}).setdefault(r["threads"], []).append(float(r["ns_per_particle_step"]))
for k, t in base.items():
    if "1" in t and "2" in t and len(t["1"]) == len(t["2"]):
        s = [a/b for a, b in zip(t["1"], t["2"])]
        print(f"| {k[0]}, N = {k[2]}, attraction cut-off {k[3]} a0 | {med(t['1']):.0f} | "
              f"{med(t['2']):.0f} | {med(s):.2f} ({min(s):.2f}-{max(s):.2f}) |")
