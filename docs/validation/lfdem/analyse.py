#!/usr/bin/python3
"""Tabulate the runs of docs/validation/lfdem/run.sh.

    docs/validation/lfdem/analyse.py [OUTDIR] [--end E] [--discard S] [--blocks B]

OUTDIR: run.sh's (default run/validation/lfdem); a run that has not reached
the strain E (default 30, run.sh's END) is left out and named. Both codes'
series are sampled every 0.01 strain and reduced the same way: the first
S strain units discarded (default 5), the rest cut into B blocks of equal
strain (default 8), the mean of the block means and its standard error
(rheologydata.blockMeans, meanAndError); a code's value at a phi is the
mean over its seeds (packings) weighted by their errors, its error scaled
up when the seeds scatter more than their error bars say
(rheologydata.combineSeeds). Quantities, in units of eta0:
  etaR        ours: etaR of rheology.dat; LF_DEM: its "viscosity"
  etaR_pairs  etaR without the one-body (Einstein, 5/2 phi) stresslet:
              ours etaR - etaR_stokes; LF_DEM has no one-body stresslet,
              so its etaR
  contact     ours etaR_contact; LF_DEM Viscosity(contact) +
              Viscosity(dashpot) (its dashpot is the lubrication of
              touching pairs, which ours keeps in etaR_lubrication)
  hydro       ours 1 + etaR_stokes + etaR_lubrication; LF_DEM
              Viscosity(hydro) (solvent included)
  N1, N2      the normal stress differences over gammaDot (LF_DEM's "N1
              viscosity", "N2 viscosity", its axes mapped to ours)
  Z           contacts per particle (ours 2 nContacts/N; LF_DEM "contact
              number")
Writes docs/validation/lfdem/runs.csv (a row per run), results.csv (a row
per code and phi), results.png and results.md (printed, and put into
docs/validation.md between its <!-- table:lfdem --> markers).
"""
import argparse
import glob
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(os.path.dirname(here)))
sys.path.insert(0, os.path.dirname(os.path.dirname(here)))
from rheologydata import (blockMeans, combineSeeds, fillTables,  # noqa: E402
                          meanAndError, readRheology, writeCsv)
sys.path.insert(0, os.path.join(root, "docs", "performance", "lfdem"))
from summarise import lfdem_data  # noqa: E402

CODES = {"ours": "wavyShearFoam (implicitEuler)",
         "oursStep4": "wavyShearFoam, a quarter of the step", "stock": "LF_DEM",
         "ourSprings": "LF_DEM, our springs (kn h)",
         "ourCutoff": "LF_DEM, our cut-off (h < 0.5 a0)"}
SHORT = {"ours": "ours", "oursStep4": "ours,\nstep/4", "stock": "LF_DEM",
         "ourSprings": "LF_DEM,\nour springs", "ourCutoff": "LF_DEM,\nour cut-off"}
QUANTITIES = ["etaR", "etaR_pairs", "contact", "hydro", "N1", "N2", "Z"]


def lfdemSeries(run):
    """LF_DEM's data_*.dat of a run as the quantities of QUANTITIES"""
    if len(glob.glob(os.path.join(run, "data_*.dat"))) != 1:
        return None
    names, rows = lfdem_data(run)
    if not rows:
        return None
    a = np.array([r for r in rows if len(r) == len(rows[0])])   # a running LF_DEM's last row may be partial
    c = {k: a[:, i] for k, i in names.items()}
    return {"strain": c["cumulated shear strain"], "etaR": c["viscosity"],
            "etaR_pairs": c["viscosity"],
            "contact": c["Viscosity(contact)"] + c["Viscosity(dashpot)"],
            "hydro": c["Viscosity(hydro)"], "N1": c["N1 viscosity"], "N2": c["N2 viscosity"],
            "Z": c["contact number"]}


def oursSeries(run, n):
    r = readRheology(run)
    if r is None:
        return None
    return {"strain": r["strain"], "etaR": r["etaR"], "etaR_pairs": r["etaR"] - r["etaR_stokes"],
            "contact": r["etaR_contact"], "hydro": 1 + r["etaR_stokes"] + r["etaR_lubrication"],
            "N1": r["N1"], "N2": r["N2"], "Z": 2*r["nContacts"]/n}


