#!/usr/bin/python3
"""analyse.py WORK OUT [TAG]: the tables and plots of docs/coupling.md from
the cases of perturbation.sh (WORK/<case>), written to OUT (each name with
TAG before its extension: perturbation<TAG>.csv, ...):

  perturbation.csv  per case: phi, F, the steady mean amplitude A of u'
                    and its error, etaEff = F/(eta0 k^2 A), etaDirect =
                    1 + <sigmaPk>/(eta0 k <A>) (the particles' own stress
                    mode over the shear-rate mode they see), the run's own
                    bulk etaR (rheologySummary.dat), the RMS deviation of
                    the shear rate across y beyond the forced mode (what
                    the particle-stress noise drives), the steady mean of
                    phik/phi (migration) and its value at the start (the
                    packing's own), and per phi the
                    uniform-shear etaR (rheologySummary.dat) and both
                    extrapolated to zero amplitude (linear in A^2)
  migration.csv     the volume-fraction mode phik/phi against strain
  perturbation.png  etaEff and etaDirect against A^2 with the zero-amplitude
                    extrapolation and the uniform-shear etaR
  migration.png     phik/phi against strain
  momentum.csv      per case and row across y: the steady mean of the total
                    shear stress tauInstant = eta0 dU/dy + Sigma_p,xy (the
                    instantaneous particle stress) with its error (blocks of
                    PROFILE_BLOCK = 10 strain of the profiles written every
                    2), and the exact value <tauInstant> - (int f - mean)
                    (profile.dat); chi2 per row of the difference printed
  momentum.png      both across y

Steady state: strain >= CUT (20: two coupling strains of 10), error bars
from the means of blocks of BLOCK (10) strain units: standard deviation of
the block means over sqrt(blocks - 1). The bulk and uniform-shear etaR are
those of rheologySummary.dat (its MSER-5 start-up cut, blocks of two
correlation strains). A case named ..._F<F>off ran with feedback off (the
particles in the particle-free fluid's wave): its etaEff is that fluid's.
"""
import csv
import math
import os
import re
import sys

CUT = 20.0
BLOCK = 10.0
PROFILE_BLOCK = 10.0


def table(path):
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                w = line[1:].split()
                if w:
                    names = w
            elif line.strip():
                rows.append([float(x) for x in line.split()])
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


def joined(outDir, fileName):
    """fileName of every start time under outDir joined, a later start
    replacing the rows from its time on (a restarted run)"""
    starts = sorted((float(d), d) for d in os.listdir(outDir)
                    if os.path.isfile(os.path.join(outDir, d, fileName)))
    out = None
    for t0, d in starts:
        part = table(os.path.join(outDir, d, fileName))
        if out is None:
            out = part
        else:
            keep = sum(1 for t in out["Time"] if t < t0)
            out = {k: out[k][:keep] + part[k] for k in part}
    return out


