#!/usr/bin/env python3
"""Rows and summary of the paired LF_DEM / wavyShearFoam timing (run.sh). Stdlib only.

  summarise.py --row REP CODE STRAIN_END RUN_DIR WINDOW_START [STRAIN0]
      prints one CSV row of runs.csv for a finished run:
      rep,code,strain_end,user_s,sys_s,wall_s,maxrss_kB,load1,steps_total,
      steps_window,window_start,mean_cg_window,dir
      (user/sys/wall/max RSS from RUN_DIR/time.txt of /usr/bin/time -v;
       steps: LF_DEM from the dt column of data_*.dat, the mean step over each
       0.01 strain output interval, so steps = 0.01/dt per row; ours from the
       steps column of rheology.dat. steps_window and mean_cg_window count
       the rows with strain > WINDOW_START. mean_cg_window: mean of the
       cgIterations column, the iterations of the last CG solve of each
       0.01 strain row. STRAIN0, default 0: the strain our run restarted
       from (run.sh -b); STRAIN_END and WINDOW_START count from it.)

  summarise.py --summary RUNS_CSV START END RESULTS_CSV
      per repetition and code: CPU (user+sys) and wall per strain as
      (run to END - run to START)/(END - START), steps per strain and mean dt
      in the window, peak RSS of the run to END; writes RESULTS_CSV and prints
      a Markdown table of medians and ranges (and the paired ratios LF_DEM/ours).
"""
import csv
import glob
import os
import re
import statistics
import sys


def time_v(path):
    out = {}
    with open(path) as f:
        for line in f:
            k, _, v = line.strip().rpartition(": ")
            out[k] = v
    wall = out["Elapsed (wall clock) time (h:mm:ss or m:ss)"]
    secs = 0.0
    for part in wall.split(":"):
        secs = 60 * secs + float(part)
    status = int(out.get("Exit status", "0"))
    return (float(out["User time (seconds)"]), float(out["System time (seconds)"]),
            secs, int(out["Maximum resident set size (kbytes)"]), status)


def lfdem_data(run_dir):
    """LF_DEM's data_*.dat of a run: ({column name: index}, rows of floats)"""
    files = glob.glob(os.path.join(run_dir, "data_*.dat"))
    if len(files) != 1:
        raise SystemExit("%s: expected one data_*.dat" % run_dir)
    cols = {}
    rows = []
    with open(files[0]) as f:
        for line in f:
            if line.startswith("#"):
                h = line[1:].strip()
                if ":" in h and h.split(":")[0].isdigit():
                    n, name = h.split(":", 1)
                    cols[name.strip()] = int(n) - 1
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    return cols, rows


def lfdem_steps(run_dir, start):
    cols, rows = lfdem_data(run_dir)
    s, dt = cols["cumulated shear strain"], cols["dt"]
    total = window = 0
    for prev, r in zip(rows, rows[1:]):
        n = round((r[s] - prev[s]) / r[dt])
        total += n
        if r[s] > start + 1e-9:
            window += n
    return rows[-1][s], total, window, ""


def ours_steps(run_dir, start, strain0):
    files = glob.glob(os.path.join(run_dir, "postProcessing", "rheology", "*", "rheology.dat"))
    if len(files) != 1:
        raise SystemExit("%s: expected one rheology.dat" % run_dir)
    names, rows = None, []
    with open(files[0]) as f:
        for line in f:
            if line.startswith("# Time"):
                names = [c.strip() for c in line[1:].split("\t")]
            elif not line.startswith("#") and line.strip():
                rows.append([float(v) for v in line.split()])
    c = {n: i for i, n in enumerate(names)}
    s, st = c["strain"], c["steps"]
    # A restart: strains and steps count from the state it started from
    st0 = 0
    if strain0:
        state = os.path.join(run_dir, "%g" % strain0, "uniform", "suspensionState")
        with open(state) as f:
            st0 = int(re.search(r"^steps\s+(\d+);", f.read(), re.M).group(1))
    for r in rows:
        r[s] -= strain0
        r[st] -= st0
    at_start = [r[st] for r in rows if abs(r[s] - start) < 1e-9]
    window = rows[-1][st] - at_start[0] if at_start and rows[-1][s] > start + 1e-9 else ""
    cg = ""
    if "cgIterations" in c:
        w = [r[c["cgIterations"]] for r in rows if r[s] > start + 1e-9]
        cg = "%.1f" % statistics.mean(w) if w else ""
    return rows[-1][s], int(rows[-1][st]), (int(window) if window != "" else ""), cg


def row(args):
    rep, code, strain_end, run_dir, start = args[:5]
    strain0 = float(args[5]) if len(args) > 5 else 0.0
    start = float(start)
    user, sys_, wall, rss, status = time_v(os.path.join(run_dir, "time.txt"))
    if status != 0:
        raise SystemExit("%s: exit status %d" % (run_dir, status))
    if code == "lfdem":
        reached, total, window, cg = lfdem_steps(run_dir, start)
    else:
        reached, total, window, cg = ours_steps(run_dir, start, strain0)
    if abs(reached - float(strain_end)) > 1e-6:
        raise SystemExit("%s: reached strain %g, not %s" % (run_dir, reached, strain_end))
    with open(os.path.join(run_dir, "loadavg")) as f:
        load1 = f.read().split()[0]
    print(",".join(str(v) for v in (rep, code, strain_end, user, sys_, "%.2f" % wall, rss, load1,
                                    total, window if float(strain_end) > start else "",
                                    start, cg, run_dir)))


