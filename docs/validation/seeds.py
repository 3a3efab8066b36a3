#!/usr/bin/python3
"""The runs of docs/validation/seeds.sh: each seed's steady eta_r and stated
standard error (its latest rheologySummary.dat), the standard deviation of
the seeds' means, the root mean square of their stated errors, and the ratio
of the two (1 if the error bars are right; the ratio's own uncertainty is
about 1/sqrt(2 (n - 1)) for n seeds).

    seeds.py RUNROOT   ->  docs/validation/seeds.csv, seeds.md
"""
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from rheologydata import readSummary, writeRowsAndTable  # noqa: E402


def main(runRoot):
    groups = {}
    for case in sorted(glob.glob(os.path.join(runRoot, "delta*-phi*-seed*"))):
        m = re.search(r"(delta[0-9.]+-phi[0-9.]+)-seed(\d+)$", case)
        s = readSummary(case)
        if m and s:
            groups.setdefault(m.group(1), []).append((int(m.group(2)), s))
    if not groups:
        sys.exit("seeds.py: no summaries under " + runRoot)
    csvRows, md = [], []
    md.append("Table written by `docs/validation/seeds.py` (seeds.csv) from the runs of "
              "`docs/validation/seeds.sh`:\n")
    md.append("| point | seeds | mean of ηr | sd of the seeds' ηr | rms stated error | ratio | ± |")
    md.append("|---|---:|---:|---:|---:|---:|---:|")
    for point, seeds in sorted(groups.items()):
        means = [s["mean"] for _, s in seeds]
        n = len(means)
        mu = sum(means)/n
        sd = math.sqrt(sum((x - mu)**2 for x in means)/(n - 1)) if n > 1 else float("nan")
        rms = math.sqrt(sum(s["se"]**2 for _, s in seeds)/n)
        ratio = sd/rms
        for seed, s in seeds:
            csvRows.append([point, seed, s["mean"], s["se"], s["corr"], s["used"],
                            s["discarded"], s["trusted"]])
        md.append("| %s | %d | %.4g | %.3g | %.3g | %.2f | %.2f |" % (
            point, n, mu, sd, rms, ratio, ratio/math.sqrt(2*(n - 1)) if n > 1 else float("nan")))
    writeRowsAndTable(os.path.join(here, "seeds"),
                      "point,seed,etaR,stdError,correlationStrain,strainUsed,strainDiscarded,trusted",
                      csvRows, md)
    for r in csvRows:
        print(*r)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else
         os.path.join(os.path.dirname(os.path.dirname(here)), "run", "validation", "seeds"))
