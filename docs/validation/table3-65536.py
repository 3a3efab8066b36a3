#!/usr/bin/python3
"""The paper's fig. 10 from the runs of docs/validation/table3-65536.sh.

    docs/validation/table3-65536.py

For Table 3 NW and YW at N = 65536 (run/validation/table3-65536/<case>):
the eta_r histories of both; the particle and ambient streamwise velocity
and the local shear rate across y, averaged over the write times after the
discarded start-up; the steady eta_r with its error bar (the solver's own
rheologySummary.dat: MSER-5 start-up, blocks of two correlation strains);
the CPU seconds per strain for each number of threads the chunks ran
with (from the progress lines, which carry the process's CPU seconds: the
difference between the first and the last line of each chunk over its
strain, summed over the chunks of that thread count, so the set-up and
any strain redone after a stop are not counted twice); the peak resident
memory of the latest chunk (the largest its progress lines or end-of-run
line give, from getrusage as /usr/bin/time -v: the current code's, as
chunks may span versions).
Writes docs/validation/table3-65536.csv and .png and the table between
<!-- table:table3-65536 --> in docs/validation.md.
"""
import glob
import math
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
sys.path.insert(0, here)
from analyse import plotFig10, readProfiles  # noqa: E402
from rheologydata import (fillTables, readRheology, readSummaries,  # noqa: E402
                          wallSeconds, writeCsv)

runs = os.path.join(os.environ.get("WSF_VALIDATION_DIR", os.path.join(root, "run", "validation")),
                    "table3-65536")
CASES = ("NW", "YW")
COLUMNS = ["case", "strain", "etaR", "etaR_error", "discarded_strain", "correlation_strain",
           "trusted", "N1", "N1_error", "N2", "N2_error", "steps_per_strain",
           "cpu_s_per_strain_1_thread", "cpu_s_per_strain_2_threads", "wall_s", "peak_rss_MB"]


def chunks(case):
    """Per solver log: (strains, CPU seconds) of its progress lines, threads, peak RSS"""
    out = []
    for log in sorted(glob.glob(os.path.join(case, "log.wavyShearFoam.*")),
                      key=lambda f: int(f.rsplit(".", 1)[1])):
        strain, cpu, threads, rss, steps = [], [], float("nan"), float("nan"), float("nan")
        with open(log) as fh:
            for line in fh:
                m = re.match(r"strain (\S+) .* CPU (\S+) s(  peak RSS (\d+) MB)?", line)
                if m:
                    strain.append(float(m.group(1)))
                    cpu.append(float(m.group(2)))
                    if m.group(4):
                        rss = max(float(m.group(4)), 0 if math.isnan(rss) else rss)
                m = re.match(r"\s+threads\s+(\d+)", line)
                if m:
                    threads = int(m.group(1))
                m = re.match(r"\s+outer step\s+(\S+) = (\d+) steps of dt and one", line)
                if m:
                    steps = (int(m.group(2)) + 1)/float(m.group(1))
                m = re.match(r"Peak resident memory (\S+) MB", line)
                if m:
                    rss = max(float(m.group(1)), 0 if math.isnan(rss) else rss)
        out.append(dict(strain=np.array(strain), cpu=np.array(cpu), threads=threads,
                        rss=rss, steps=steps))
    return out


def analyse(name):
    case = os.path.join(runs, name)
    parts = chunks(case)
    if not parts:
        return None
    s = readSummaries(case) or {}
    e = s.get("etaR", {})
    def cpuPerStrain(threads):
        done = [p for p in parts if len(p["strain"]) > 1 and p["threads"] == threads]
        dS = sum(p["strain"][-1] - p["strain"][0] for p in done)
        dC = sum(p["cpu"][-1] - p["cpu"][0] for p in done)
        return dC/dS if dS > 0 else float("nan")

    history = readRheology(case)
    row = {"case": name,
           "strain": float(history["strain"][-1]) if history is not None else float("nan"),
           "etaR": e.get("mean", float("nan")), "etaR_error": e.get("se", float("nan")),
           "discarded_strain": e.get("discarded", float("nan")),
           "correlation_strain": e.get("corr", float("nan")),
           "trusted": e.get("trusted", "no"),
           "steps_per_strain": parts[-1]["steps"],
           "cpu_s_per_strain_1_thread": cpuPerStrain(1),
           "cpu_s_per_strain_2_threads": cpuPerStrain(2),
           "wall_s": wallSeconds(case),
           "peak_rss_MB": parts[-1]["rss"]}
    for q in ("N1", "N2"):
        row[q] = s.get(q, {}).get("mean", float("nan"))
        row[q + "_error"] = s.get(q, {}).get("se", float("nan"))
    start = e.get("discarded", 0.0)
    if math.isnan(start):
        start = 0.0
    return row, history, readProfiles(case, start)


def markdown(rows):
    head = ("| case | strain run | eta_r | ± | discarded | correlation strain | trusted | N1 | N2 "
            "| steps per strain | CPU s per strain, 1 thread | CPU s per strain, 2 threads "
            "| peak RSS MB (last chunk) |\n"
            "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|\n")
    fmt = ("| {case} | {strain:.2f} | {etaR:.3g} | {etaR_error:.2g} | {discarded_strain:.2f} "
           "| {correlation_strain:.2g} | {trusted} | {N1:.3g} | {N2:.3g} | {steps_per_strain:.0f} "
           "| {cpu_s_per_strain_1_thread} | {cpu_s_per_strain_2_threads} "
           "| {peak_rss_MB:.0f} |\n")

    def cells(r):
        cpu = ("cpu_s_per_strain_1_thread", "cpu_s_per_strain_2_threads")
        return {k: ("–" if math.isnan(v) else f"{v:.0f}") if k in cpu else v
                for k, v in r.items()}
    return head + "".join(fmt.format(**cells(r)) for r in rows)


def main():
    results = {c: analyse(c) for c in CASES}
    results = {c: r for c, r in results.items() if r is not None}
    if not results:
        print(f"no runs under {runs} (docs/validation/table3-65536.sh)")
        return
    plotFig10({c: r[1] for c, r in results.items()}, {c: r[2] for c, r in results.items()},
              "Table 3, N = 65536: same initial condition",
              os.path.join(here, "table3-65536.png"))

    rows = [r[0] for r in results.values()]
    path = writeCsv(os.path.join(here, "table3-65536.csv"), rows, COLUMNS)
    table = (f"Table written by `docs/validation/table3-65536.py` from "
             f"`{os.path.relpath(path, root)}`:\n\n" + markdown(rows))
    print(table)
    fillTables(os.path.join(root, "docs", "validation.md"), {"table3-65536": table})


if __name__ == "__main__":
    main()