def blocks(t, values):
    """Means of the blocks of BLOCK strain after CUT"""
    out = {}
    for ti, v in zip(t, values):
        if ti > CUT:
            out.setdefault(int((ti - CUT - 1e-9)//BLOCK), []).append(v)
    return [sum(b)/len(b) for k, b in sorted(out.items())
            if len(b) > 0.9*len(max(out.values(), key=len))]


def meanErr(b):
    m = sum(b)/len(b)
    if len(b) < 2:
        return m, float("nan")
    s = math.sqrt(sum((x - m)**2 for x in b)/(len(b) - 1))
    return m, s/math.sqrt(len(b))


def err(q):
    """The name of the error of quantity q: dEtaEff of etaEff"""
    return "d" + q[0].upper() + q[1:]


def summary(path):
    for line in open(path):
        w = line.split()
        if w and w[0] == "etaR" and len(w) == 10:
            return float(w[1]), float(w[2]), w[9] == "yes"
    raise ValueError("no etaR row in " + path)


def main(work, out, tag=""):
    def outPath(name):
        stem, ext = os.path.splitext(name)
        return os.path.join(out, stem + tag + ext)

    cases = sorted(d for d in os.listdir(work)
                   if re.match(r"phi[0-9.]+_(F[0-9.]+(off)?|uniform)$", d))
    rows, uniform, migration = [], {}, {}
    for c in cases:
        phi = float(re.match(r"phi([0-9.]+)_", c).group(1))
        post = os.path.join(work, c, "postProcessing")
        if c.endswith("uniform"):
            uniform[phi] = summary(os.path.join(post, "rheology", "0",
                                                "rheologySummary.dat"))
            continue
        a = joined(os.path.join(post, "coupling"), "amplitude.dat")
        t = a["Time"]
        Ly = float(re.search(r"Ly\s+([0-9.e+-]+);", open(os.path.join(
            work, c, "constant", "particleBox")).read()).group(1))
        k = 2*math.pi/Ly
        F = a["F"][-1]
        bA = blocks(t, a["A"])
        bS = blocks(t, a["sigmaPk"])
        A, dA = meanErr(bA)
        nan = float("nan")
        eta = F/(k*k*A) if F != 0 else nan
        direct = [1 + s/(k*x) for s, x in zip(bS, bA)]
        etaD, dEtaD = meanErr(direct) if F != 0 else (nan, nan)
        # the coupled run's own bulk etaR, and the shear rate's deviation
        # across y from gammaDot beyond the forced mode (RMS over the rows of
        # the profiles after CUT): what the stress noise drives
        sdirs = [d for d in os.listdir(os.path.join(post, "rheology"))
                 if os.path.isfile(os.path.join(post, "rheology", d,
                                                "rheologySummary.dat"))]
        bulk = summary(os.path.join(post, "rheology", max(sdirs, key=float),
                                    "rheologySummary.dat"))
        cdir = os.path.join(post, "coupling")
        dev = []
        for d in os.listdir(cdir):
            f = os.path.join(cdir, d, "profile.dat")
            if os.path.isfile(f) and float(d) > CUT:
                p = table(f)
                n = len(p["y"])
                ck = 2*sum(r*math.cos(k*y) for r, y in zip(p["shearRate"], p["y"]))/n
                dev += [r - 1 - ck*math.cos(k*y)
                        for r, y in zip(p["shearRate"], p["y"])]
        noise = math.sqrt(sum(x*x for x in dev)/len(dev)) if dev else float("nan")
        migr, dMigr = meanErr(blocks(t, [x/phi for x in a["phik"]]))
        rows.append({"case": c, "phi": phi, "F": F, "k": k, "A": A, "dA": dA,
                     "phikRel": migr, "dPhikRel": dMigr,
                     "phikRelStart": a["phik"][0]/phi,
                     "off": c.endswith("off"),
                     "etaRBulk": bulk[0], "dEtaRBulk": bulk[1],
                     "bulkTrusted": "yes" if bulk[2] else "no",
                     "rateNoise": noise,
                     "etaEff": eta, "dEtaEff": eta*dA/A,
                     "etaDirect": etaD, "dEtaDirect": dEtaD,
                     "blocks": len(bA), "strain": t[-1]})
        migration[c] = (t, [p/phi for p in a["phik"]])

    # zero-amplitude extrapolation, linear in A^2, per phi
    ext = {}
    for phi in sorted({r["phi"] for r in rows}):
        r = sorted((x for x in rows
                    if x["phi"] == phi and x["F"] != 0 and not x["off"]),
                   key=lambda x: x["A"])
        if len(r) < 2:
            continue
        lo, hi = r[0], r[-1]
        a2, b2 = lo["A"]**2, hi["A"]**2
        e = {}
        for q in ("etaEff", "etaDirect"):
            slope = (hi[q] - lo[q])/(b2 - a2)
            e[q] = lo[q] - slope*a2
            # errors of the two ends, independent
            w1, w2 = b2/(b2 - a2), a2/(b2 - a2)
            e[err(q)] = math.hypot(w1*lo[err(q)], w2*hi[err(q)])
        ext[phi] = e

    with open(outPath("perturbation.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "phi", "F", "k", "strain", "blocks", "A", "dA",
                    "etaEff", "dEtaEff", "etaDirect", "dEtaDirect",
                    "etaRBulk", "dEtaRBulk", "bulkTrusted", "rateNoise",
                    "phikRel", "dPhikRel", "phikRelStart",
                    "etaEff0", "dEtaEff0", "etaDirect0", "dEtaDirect0",
                    "etaRUniform", "dEtaRUniform", "uniformTrusted"])
        for r in rows:
            e = ext.get(r["phi"], {})
            u = uniform.get(r["phi"], (float("nan"),)*2 + (False,))
            w.writerow([r["case"], r["phi"], r["F"], "%.6g" % r["k"],
                        r["strain"], r["blocks"]]
                       + ["%.4g" % r[q] for q in ("A", "dA", "etaEff",
                          "dEtaEff", "etaDirect", "dEtaDirect", "etaRBulk",
                          "dEtaRBulk")] + [r["bulkTrusted"]]
                       + ["%.4g" % r[q] for q in ("rateNoise", "phikRel",
                          "dPhikRel", "phikRelStart")]
                       + ["%.4g" % e.get(q, float("nan")) for q in
                          ("etaEff", "dEtaEff", "etaDirect", "dEtaDirect")]
                       + ["%.4g" % u[0], "%.4g" % u[1],
                          "yes" if u[2] else "no"])

    with open(outPath("migration.csv"), "w", newline="") as f:
        w = csv.writer(f)
        names = sorted(migration)
        w.writerow(["strain"] + ["phik/phi " + n for n in names])
        t0 = migration[names[0]][0]
        for i in range(0, len(t0), 100):
            w.writerow(["%.4g" % t0[i]] + ["%.4g" % migration[n][1][i]
                                           for n in names
                                           if i < len(migration[n][1])])

    # The momentum balance across y, averaged over the steady profiles
    momentum = {}
    for c in cases:
        if c.endswith("uniform"):
            continue
        cdir = os.path.join(work, c, "postProcessing", "coupling")
        times = sorted((float(d), d) for d in os.listdir(cdir)
                       if re.match(r"^[0-9.e+-]+$", d) and os.path.isfile(
                           os.path.join(cdir, d, "profile.dat")))
        profs = [table(os.path.join(cdir, d, "profile.dat"))
                 for t, d in times if t > CUT]
        ptimes = [t for t, d in times if t > CUT]
        if len(profs) < 2:
            continue
        y = profs[0]["y"]
        # tauExact of a profile is <tau> - (int f - mean): the mean of the
        # instantaneous total stress in place of <tau> (the relaxed one's
        # mean does not act, and lags)
        def exact(p):
            shift = (sum(p["tauInstant"]) - sum(p["tau"]))/len(p["tau"])
            return [x + shift for x in p["tauExact"]]
        exacts = [exact(p) for p in profs]
        # error bars: blocks of PROFILE_BLOCK strain (u' and the relaxed
        # stress are correlated over the coupling strain)
        rowsM = []
        for j in range(len(y)):
            b = {}
            for t, p in zip(ptimes, profs):
                b.setdefault(int((t - CUT - 1e-9)//PROFILE_BLOCK), []).append(
                    p["tauInstant"][j])
            m, e = meanErr([sum(v)/len(v) for k, v in sorted(b.items())])
            ex = sum(x[j] for x in exacts)/len(exacts)
            rowsM.append((y[j], m, e, ex))
        momentum[c] = (rowsM, len(profs))
    with open(outPath("momentum.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "profiles", "y", "tauInstant", "dTauInstant",
                    "tauExact"])
        for c in sorted(momentum):
            rowsM, n = momentum[c]
            for y, m, e, ex in rowsM:
                w.writerow([c, n, "%.4g" % y, "%.5g" % m, "%.3g" % e,
                            "%.5g" % ex])
    for c in sorted(momentum):
        rowsM, n = momentum[c]
        chi2 = sum(((m - ex)/e)**2 for y, m, e, ex in rowsM)/len(rowsM)
        print("%s: momentum chi2 per row %.2f over %d rows, %d profiles"
              % (c, chi2, len(rowsM), n))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(ext) or 1, figsize=(5*max(len(ext), 1), 4))
    axes = axes if hasattr(axes, "__len__") else [axes]
    for ax, phi in zip(axes, sorted(ext)):
        r = [x for x in rows if x["phi"] == phi and x["F"] != 0 and not x["off"]]
        A2 = [x["A"]**2 for x in r]
        ax.errorbar(A2, [x["etaEff"] for x in r], [x["dEtaEff"] for x in r],
                    fmt="o", label="etaEff = F/(k^2 A)")
        ax.errorbar(A2, [x["etaDirect"] for x in r],
                    [x["dEtaDirect"] for x in r], fmt="s",
                    label="etaDirect = 1 + sigma_k/(k A)")
        e = ext[phi]
        ax.errorbar([0], [e["etaEff"]], [e["dEtaEff"]], fmt="o", mfc="none",
                    color="C0")
        ax.errorbar([0], [e["etaDirect"]], [e["dEtaDirect"]], fmt="s",
                    mfc="none", color="C1")
        for q, col in (("etaEff", "C0"), ("etaDirect", "C1")):
            ax.plot([0] + A2, [e[q]] + [x[q] for x in r], ":", color=col)
        if phi in uniform:
            m, d, _ = uniform[phi]
            ax.axhspan(m - d, m + d, color="0.8",
                       label="uniform shear etaR")
        ax.set_xlabel("A^2 (amplitude of u', squared)")
        ax.set_ylabel("relative viscosity")
        ax.set_title("phi = %g, N = 500" % phi)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(outPath("perturbation.png"), dpi=100)

    fig, ax = plt.subplots(figsize=(6, 4))
    for n in sorted(migration):
        t, p = migration[n]
        ax.plot(t, p, label=n, lw=0.8)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("strain")
    ax.set_ylabel("phi_k/phi (cos mode of phi)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(outPath("migration.png"), dpi=100)
    if momentum:
        fig, axes = plt.subplots(1, len(momentum),
                                 figsize=(3.2*len(momentum), 4), sharey=True)
        axes = axes if hasattr(axes, "__len__") else [axes]
        for ax, c in zip(axes, sorted(momentum)):
            rowsM, n = momentum[c]
            ax.errorbar([m for y, m, e, ex in rowsM], [y for y, *_ in rowsM],
                        xerr=[e for y, m, e, ex in rowsM], fmt="o", ms=3,
                        label="steady mean")
            ax.plot([ex for y, m, e, ex in rowsM], [y for y, *_ in rowsM],
                    "k--", label="exact")
            ax.set_title(c, fontsize=9)
            ax.set_xlabel("total shear stress")
        axes[0].set_ylabel("y")
        axes[0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(outPath("momentum.png"), dpi=100)
    for name in ("perturbation.csv", "migration.csv", "momentum.csv",
                 "perturbation.png", "migration.png", "momentum.png"):
        print(outPath(name))


if __name__ == "__main__":
    main(*sys.argv[1:4])
