"""Reading wavyShearFoam case output for the analysis scripts of docs/:
the rheology time series joined over restarts, run times, block averages."""
import csv
import glob
import math
import os
import re

import numpy as np


def readRheology(case):
    """Columns of every postProcessing/rheology/<start>/rheology.dat of a case
    (one per restart) joined, sorted and unique in strain; only the columns
    that every file has (a restart by a newer solver may add columns); None
    if empty"""
    rows = {}
    common = None
    # A run restarted at the same start time writes rheology_<start>.dat
    # next to the file of the stopped run: read both, the later last
    files = glob.glob(os.path.join(case, "postProcessing", "rheology", "*", "rheology*.dat"))
    for f in sorted(files, key=lambda f: (os.path.dirname(f), len(f), f)):
        header = None
        with open(f) as fh:
            for line in fh:
                if line.startswith("# Time"):
                    header = line[1:].split()
                    common = set(header) if common is None else common & set(header)
                elif not line.startswith("#") and line.strip() and header:
                    row = dict(zip(header, (float(x) for x in line.split())))
                    rows[row["strain"]] = row
    if not rows:
        return None
    ordered = [rows[k] for k in sorted(rows)]
    return {name: np.array([r[name] for r in ordered]) for name in common}


def readSummaries(case):
    """Every quantity's row of the latest rheologySummary.dat of a case (the
    function object suspensionRheology's steady-state summary), as
    {quantity: {mean, se, corr, blocks, used, discarded, trusted, time}};
    None without one"""
    files = glob.glob(os.path.join(case, "postProcessing", "rheology", "*", "rheologySummary.dat"))
    if not files:
        return None
    path = max(files, key=lambda f: float(os.path.basename(os.path.dirname(f))))
    out, time = {}, float("nan")
    with open(path) as f:
        for line in f:
            m = re.match(r"# Steady-state rheology at time (\S+)", line)
            if m:
                time = float(m.group(1))
            w = line.split()
            if len(w) == 10 and not line.startswith("#"):
                out[w[0]] = dict(mean=float(w[1]), se=float(w[2]), corr=float(w[4]),
                                 block=float(w[5]), blocks=int(w[6]), used=float(w[7]),
                                 discarded=float(w[8]), trusted=w[9], time=time)
    return out or None


def readSummary(case, quantity="etaR"):
    """One quantity's row of readSummaries(case); None without one"""
    return (readSummaries(case) or {}).get(quantity)


def combineSeeds(rows):
    """Mean and error of one quantity over independent runs (rows of
    readSummaries): the mean weighted by 1/se^2, its error sqrt(1/sum w)
    scaled up by sqrt(chi^2/(n - 1)) when the runs scatter more than their
    error bars say (the Particle Data Group's scale factor; near jamming one
    run's error bar is a lower bound, docs/validation.md); a run with se = 0
    (a constant, e.g. the Stokes part) gives the plain mean and error 0, a
    run without an error bar (se nan) the plain mean and error nan"""
    means = [r["mean"] for r in rows]
    if any(math.isnan(r["se"]) for r in rows):
        return sum(means)/len(means), float("nan")
    if any(r["se"] <= 0 for r in rows):
        return sum(means)/len(means), 0.0
    w = [1/r["se"]**2 for r in rows]
    mean = sum(wi*x for wi, x in zip(w, means))/sum(w)
    error = math.sqrt(1/sum(w))
    if len(rows) > 1:
        chi2 = sum(wi*(x - mean)**2 for wi, x in zip(w, means))
        error *= max(1.0, math.sqrt(chi2/(len(rows) - 1)))
    return mean, error


def wallSeconds(case):
    """Wall time of all runs of a case (written by etc/caseFunctions)"""
    try:
        return float(open(os.path.join(case, "wallSeconds")).read())
    except OSError:
        return float("nan")


def cpuSeconds(case):
    """Sum over the solver logs of a case of the last ExecutionTime (CPU s)"""
    total = 0.0
    for log in glob.glob(os.path.join(case, "log.wavyShearFoam.*")):
        last = None
        with open(log) as fh:
            for line in fh:
                m = re.match(r"ExecutionTime = ([0-9.eE+-]+) s", line)
                if m:
                    last = float(m.group(1))
        total += last or 0.0
    return total


def blockMeans(strain, values, start, blocks):
    """Means of `blocks` blocks of equal strain after `start`, and the block
    length in strain"""
    edges = np.linspace(start, strain[-1], blocks + 1)
    means = []
    for a, b in zip(edges[:-1], edges[1:]):
        sel = (strain > a) & (strain <= b)
        if sel.any():
            means.append(values[sel].mean())
    return np.array(means), (strain[-1] - start)/blocks


def meanAndError(blocks):
    """Mean of block means and its standard error"""
    blocks = np.asarray(blocks)
    if len(blocks) < 2:
        return (float(blocks.mean()) if len(blocks) else float("nan")), float("nan")
    return float(blocks.mean()), float(blocks.std(ddof=1)/math.sqrt(len(blocks)))


def writeCsv(path, rows, columns):
    """rows (dicts) as CSV with a header row; floats to 6 significant digits"""
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=columns)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r[k], float) else r[k]) for k in columns})
    return path


def writeRowsAndTable(stem, header, rows, md):
    """rows (lists) as stem.csv under `header` (comma-separated names), the
    Markdown lines md as stem.md, and md printed"""
    with open(stem + ".csv", "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")
    with open(stem + ".md", "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


def fillTables(path, sections):
    """Replace what stands between <!-- table:NAME --> and <!-- /table:NAME -->
    (or after a lone opening marker) by the table of NAME"""
    doc = open(path).read()
    for name, table in sections.items():
        opening, closing = f"<!-- table:{name} -->", f"<!-- /table:{name} -->"
        if opening not in doc:
            continue
        start = doc.index(opening) + len(opening)
        end = doc.index(closing) if closing in doc else start
        doc = doc[:start] + "\n" + table + "\n" + closing + doc[end + (len(closing) if closing in doc else 0):]
    open(path, "w").write(doc)
