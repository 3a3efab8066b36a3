#!/usr/bin/python3
"""Tables and plots of docs/rheometry.md.

    analyse.py amplitude <workDir> <tag>   amplitude-<tag>.csv from the runs
                                           <workDir>/<tag>-<gamma0> of
                                           amplitude.sh; amplitude.png of
                                           every amplitude-*.csv here
    analyse.py flowcurve <workDir> <tag>   flowcurve-<tag>.csv from the runs
                                           <workDir>/<tag>-rate-<r> and
                                           <tag>-stress-<s> of flowcurve.sh
                                           (their steady summaries);
                                           flowcurve.png of every
                                           flowcurve-*.csv here but the
                                           other packings of a set
                                           (<tag>s<seed>), without the
                                           runs that sheared less than
                                           one strain unit (jammed)
    analyse.py agreement <name> <tag>...   agreement-<name>.csv: rate against
                                           stress control over independent
                                           packings (flowcurve-<tag>.csv
                                           here, one or more per seed):
                                           each run's etaR, the pooled
                                           (inverse-variance) mean of each
                                           control and setting over the
                                           seeds with their scatter against
                                           the error bars, and each stress
                                           setting against each rate in
                                           combined error bars
    analyse.py reversal <caseDir> <tag> <window>
                                           reversal-<tag>.csv and
                                           reversal-<tag>.png from a case
                                           whose rate reverses (reversal.sh):
                                           etaR and its shares against the
                                           strain since each reversal, the
                                           mean over the reversals with the
                                           scatter of the reversals over
                                           sqrt(reversals) as error bar,
                                           window: strain after a reversal
                                           analysed

Reads postProcessing/oscillation/*/oscillationSummary.dat (the latest start
time) and postProcessing/rheology/*/rheology.dat (joined over start times),
the CPU seconds and peak RSS of /usr/bin/time -v in log.time.
"""
import csv
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))

# Steady etaR of Table 1 at phi = 0.5 in rate-controlled uniform shear:
# docs/validation/frictionless.csv (N = 200, delta_lub = 0.05) and, for the
# others, the rate 1 of flowcurve-<tag>.csv (flowcurve.sh)
STEADY = {"FL": ("docs/validation/frictionless.csv", "frictionless", "0.5", "delta_lub=0.05")}


def read_table(path):
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("# Time"):
                names = line[1:].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    return names, rows


def joined_rheology(case):
    """Rows of every start time, a later start replacing from its time on"""
    dirs = sorted(glob.glob(os.path.join(case, "postProcessing", "rheology", "*")),
                  key=lambda d: float(os.path.basename(d)))
    names, rows = None, []
    for d in dirs:
        for path in sorted(p for p in glob.glob(os.path.join(d, "rheology*.dat"))
                           if not p.endswith("Summary.dat")):
            n, r = read_table(path)
            if not r:
                continue
            names = n
            rows = [x for x in rows if x[0] < r[0][0] - 1e-12] + r
    return names, rows


def cost(case):
    """CPU seconds (user + system), wall seconds and peak RSS in MB"""
    cpu = wall = rss = 0.0
    for path in glob.glob(os.path.join(case, "log.time*")):
        text = open(path).read()
        u = re.search(r"User time \(seconds\): ([0-9.]+)", text)
        s = re.search(r"System time \(seconds\): ([0-9.]+)", text)
        w = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([0-9:.]+)", text)
        m = re.search(r"Maximum resident set size \(kbytes\): ([0-9]+)", text)
        if u and s:
            cpu += float(u.group(1)) + float(s.group(1))
        if w:
            parts = [float(p) for p in w.group(1).split(":")]
            wall += sum(p*60**k for k, p in enumerate(reversed(parts)))
        if m:
            rss = max(rss, float(m.group(1))/1024)
    return cpu, wall, rss


def steady(tag):
    if tag in STEADY:
        path, case, phi, setting = STEADY[tag]
        for row in csv.DictReader(open(os.path.join(here, "..", "..", path))):
            if row["case"] == case and row["x"] == phi and row["setting"] == setting:
                return float(row["value"]), float(row["error"])
    path = os.path.join(here, "flowcurve-%s.csv" % tag)
    if os.path.isfile(path):
        for row in csv.DictReader(open(path)):
            if row["control"] == "rate" and float(row["setting"]) == 1:
                return float(row["etaR"]), float(row["etaR_error"])
    return None


