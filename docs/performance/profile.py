#!/usr/bin/python3
"""Medians over repeats of docs/performance/profile.csv (profile.sh) as a
Markdown table: per integrator and set of models switched off, the pair
range, pairs per particle, ns per particle-step in total and per kernel."""
import csv
import os
import statistics
from collections import defaultdict

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, "profile.csv"))))
groups = defaultdict(list)
for r in rows:
    groups[(r["integrator"], r["attractionCutoff"], r["off"])].append(r)

kernels = ["flow_ns", "pairs_ns", "particle_ns", "search_ns", "hydrodynamics_ns", "integration_ns"]
print("| integrator | attraction cut-off | off | pair range gap | pairs/particle | ns/particle-step | "
      + " | ".join(k.replace("_ns", "") for k in kernels) + " |")
print("|---|---:|---|---:|---:|---:|" + "---:|"*len(kernels))
for (integrator, cutoff, off), rs in groups.items():
    med = lambda c: statistics.median(float(r[c]) for r in rs)
    print(f"| {integrator} | {cutoff} | {off} | {med('gap'):g} | {med('pairs_per_particle'):.2f} | "
          f"{med('ns_per_particle_step'):.0f} | " + " | ".join(f"{med(k):.0f}" for k in kernels) + " |")