def plot(points, path):
    """eta_r with and without the one-body stresslet, each code a marker,
    each phi a panel"""
    phis = sorted({p["phi"] for p in points})
    fig, axes = plt.subplots(1, len(phis), figsize=(4.5*len(phis), 3.6), squeeze=False)
    for ax, phi in zip(axes[0], phis):
        pts = [p for p in points if p["phi"] == phi]
        for k, p in enumerate(pts):
            ax.errorbar([k], [p["etaR_pairs"]], yerr=[p["etaR_pairs_se"]], fmt="o", color="C0",
                        label="without 5/2 phi" if k == 0 else None)
            if p["code"].startswith("ours"):
                ax.errorbar([k], [p["etaR"]], yerr=[p["etaR_se"]], fmt="s", mfc="none", color="C1",
                            label="ours, with 5/2 phi" if k == 0 else None)
        ax.set_xticks(range(len(pts)))
        ax.set_xticklabels([SHORT[p["code"]] for p in pts], fontsize=8)
        ax.set_title(f"phi = {phi}, N = 200, frictionless")
        ax.set_ylabel("eta_r")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default=os.path.join(root, "run", "validation", "lfdem"))
    ap.add_argument("--end", type=float, default=30)
    ap.add_argument("--discard", type=float, default=5)
    ap.add_argument("--blocks", type=int, default=8)
    a = ap.parse_args()
    rows = []
    for run in sorted(glob.glob(os.path.join(a.outdir, "*-*-s*"))):
        m = re.fullmatch(r"(\w+)-([0-9.]+)-s([0-9]+)", os.path.basename(run))
        if not (m and m.group(1) in CODES and os.path.isdir(run)):
            continue
        code, phi, seed = m.group(1), m.group(2), "s" + m.group(3)
        s = oursSeries(run, 200) if code.startswith("ours") else lfdemSeries(run)
        if s is None or s["strain"][-1] < a.end - 1e-6:
            print(f"{run}: not at strain {a.end:g}, left out", file=sys.stderr)
            continue
        keep = s["strain"] <= a.end + 1e-6                 # a longer run: its first E strain units
        s = {k: v[keep] for k, v in s.items()}
        row = {"code": code, "phi": phi, "seed": seed[1:], "strain_end": float(round(s["strain"][-1], 6))}
        for q in QUANTITIES:
            blocks, length = blockMeans(s["strain"], s[q], a.discard, a.blocks)
            row[q], row[q + "_se"] = meanAndError(blocks)
        row["block_strain"] = float(length)
        rows.append(row)
    values = [x for q in QUANTITIES for x in (q, q + "_se")]
    writeCsv(os.path.join(here, "runs.csv"), rows,
             ["code", "phi", "seed", "strain_end", "block_strain"] + values)
    order = list(CODES)
    points = []
    for key in sorted({(r["phi"], r["code"]) for r in rows}, key=lambda k: (k[0], order.index(k[1]))):
        runs = [r for r in rows if (r["phi"], r["code"]) == key]
        point = {"phi": key[0], "code": key[1], "seeds": len(runs),
                 "strain_end": min(r["strain_end"] for r in runs)}
        for q in QUANTITIES:
            point[q], point[q + "_se"] = combineSeeds([{"mean": r[q], "se": r[q + "_se"]} for r in runs])
        points.append(point)
    writeCsv(os.path.join(here, "results.csv"), points, ["phi", "code", "seeds", "strain_end"] + values)
    md = [f"Steady state from strain {a.discard:g}, {a.blocks} blocks per run; mean ± standard error "
          "over the seeds, units of eta0 (N1, N2 over gammaDot).", "",
          "| phi | code | seeds | strain | etaR | etaR without 5/2 phi | contact | hydrodynamic | N1 | N2 | Z |",
          "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for p in points:
        cells = [f"{p[q]:.2f} ± {p[q + '_se']:.2f}" for q in QUANTITIES]
        md.append(f"| {p['phi']} | {CODES[p['code']]} | {p['seeds']} | {p['strain_end']:g} | "
                  + " | ".join(cells) + " |")
    plot(points, os.path.join(here, "results.png"))
    with open(os.path.join(here, "results.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    fillTables(os.path.join(root, "docs", "validation.md"),
               {"lfdem": "Table written by `docs/validation/lfdem/analyse.py` (results.csv):\n\n" + "\n".join(md)})
    print("\n".join(md))


if __name__ == "__main__":
    main()