def read_summary(case):
    """The latest rheologySummary.dat: {quantity: (mean, error, trusted,
    strainUsed)}"""
    paths = sorted(glob.glob(os.path.join(case, "postProcessing", "rheology", "*",
                                          "rheologySummary.dat")),
                   key=lambda p: float(p.split(os.sep)[-2]))
    if not paths:
        return None
    q = {}
    for line in open(paths[-1]):
        f = line.split()
        if line.startswith("  ") and len(f) == 10:
            q[f[0]] = (float(f[1]), float(f[2]), f[9] == "yes", float(f[7]))
    return q


def flowcurve(work, tag):
    rows = []
    for case in sorted(glob.glob(os.path.join(work, tag + "-*-*"))):
        control, setting = os.path.basename(case)[len(tag) + 1:].split("-", 1)
        q = read_summary(case)
        if not q or "shearRate" not in q:
            continue
        rate, sigma, eta = q["shearRate"], q["sigma"], q["etaR"]
        if control == "stress":
            # the target over the mean rate; the rate's relative error
            etaR = float(setting)/rate[0]
            etaErr = etaR*rate[1]/abs(rate[0])
        else:
            etaR, etaErr = eta[0], eta[1]
        cpu, wall, rss = cost(case)
        names, table = joined_rheology(case)
        steps = table[-1][names.index("steps")] if table else 0
        strain = table[-1][names.index("strain")] if table else 0
        overlap = max(r[names.index("maxOverlap")] for r in table) if table else 0
        rows.append({
            "tag": tag, "control": control, "setting": float(setting),
            "shearRate": rate[0], "shearRate_error": rate[1],
            "sigma": sigma[0], "sigma_error": sigma[1],
            "etaR": round(etaR, 4), "etaR_error": round(etaErr, 4),
            "etaR_of_rows": eta[0], "etaR_of_rows_error": eta[1],
            "contact_share": q["etaR_contact"][0]/eta[0] if "etaR_contact" in q else "",
            "trusted": "yes" if eta[2] and rate[2] else "no",
            "steady_strain": eta[3], "strain": round(strain, 3),
            "max_overlap": round(overlap, 4),
            "steps": int(steps), "cpu_seconds": round(cpu, 1),
            "cpu_ms_per_step": round(1000*cpu/steps, 3) if steps else "",
            "wall_seconds": round(wall, 1), "peak_rss_MB": round(rss, 1)})
    out = os.path.join(here, "flowcurve-%s.csv" % tag)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote " + out)
    plot_flowcurve()


def replica(tag):
    """A tag <base>s<seed> of another packing of a set flowcurve-<base>.csv
    holds (agreement, not a flow curve of its own)"""
    m = re.fullmatch(r"(.+?)s\d+", tag)
    return m is not None and os.path.exists(os.path.join(here, "flowcurve-%s.csv" % m.group(1)))


def pooled(values):
    """Inverse-variance mean and error of [(mean, error)]"""
    if any(e <= 0 for _, e in values):
        sys.exit("agreement: a run without an error bar (not steady): %s" % values)
    w = [1/e**2 for _, e in values]
    return sum(wi*m for wi, (m, _) in zip(w, values))/sum(w), 1/math.sqrt(sum(w))


def agreement(name, tags):
    rows = []
    runs = {}           # (control, setting): [(etaR, error)], one per seed
    for tag in tags:
        for x in csv.DictReader(open(os.path.join(here, "flowcurve-%s.csv" % tag))):
            key = (x["control"], float(x["setting"]))
            runs.setdefault(key, []).append((float(x["etaR"]), float(x["etaR_error"])))
            rows.append({"tag": tag, "control": x["control"], "setting": x["setting"],
                         "shearRate": x["shearRate"], "etaR": x["etaR"],
                         "etaR_error": x["etaR_error"], "note": ""})
    pooledRuns = {}
    for (control, setting), v in sorted(runs.items()):
        m, e = pooled(v)
        # chi^2 per degree of freedom of the seeds about their pooled mean:
        # about 1 if the error bars hold across packings
        chi2 = sum(((x - m)/ex)**2 for x, ex in v)/(len(v) - 1) if len(v) > 1 else float("nan")
        pooledRuns[(control, setting)] = (m, e)
        rows.append({"tag": "pooled", "control": control, "setting": setting,
                     "shearRate": "", "etaR": round(m, 4), "etaR_error": round(e, 4),
                     "note": "%d seeds, chi2/dof %.2f" % (len(v), chi2)})
    for (cs, ss), (ms, es) in pooledRuns.items():
        if cs != "stress":
            continue
        for (cr, sr), (mr, er) in pooledRuns.items():
            if cr != "rate":
                continue
            d, ed = ms - mr, math.hypot(er, es)
            rows.append({"tag": "stress %g - rate %g" % (ss, sr), "control": "",
                         "setting": "", "shearRate": "", "etaR": round(d, 4),
                         "etaR_error": round(ed, 4),
                         "note": "%.2f combined error bars, %.1f %%" % (abs(d)/ed, 100*d/mr)})
    out = os.path.join(here, "agreement-%s.csv" % name)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    for r in rows:
        print(r)
    print("wrote " + out)


