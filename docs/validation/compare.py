#!/usr/bin/python3
"""The validation tables as analyse.py now writes them (from the solver's
own summaries, docs/validation/<case>.csv) against the same tables at an
earlier commit (default 342d90c, the last made by analyse.py's own block
averages of 8 blocks per run over a fixed start-up cut): for each point both
values, both error bars and the difference in units of the two combined
(the runs are independent where they were rerun), and per case chi^2 over
the points present in both.

    docs/validation/compare.py [commit]  ->  docs/validation/compare.csv, .md
                                             and docs/validation.md
"""
import csv
import io
import math
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
from rheologydata import fillTables, writeRowsAndTable  # noqa: E402

CASES = ("frictionless", "frictional", "shearThickening", "wavy", "dilute")


def table(text):
    """{(setting, x): (value, error)}; None for a table not made from the
    summaries (no column 'trusted')"""
    if "trusted" not in text.splitlines()[0].split(","):
        return None
    return {(r["setting"], float(r["x"])): (float(r["value"]), float(r["error"]))
            for r in csv.DictReader(io.StringIO(text))}


def main(commit):
    rows, md = [], []
    md.append("Table written by `docs/validation/compare.py %s` (compare.csv): the "
              "tables of `docs/validation/analyse.py` from the solver's summaries "
              "against those of commit %s (block averages of analyse.py).\n" % (commit, commit))
    md.append("| case | point | ηr now | ± | ηr at %s | ± | difference / σ |" % commit)
    md.append("|---|---|---:|---:|---:|---:|---:|")
    totals = []
    for case in CASES:
        path = os.path.join(here, case + ".csv")
        if not os.path.exists(path):
            continue
        old = subprocess.run(["git", "-C", root, "show", "%s:docs/validation/%s.csv" % (commit, case)],
                             capture_output=True, text=True)
        if old.returncode != 0:
            continue
        before, now = table(old.stdout.replace("etaN", "trusted")), table(open(path).read())
        if now is None:
            continue
        chi2, n, noError = 0.0, 0, 0
        for key in sorted(now):
            if key not in before:
                continue
            (v, e), (v0, e0) = now[key], before[key]
            sigma = (v - v0)/math.hypot(e, e0)
            if math.isnan(sigma):
                noError += 1    # a mean without an error bar (too short)
            else:
                chi2 += sigma**2
                n += 1
            rows.append([case, key[0], key[1], v, e, v0, e0, sigma])
            md.append(("| %s | %s, %g | %.4g | %.2g | %.4g | %.2g | %+.1f |" % (
                case, key[0], key[1], v, e, v0, e0, sigma)).replace("| +nan |", "| – |"))
        if n or noError:
            totals.append("%s: χ² = %.1f for %d points%s" % (
                case, chi2, n, " (%d more without an error bar)" % noError if noError else ""))
    md.append("\n" + "; ".join(totals) + ".")
    writeRowsAndTable(os.path.join(here, "compare"),
                      "case,setting,x,etaR,error,etaR_before,error_before,sigmas", rows, md)
    fillTables(os.path.join(root, "docs", "validation.md"), {"compare": "\n".join(md)})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "342d90c")
