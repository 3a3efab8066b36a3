#!/usr/bin/python3
"""The paper's fig. 10 from the runs of docs/validation/table3-65536.sh.

    docs/validation/table3-65536.py

For Table 3 NW and YW at N = 65536 ($WSF_VALIDATION_DIR/table3-65536/<case>,
by default run/validation/ in the checkout):
the eta_r histories of both; the particle and ambient streamwise velocity
and the local shear rate across y, averaged over the write times after the
discarded start-up; the steady eta_r with its error bar (the solver's own
rheologySummary.dat: MSER-5 start-up, blocks of two correlation strains);
the CPU seconds per strain for each number of threads the chunks ran
with (from the progress lines, which carry the process's CPU seconds: the
difference between the first and the last line of each chunk over its
strain, summed over the chunks of that thread count, so the set-up and
any strain redone after a stop are not counted twice); the peak resident
memory of the latest chunk that printed one (the largest its progress
lines or end-of-run line give, from getrusage as /usr/bin/time -v: the current code's, as
chunks may span versions).
Writes docs/validation/table3-65536.csv and .png, the table between
<!-- table:table3-65536 --> in docs/validation.md, and
table3-65536-migration.png: the solid fraction across y at a few strains
and, against strain, its mean over the bins where the wavy flow shears at
under 0.6 and over 1.5 times the mean rate (the same bins for both cases:
in NW they show whether the regions differ at all).

A run directory holds the restart state (21-25 MB a write) and lives only
as long as its machine, so what this script reads of it, a few hundred kB,
is first copied to docs/validation/table3-65536/<case>/ in the same layout
(postProcessing/rheology and profiles, wallSeconds, and of each solver log
its set-up lines, progress lines, peak memory and any error), replacing the
copy of before, and the analysis reads that copy: the
table and figure can be made again, and checked, from the repository alone.
A case with neither a run nor a copy keeps its row of the existing CSV
(the column `data` says where each row comes from).
"""
import csv
import glob
import math
import os
import re
import shutil
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
sys.path.insert(0, here)
from analyse import plt, plotFig10, profileSeries, readProfiles  # noqa: E402
from rheologydata import (fillTables, readRheology, readSummaries,  # noqa: E402
                          wallSeconds, writeCsv)

runs = os.path.join(os.environ.get("WSF_VALIDATION_DIR", os.path.join(root, "run", "validation")),
                    "table3-65536")
kept = os.path.join(here, "table3-65536")
CASES = ("NW", "YW")
COLUMNS = ["case", "data", "strain", "etaR", "etaR_error", "discarded_strain", "correlation_strain",
           "trusted", "N1", "N1_error", "N2", "N2_error", "steps_per_strain",
           "cpu_s_per_strain_1_thread", "cpu_s_per_strain_2_threads", "wall_s", "peak_rss_MB"]


def keep(name):
    """Mirror what the analysis reads of run <name> (when it is on this
    machine) in kept/<name>, replaced whole, so that the copy never mixes
    two runs (a run from restart.tar.xz holds all earlier output); return
    kept/<name>, or None if neither exists"""
    run, copy = os.path.join(runs, name), os.path.join(kept, name)
    if os.path.isdir(run):
        part = copy + ".part"
        shutil.rmtree(part, ignore_errors=True)
        os.makedirs(part)
        for sub in ("rheology", "profiles"):
            for f in glob.glob(os.path.join(run, "postProcessing", sub, "*", "*.dat")):
                target = os.path.join(part, os.path.relpath(f, run))
                os.makedirs(os.path.dirname(target), exist_ok=True)
                shutil.copyfile(f, target)
        if os.path.isfile(os.path.join(run, "wallSeconds")):
            shutil.copyfile(os.path.join(run, "wallSeconds"), os.path.join(part, "wallSeconds"))
        for log in glob.glob(os.path.join(run, "log.wavyShearFoam.*")):
            with open(log) as src, open(os.path.join(part, os.path.basename(log)), "w") as dst:
                setUp = True
                for line in src:
                    setUp = setUp and not line.startswith("Starting time loop")
                    if setUp or re.match(r"strain \S+ |Peak resident memory|.*(FATAL|[Ee]rror)", line):
                        dst.write(line)
        restart = os.path.join(copy, "restart.tar.xz")
        if os.path.isfile(restart):
            os.replace(restart, os.path.join(part, "restart.tar.xz"))
        shutil.rmtree(copy, ignore_errors=True)
        os.replace(part, copy)
    return copy if os.path.isdir(copy) else None


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
    case = keep(name)
    parts = chunks(case) if case else []
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
    row = {"case": name, "data": os.path.relpath(case, root),
           "strain": float(history["strain"][-1]) if history is not None else float("nan"),
           "etaR": e.get("mean", float("nan")), "etaR_error": e.get("se", float("nan")),
           "discarded_strain": e.get("discarded", float("nan")),
           "correlation_strain": e.get("corr", float("nan")),
           "trusted": e.get("trusted", "no"),
           "steps_per_strain": parts[-1]["steps"],
           "cpu_s_per_strain_1_thread": cpuPerStrain(1),
           "cpu_s_per_strain_2_threads": cpuPerStrain(2),
           "wall_s": wallSeconds(case),
           "peak_rss_MB": next((p["rss"] for p in reversed(parts) if not math.isnan(p["rss"])),
                               float("nan"))}
    for q in ("N1", "N2"):
        row[q] = s.get(q, {}).get("mean", float("nan"))
        row[q + "_error"] = s.get(q, {}).get("se", float("nan"))
    start = e.get("discarded", 0.0)
    if math.isnan(start):
        start = 0.0
    return row, history, readProfiles(case, start)