def plot_flowcurve():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.5))
    paths = [p for p in sorted(glob.glob(os.path.join(here, "flowcurve-*.csv")))
             if not replica(os.path.basename(p)[len("flowcurve-"):-len(".csv")])]
    for path, colour in zip(paths, ("tab:blue", "tab:red", "tab:green", "tab:purple")):
        tag = os.path.basename(path)[len("flowcurve-"):-len(".csv")]
        rows = list(csv.DictReader(open(path)))
        for control, marker in (("rate", "o"), ("stress", "s")):
            # a run in which the suspension jammed (less than one strain
            # unit in all) has no steady flow to draw
            r = sorted((x for x in rows if x["control"] == control and float(x["strain"]) >= 1),
                       key=lambda x: float(x["sigma"]))
            if not r:
                continue
            sig = [float(x["setting"]) if control == "stress" else float(x["sigma"]) for x in r]
            eta = [float(x["etaR"]) for x in r]
            err = [float(x["etaR_error"]) for x in r]
            rate = [float(x["shearRate"]) for x in r]
            kw = dict(fmt=marker + "-", color=colour, mfc="none" if control == "stress" else colour,
                      label="%s, %s control" % (tag, control))
            a1.errorbar(sig, eta, yerr=err, **kw)
            a2.errorbar(rate, eta, yerr=err, **kw)
    for ax, x in ((a1, r"shear stress $\sigma$ [$\eta_0\dot\gamma_{ref}$]"),
                  (a2, r"shear rate $\dot\gamma$ [$\dot\gamma_{ref}$]")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(x)
        ax.set_ylabel(r"$\eta_r$")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle("Steady flow curves: rate and stress control")
    fig.tight_layout()
    out = os.path.join(here, "flowcurve.png")
    fig.savefig(out, dpi=120)
    print("wrote " + out)


def amplitude(work, tag):
    rows = []
    for case in glob.glob(os.path.join(work, tag + "-*")):
        summaries = sorted(glob.glob(os.path.join(case, "postProcessing", "oscillation", "*",
                                                  "oscillationSummary.dat")),
                           key=lambda p: float(p.split(os.sep)[-2]))
        if not summaries:
            continue
        q = {}
        header = open(summaries[-1]).readline()
        omega = float(re.search(r"omega = ([0-9.e+-]+)", header).group(1))
        for line in open(summaries[-1]):
            if line.startswith("  "):
                name, mean, err, cycles = line.split()
                q[name] = (float(mean), float(err), int(cycles))
        cpu, wall, rss = cost(case)
        rows.append({
            "tag": tag, "gamma0": q["gamma0"][0], "omega": omega,
            "etaP": q["etaP"][0], "etaP_error": q["etaP"][1],
            "etaPP": q["etaPP"][0], "etaPP_error": q["etaPP"][1],
            "Gp": q["Gp"][0], "Gp_error": q["Gp"][1],
            "Gpp": q["Gpp"][0], "Gpp_error": q["Gpp"][1],
            "I3overI1": q["I3overI1"][0], "I3overI1_error": q["I3overI1"][1],
            "cycles": q["gamma0"][2], "cpu_seconds": round(cpu, 1),
            "wall_seconds": round(wall, 1), "peak_rss_MB": round(rss, 1)})
    rows.sort(key=lambda r: r["gamma0"])
    out = os.path.join(here, "amplitude-%s.csv" % tag)
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("wrote " + out)
    plot_amplitude()


def plot_amplitude():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for path, colour in zip(sorted(glob.glob(os.path.join(here, "amplitude-*.csv"))),
                            ("tab:blue", "tab:red", "tab:green")):
        tag = os.path.basename(path)[len("amplitude-"):-len(".csv")]
        rows = list(csv.DictReader(open(path)))
        g = [float(r["gamma0"]) for r in rows]
        ax.errorbar(g, [float(r["etaP"]) for r in rows],
                    yerr=[float(r["etaP_error"]) for r in rows], fmt="o-",
                    color=colour, label=r"$\eta'$ " + tag)
        ax.errorbar(g, [float(r["etaPP"]) for r in rows],
                    yerr=[float(r["etaPP_error"]) for r in rows], fmt="s--",
                    color=colour, mfc="none", label=r"$\eta''$ " + tag)
        s = steady(tag)
        if s:
            ax.axhspan(s[0] - s[1], s[0] + s[1], color=colour, alpha=0.15)
            ax.axhline(s[0], color=colour, lw=0.8, ls=":",
                       label=r"steady $\eta_r$ " + tag)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"strain amplitude $\gamma_0$")
    ax.set_ylabel(r"$\eta' = G''/\omega$, $\eta'' = G'/\omega$ [$\eta_0$]")
    ax.set_title(r"Amplitude sweeps, Table 1 at $\phi = 0.5$, $\omega = 1$")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(here, "amplitude.png")
    fig.savefig(out, dpi=120)
    print("wrote " + out)