def fmt(v, nd):
    return ("%." + str(nd) + "f") % v


def med_range(vals, nd):
    return "%s (%s–%s)" % (fmt(statistics.median(vals), nd), fmt(min(vals), nd), fmt(max(vals), nd))


def summary(args):
    runs_csv, start, end, results_csv = args
    start, end = float(start), float(end)
    w = end - start
    runs = list(csv.DictReader(open(runs_csv)))
    by = {}
    for r in runs:
        by.setdefault((r["rep"], r["code"]), {})[float(r["strain_end"])] = r
    codes = [c for c in ("lfdem", "overdamped", "implicitEuler") if any(k[1] == c for k in by)]
    per = []
    for (rep, code), d in sorted(by.items(), key=lambda kv: (int(kv[0][0]), codes.index(kv[0][1]))):
        if start not in d or end not in d:
            continue
        a, b = d[start], d[end]
        cpu = lambda r: float(r["user_s"]) + float(r["sys_s"])
        steps = int(b["steps_window"])
        per.append({
            "rep": rep, "code": code,
            "cpu_s_per_strain": (cpu(b) - cpu(a)) / w,
            "user_s_per_strain": (float(b["user_s"]) - float(a["user_s"])) / w,
            "sys_s_per_strain": (float(b["sys_s"]) - float(a["sys_s"])) / w,
            "wall_s_per_strain": (float(b["wall_s"]) - float(a["wall_s"])) / w,
            "steps_per_strain": steps / w,
            "cpu_ms_per_step": 1000 * (cpu(b) - cpu(a)) / steps,
            "mean_dt": w / steps,
            "maxrss_MB": int(b["maxrss_kB"]) / 1024.0,
            "mean_cg": b["mean_cg_window"],
            "short_run_cpu_s": cpu(a),
            "load1_short": a["load1"], "load1_long": b["load1"],
        })
    keys = list(per[0].keys())
    with open(results_csv, "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=keys)
        wr.writeheader()
        for p in per:
            wr.writerow({k: (("%.6g" % v) if isinstance(v, float) else v) for k, v in p.items()})

    label = {"lfdem": "LF_DEM (Euler, adaptive dt)", "overdamped": "ours, overdamped",
             "implicitEuler": "ours, implicitEuler"}
    print("Strain window %g–%g (CPU of the run to %g minus the run to %g), one thread, "
          "%d repetitions; median (min–max)." % (start, end, end, start,
                                                  len({p['rep'] for p in per})))
    print()
    print("| code | CPU s per strain (user+sys) | wall s per strain | steps per strain | mean dt "
          "| CPU ms per step | mean CG iterations | peak RSS MB |")
    print("|---|---|---|---|---|---|---|---|")
    for c in codes:
        ps = [p for p in per if p["code"] == c]
        cg = [float(p["mean_cg"]) for p in ps if p["mean_cg"] not in ("", None)]
        print("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label[c], med_range([p["cpu_s_per_strain"] for p in ps], 1),
            med_range([p["wall_s_per_strain"] for p in ps], 1),
            med_range([p["steps_per_strain"] for p in ps], 0),
            "%.3g" % statistics.median([p["mean_dt"] for p in ps]),
            med_range([p["cpu_ms_per_step"] for p in ps], 1),
            med_range(cg, 1) if cg else "–",
            med_range([p["maxrss_MB"] for p in ps], 0)))
    if "lfdem" in codes:
        print()
        print("Paired ratios, LF_DEM CPU per strain / ours in the same repetition: ", end="")
        parts = []
        for c in codes[1:]:
            r = []
            for rep in sorted({p["rep"] for p in per}, key=int):
                l = [p for p in per if p["rep"] == rep and p["code"] == "lfdem"]
                o = [p for p in per if p["rep"] == rep and p["code"] == c]
                if l and o:
                    r.append(l[0]["cpu_s_per_strain"] / o[0]["cpu_s_per_strain"])
            if r:
                parts.append("%s %s" % (label[c].replace("ours, ", ""), med_range(r, 1)))
        print("; ".join(parts) + ".")
    print()
    print("CPU of the runs to strain %g (set-up and the discarded start), median: %s." % (
        start, ", ".join("%s %.2f s" % (label[c], statistics.median(
            [p["short_run_cpu_s"] for p in per if p["code"] == c])) for c in codes)))


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--row" and len(sys.argv) in (7, 8):
        row(sys.argv[2:])
    elif len(sys.argv) > 1 and sys.argv[1] == "--summary" and len(sys.argv) == 6:
        summary(sys.argv[2:])
    else:
        sys.exit(__doc__)
