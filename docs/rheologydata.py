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
    for f in glob.glob(os.path.join(case, "postProcessing", "rheology", "*", "rheology.dat")):
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