def reversal(case, tag, window):
    names, rows = joined_rheology(case)
    col = {n: k for k, n in enumerate(names)}
    rate = [r[col["shearRate"]] for r in rows]
    starts = [k for k in range(1, len(rows)) if rate[k]*rate[k - 1] < 0]
    shares = [n for n in names if n.startswith("etaR_")]
    # every reversal: etaR(s) at strain s since it, on a common grid
    grid = [window*(k + 0.5)/200 for k in range(200)]
    curves = []
    for k in starts:
        g0 = rows[k][col["strain"]]
        pts = []
        for r in rows[k:]:
            s = abs(r[col["strain"]] - g0)
            if r[col["shearRate"]]*rate[k] <= 0 or s > window:
                break
            pts.append((s, [abs(r[col["etaR"]])] + [r[col[n]] for n in shares]))
        if not pts or pts[-1][0] < 0.99*window:
            continue
        curve = []
        j = 0
        for s in grid:
            while j + 1 < len(pts) and pts[j + 1][0] < s:
                j += 1
            a, b = pts[j], pts[min(j + 1, len(pts) - 1)]
            w = 0 if b[0] == a[0] else (s - a[0])/(b[0] - a[0])
            curve.append([(1 - w)*x + w*y for x, y in zip(a[1], b[1])])
        curves.append(curve)
    n = len(curves)
    out = os.path.join(here, "reversal-%s.csv" % tag)
    fields = ["strain_since_reversal", "etaR", "etaR_error"]
    for s in shares:
        fields += [s, s + "_error"]
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(fields + ["reversals"])
        means = []
        for i, s in enumerate(grid):
            row = [round(s, 5)]
            m = []
            for q in range(1 + len(shares)):
                v = [c[i][q] for c in curves]
                mean = sum(v)/n
                err = math.sqrt(sum((x - mean)**2 for x in v)/(n - 1)/n) if n > 1 else 0
                row += [round(mean, 5), round(err, 5)]
                m.append((mean, err))
            means.append(m)
            w.writerow(row + [n])
    print("wrote %s (%d reversals)" % (out, n))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    labels = ["etaR"] + [s[len("etaR_"):] for s in shares]
    for q, label in enumerate(labels):
        mean = [m[q][0] for m in means]
        if q > 0 and max(abs(x) for x in mean) == 0:
            continue
        err = [m[q][1] for m in means]
        line, = ax.plot(grid, mean, lw=2 if q == 0 else 1,
                        color="k" if q == 0 else None,
                        label=r"$\eta_r$" if q == 0 else label)
        ax.fill_between(grid, [a - b for a, b in zip(mean, err)],
                        [a + b for a, b in zip(mean, err)],
                        color=line.get_color(), alpha=0.2)
    ax.set_xlabel(r"strain since the reversal $|\gamma - \gamma_r|$")
    ax.set_ylabel(r"$\eta_r$ and its shares")
    ax.set_title("Shear reversal, %s (mean of %d reversals, band: error)" % (tag, n))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(here, "reversal-%s.png" % tag)
    fig.savefig(png, dpi=120)
    print("wrote " + png)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "amplitude":
        amplitude(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "flowcurve":
        flowcurve(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 4 and sys.argv[1] == "agreement":
        agreement(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) == 5 and sys.argv[1] == "reversal":
        reversal(sys.argv[2], sys.argv[3], float(sys.argv[4]))
    else:
        sys.exit(__doc__)