def plotMigration(series, path):
    """Shear-induced migration: phi(y) about strains 0, 1, 2, ... and the mean
    phi of the low- and high-shear bins of the wavy flow against strain"""
    wavy = next((s for s in series.values() if s and np.ptp(next(iter(s.values()))[:, 5]) > 0.1),
                None)
    if wavy is None:
        return
    # The bins of the latest write; the set-up's profile at strain 0 has
    # the default bins (makeSuspension writes it before the set-up sets
    # nBins) and is left out with any other of a different binning
    y, rate = list(wavy.values())[-1][:, 0], list(wavy.values())[-1][:, 5]
    low, high = rate < 0.6, rate > 1.5
    series = {c: {t: p for t, p in s.items() if p.shape[0] == len(y) and np.allclose(p[:, 0], y)}
              for c, s in series.items()}
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for (label, s), colour in zip(series.items(), ("C0", "C3")):
        if not s:
            continue
        times = np.array(list(s))
        # phi(y) averaged over the writes within 0.25 strain of 0, 1, 2, ...
        shown = [k for k in range(int(times[-1] + 0.25) + 1)]
        for n, k in enumerate(shown):
            near = [t for t in times if abs(t - k) <= 0.25]
            if not near:
                continue
            phi = np.mean([s[t][:, 2] for t in near], axis=0)
            axes[0].plot(phi, s[near[0]][:, 0], color=colour, alpha=0.3 + 0.7*(n + 1)/len(shown),
                         lw=1, label=f"{label}, strain {min(near):g}–{max(near):g}")
        for mask, style, where in ((low, "-", r"< 0.6 $\dot\gamma$"),
                                   (high, "--", r"> 1.5 $\dot\gamma$")):
            axes[1].plot(times, [s[t][mask, 2].mean() for t in times], style, color=colour,
                         marker="o" if len(times) == 1 else None,
                         label=f"{label}: bins where YW's d$U_\\infty$/dy {where}")
    axes[0].set_xlabel(rf"solid fraction $\phi$ (bins of {y[1] - y[0]:.3g} $a_0$)")
    axes[0].set_ylabel(r"$y/a_0$")
    axes[0].legend(fontsize=6)
    axes[1].set_xlabel(r"strain $\dot\gamma t$")
    axes[1].set_ylabel(r"mean $\phi$ of the bins")
    axes[1].legend(fontsize=6)
    axes[0].set_title("shear-induced migration")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def markdown(rows):
    head = ("| case | data | strain run | eta_r | ± | discarded | correlation strain | trusted | N1 | N2 "
            "| steps per strain | CPU s per strain, 1 thread | CPU s per strain, 2 threads "
            "| peak RSS MB (last chunk) |\n"
            "|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|\n")
    fmt = ("| {case} | {data} | {strain:.2f} | {etaR:.3g} | {etaR_error:.2g} | {discarded_strain:.2f} "
           "| {correlation_strain:.2g} | {trusted} | {N1:.3g} | {N2:.3g} | {steps_per_strain:.0f} "
           "| {cpu_s_per_strain_1_thread} | {cpu_s_per_strain_2_threads} "
           "| {peak_rss_MB:.0f} |\n")

    def cells(r):
        cpu = ("cpu_s_per_strain_1_thread", "cpu_s_per_strain_2_threads")
        return {k: ("–" if math.isnan(v) else f"{v:.0f}") if k in cpu else v
                for k, v in r.items()}
    return head + "".join(fmt.format(**cells(r)) for r in rows)


def earlierRows(path):
    """The rows of the existing CSV, as lists by case (strings as written)"""
    out = {}
    try:
        with open(path) as fh:
            for r in csv.DictReader(fh):
                out.setdefault(r["case"], []).append(r)
    except OSError:
        pass
    return out


def main():
    results = {c: analyse(c) for c in CASES}
    results = {c: r for c, r in results.items() if r is not None}
    if not results:
        print(f"no runs under {runs} nor in {kept} (docs/validation/table3-65536.sh)")
        return
    plotFig10({c: r[1] for c, r in results.items()}, {c: r[2] for c, r in results.items()},
              "Table 3, N = 65536: same initial condition",
              os.path.join(here, "table3-65536.png"))

    plotMigration({c: profileSeries(os.path.join(kept, c)) for c in results},
                  os.path.join(here, "table3-65536-migration.png"))

    csvPath = os.path.join(here, "table3-65536.csv")
    earlier = earlierRows(csvPath)
    rows = []
    for c in CASES:
        if c in results:
            rows.append(results[c][0])
        # A row of an earlier run (one whose copy has since been replaced
        # by a rerun's, or lost) stays while it has run further than the
        # run here: a rerun from strain 0 supersedes it only then
        for e in earlier.get(c, []):
            if c in results and float(e["strain"] or "inf") <= results[c][0]["strain"]:
                continue
            r = {k: e.get(k) or "" for k in COLUMNS}
            r["data"] = "an earlier run, this row only"
            rows.append({k: (v if k in ("case", "data", "trusted") else float(v or "nan"))
                         for k, v in r.items()})
    path = writeCsv(csvPath, rows, COLUMNS)
    table = (f"Table written by `docs/validation/table3-65536.py` from "
             f"`{os.path.relpath(path, root)}`:\n\n" + markdown(rows))
    print(table)
    fillTables(os.path.join(root, "docs", "validation.md"), {"table3-65536": table})


if __name__ == "__main__":
    main()
