#!/usr/bin/python3
"""Table 1 FL from the solver's own summaries, against the table of
analyse.py (docs/validation/frictionless.csv, the block averages of earlier
runs): for each point of `docs/validation/run.sh frictionless`, eta_r and
its standard error from the latest rheologySummary.dat of each seed (seeds
averaged, their errors combined), the analyse.py value of the same point, and
the difference in units of the two error bars combined (the runs are
independent: other solver version, other trajectories).

    docs/validation/summaries.py [runRoot]  ->  docs/validation/summaries.csv, .md
"""
import csv
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
from rheologydata import readSummary  # noqa: E402


def main(runRoot):
    points = {}
    for case in sorted(glob.glob(os.path.join(runRoot, "frictionless", "delta*-phi*-seed*"))):
        m = re.search(r"delta([0-9.]+)-phi([0-9.]+)-seed(\d+)$", case)
        s = readSummary(case)
        if m and s:
            points.setdefault((float(m.group(1)), float(m.group(2))), []).append(s)
    old = {}
    with open(os.path.join(here, "frictionless.csv")) as f:
        for r in csv.DictReader(f):
            delta = float(r["setting"].split("=")[1])
            old[(delta, float(r["x"]))] = (float(r["value"]), float(r["error"]))
    rows = []
    for (delta, phi), seeds in sorted(points.items()):
        mean = sum(s["mean"] for s in seeds)/len(seeds)
        se = math.sqrt(sum(s["se"]**2 for s in seeds))/len(seeds)
        v, e = old.get((delta, phi), (float("nan"), float("nan")))
        rows.append(dict(
            delta=delta, phi=phi, seeds=len(seeds), etaR=mean, se=se,
            corr=max(s["corr"] for s in seeds),
            discarded=max(s["discarded"] for s in seeds),
            trusted="yes" if all(s["trusted"] == "yes" for s in seeds) else "no",
            analyse=v, analyse_error=e,
            sigmas=(mean - v)/math.hypot(se, e)))
    if not rows:
        sys.exit("summaries.py: no summaries under " + runRoot)
    cols = list(rows[0])
    with open(os.path.join(here, "summaries.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(str(r[c]) for c in cols) + "\n")
    with open(os.path.join(here, "summaries.md"), "w") as f:
        f.write("Table written by `docs/validation/summaries.py` (summaries.csv) from the runs of "
                "`docs/validation/run.sh frictionless`:\n\n")
        f.write("| δ_lub | φ | seeds | ηr (summary) | ± | correlation strain | discarded | trusted "
                "| ηr (analyse.py) | ± | difference / σ |\n")
        f.write("|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n")
        for r in rows:
            f.write("| %g | %g | %d | %.4g | %.2g | %.2g | %.3g | %s | %.4g | %.2g | %+.1f |\n" % (
                r["delta"], r["phi"], r["seeds"], r["etaR"], r["se"], r["corr"],
                r["discarded"], r["trusted"], r["analyse"], r["analyse_error"], r["sigmas"]))
    print(open(os.path.join(here, "summaries.md")).read())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "run", "validation", "full"))
