#!/usr/bin/python3
"""wavy.py WORK OUT [TAG]: the back-reaction of Table 3 YW (wavy.sh) as
OUT/wavy<TAG>.csv and OUT/wavy<TAG>.png.

  wavy.csv   per run: the steady etaR of rheologySummary.dat (error bar, and
             whether it is trusted), the mean of etaR after the start-up cut
             of the summary, the wave amplitude of the flow (imposed: 20;
             coupled: the steady mean of A of amplitude.dat with its error),
             that of the particles' velocity (from profiles.dat, the sine
             mode of <u_x> - y over the 16 bins) and the range of the local
             shear rate of the flow across y
  wavy.png   etaR against strain; the local shear rate and the particles'
             <u_x> - y across y (profiles averaged over the written times
             after CUT); the coupled wave's amplitude against strain

Steady means: after CUT (1 strain), error bars from blocks of BLOCK (1)
strain, two coupling strains (standard deviation of the block means over
sqrt(blocks - 1)); etaR and its error bar are rheologySummary.dat's (its
MSER-5 start-up cut, blocks of two correlation strains).
"""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analyse import table, joined, meanErr  # noqa: E402

CUT = 1.0
BLOCK = 1.0


def blockMeans(t, v):
    out = {}
    for ti, vi in zip(t, v):
        if ti > CUT:
            out.setdefault(int((ti - CUT - 1e-9)//BLOCK), []).append(vi)
    full = max(len(b) for b in out.values())
    return [sum(b)/len(b) for k, b in sorted(out.items()) if len(b) > 0.9*full]


def summary(path):
    for line in open(path):
        w = line.split()
        if w and w[0] == "etaR" and len(w) == 10:
            return float(w[1]), float(w[2]), w[9] == "yes"
    return float("nan"), float("nan"), False


def profiles(post, name, column):
    d = os.path.join(post, name)
    times = sorted((float(x), x) for x in os.listdir(d)
                   if x.replace(".", "").replace("e", "").isdigit()
                   and os.path.isfile(os.path.join(d, x, column[0])))
    ps = [table(os.path.join(d, x, column[0])) for t, x in times if t > CUT]
    if not ps:
        return None, None, 0
    y = ps[0]["y"]
    return y, [sum(p[column[1]][j] for p in ps)/len(ps) for j in range(len(y))], len(ps)


def main(work, out, tag=""):
    rows, curves = [], {}
    for c in ("imposed", "coupled"):
        post = os.path.join(work, c, "postProcessing")
        rheo = joined(os.path.join(post, "rheology"), "rheology.dat")
        latest = max((float(d), d) for d in os.listdir(os.path.join(post, "rheology"))
                     if os.path.isfile(os.path.join(post, "rheology", d,
                                                    "rheologySummary.dat")))[1]
        m, e, trusted = summary(os.path.join(post, "rheology", latest,
                                             "rheologySummary.dat"))
        Ly = float(open(os.path.join(work, c, "constant", "particleBox"))
                   .read().split("Ly")[1].split(";")[0])
        k = 2*math.pi/Ly
        y, ux, nP = profiles(post, "profiles", ("profiles.dat", "Ux"))
        Ap = 2*sum((u - yy)*math.sin(k*yy) for u, yy in zip(ux, y))/len(y)
        N = int(re.search(r"nParticles\s+(\d+)", open(os.path.join(
            work, c, "constant", "suspensionProperties")).read()).group(1))
        r = {"run": c, "N": N, "Ly": Ly, "etaR": m, "dEtaR": e,
             "trusted": trusted, "strain": rheo["Time"][-1],
             "etaRMean": sum(v for t, v in zip(rheo["Time"], rheo["etaR"])
                             if t > CUT)/max(1, sum(1 for t in rheo["Time"] if t > CUT)),
             "Ap": Ap, "profiles": nP}
        if c == "coupled":
            a = joined(os.path.join(post, "coupling"), "amplitude.dat")
            A, dA = meanErr(blockMeans(a["Time"], a["A"]))
            yr, rate, _ = profiles(post, "coupling", ("profile.dat", "shearRate"))
            curves["amp"] = (a["Time"], a["A"], a["Ap"])
        else:
            A, dA = 20.0, 0.0
            yr = y
            rate = [1 + 20*k*math.cos(k*yy) for yy in yr]
        r.update({"A": A, "dA": dA, "rateMin": min(rate), "rateMax": max(rate)})
        rows.append(r)
        curves[c] = (rheo["Time"], rheo["etaR"], y, ux, yr, rate)

    with open(os.path.join(out, "wavy" + tag + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        keys = ["run", "N", "Ly", "strain", "etaR", "dEtaR", "trusted",
                "etaRMean", "A", "dA", "Ap", "rateMin", "rateMax", "profiles"]
        w.writerow(keys)
        for r in rows:
            w.writerow([("%.4g" % r[q]) if isinstance(r[q], float) else r[q]
                        for q in keys])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2, a3, a4) = plt.subplots(1, 4, figsize=(16, 4))
    for c in ("imposed", "coupled"):
        t, eta, y, ux, yr, rate = curves[c]
        a1.plot(t, eta, lw=0.8, label=c)
        a2.plot(rate, yr, "o-", ms=3, label=c + " flow")
        a3.plot([u - yy for u, yy in zip(ux, y)], y, "o-", ms=3,
                label=c + " particles")
    a1.set_xlabel("strain")
    a1.set_ylabel("etaR")
    a1.legend(fontsize=8)
    a2.set_xlabel("local shear rate of the flow [gammaDot]")
    a2.set_ylabel("y [a0]")
    a2.legend(fontsize=8)
    a3.set_xlabel("<u_x> - gammaDot y of the particles [gammaDot a0]")
    a3.legend(fontsize=8)
    t, A, Ap = curves["amp"]
    a4.plot(t, A, lw=0.8, label="A of the flow u'")
    a4.plot(t, Ap, lw=0.8, label="Ap of the particles")
    a4.axhline(20, color="k", ls="--", lw=0.8, label="imposed wave")
    a4.set_xlabel("strain")
    a4.set_ylabel("wave amplitude [gammaDot a0]")
    a4.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "wavy" + tag + ".png"), dpi=100)
    print(os.path.join(out, "wavy" + tag + ".csv"))
    print(os.path.join(out, "wavy" + tag + ".png"))


if __name__ == "__main__":
    main(*sys.argv[1:4])
