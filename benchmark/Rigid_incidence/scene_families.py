#!/usr/bin/env python3
# The scene families of issue 28 at growing sizes until they break, solved by one or more
# builds of the tool side by side in one run (e.g. --tool before=OLD/rigid_incidence
# --tool now=build/examples/Rigid_incidence/rigid_incidence), or one build with different
# options (--tool "p128=build/examples/Rigid_incidence/rigid_incidence --precision 128").
#
# Each scene is planted (scripts/make_scene_family.py: exact rational poses), so the planted
# configuration must be among the answers. For each family, size and tool: wall-clock and CPU
# seconds of `rigid_incidence solve SCENE --json --quiet --max-seconds LIMIT`, whether the answer
# is complete, its configurations (certified), and whether the planted one is among them. A
# family stops for a tool at its first size that is not complete within the limit (or is
# refused). Results: OUT.md (a table, with the targets), OUT.csv and OUT.svg (time
# against the number of bodies, log scale).
#
# Usage: benchmark/Rigid_incidence/scene_families.py [--tool LABEL=PATH]... [--families a,b]
#        [--limit SECONDS] [--seed N] [--out PREFIX] [--max-size N]
import argparse, csv, datetime, json, math, os, platform, resource, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
GENERATOR = os.path.join(ROOT, "scripts", "make_scene_family.py")

# sizes tried, in order (a family stops at its first failure)
LADDER = {
    "chain": [2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 20, 25, 30],
    "ring": [6, 7, 8, 9, 10, 11, 12, 14, 16],
    "tree": [3, 5, 7, 9, 11, 13, 15, 17, 21, 25, 31],
    "molecule": [7, 8, 9, 10, 11, 12, 13, 14, 16, 18, 20],
    "platforms": [1, 2, 3, 4, 5, 6, 7, 8],
    "strip": [2, 4, 6, 8, 10, 12, 14, 16],
}
# issue 28's targets: size -> seconds (complete, every configuration certified, the planted one
# among them)
TARGETS = {
    "chain": {12: 60, 20: 60, 30: 300},
    "ring": {10: 60, 12: 60},
    "tree": {15: 60},
    "molecule": {16: 60},
    "platforms": {2: 60, 3: 60},
    "strip": {12: 60},
}


def cpu_children():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def run_one(tool, scene, planted, limit):
    """one solve: a dict of what it measured"""
    c0 = cpu_children()
    t0 = time.monotonic()
    try:
        p = subprocess.run([tool[0], "solve", scene, "--json", "--quiet", "--max-seconds", str(limit)] + tool[1:],
                           capture_output=True, text=True, timeout=limit + 120)
        out, err, rc = p.stdout, p.stderr, p.returncode
    except subprocess.TimeoutExpired as e:
        out, err, rc = "", "killed at %g s: --max-seconds did not stop it" % (limit + 120), -9
    wall = time.monotonic() - t0
    cpu = cpu_children() - c0
    r = {"wall": wall, "cpu": cpu, "rc": rc, "complete": False, "configurations": 0, "certified": 0,
         "planted": False, "why": ""}
    try:
        d = json.loads(out)
    except ValueError:
        lines = [x for x in err.strip().splitlines() if x.strip()]
        r["why"] = (lines[-1] if lines else "exit status %d, no answer" % rc)[:160]
        return r
    sols = d.get("solutions", [])
    r["complete"] = bool(d.get("complete"))
    # the exact count (a factored answer lists its product only up to --max-listed); a
    # complete answer has every configuration certified, listed or not
    r["configurations"] = int(d.get("configuration_count", len(sols)))
    r["listed"] = len(sols)
    r["certified"] = r["configurations"] if r["complete"] else sum(1 for s in sols if s.get("certified"))
    if not r["complete"]:
        lim = d.get("limits") or []
        r["why"] = ("; ".join(str(x) for x in lim) if lim else str(d.get("diagnosis", "not complete")))[:160]
    size = max(1.0, max(abs(v) for p in planted.values() for v in p))
    for s in sols:
        pts = s.get("points", {})
        if all(k in pts for k in planted) and \
           max(max(abs(a - b) for a, b in zip(pts[k], planted[k])) for k in planted) <= 1e-6 * size:
            r["planted"] = True
            break
    if not r["planted"] and d.get("listing"):
        r["planted"] = None  # not among the configurations listed: not checked
    return r


def seconds(x):
    return "%.3g" % x if x < 100 else "%.0f" % x


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tool", action="append", default=[],
                    help="LABEL=PATH [OPTION...]: a rigid_incidence build and options of its solve (repeatable)")
    ap.add_argument("--families", default=",".join(LADDER))
    ap.add_argument("--limit", type=float, default=60.0, help="--max-seconds of each solve (default 60)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-size", type=int, default=0, help="stop each family after this size (0: no bound)")
    ap.add_argument("--out", default=os.path.join(HERE, "results", "scene_families"))
    a = ap.parse_args()
    tools = []
    for t in a.tool or ["now=" + os.path.join(ROOT, "build", "examples", "Rigid_incidence", "rigid_incidence")]:
        label, _, rest = t.partition("=")
        words = rest.split()
        path = words[0] if words else ""
        if not path or not os.access(path, os.X_OK):
            sys.exit("scene_families: --tool %s: no program at '%s' (build the tool first)" % (t, path))
        tools.append((label, [os.path.abspath(path)] + words[1:]))
    families = [f for f in a.families.split(",") if f]
    for f in families:
        if f not in LADDER:
            sys.exit("scene_families: unknown family '%s' (one of %s)" % (f, ", ".join(LADDER)))
    rows = []
    tmp = tempfile.mkdtemp(prefix="ri_families_")
    for fam in families:
        alive = {label for label, _ in tools}
        for k in LADDER[fam]:
            if not alive or (a.max_size and k > a.max_size):
                break
            scene = os.path.join(tmp, "%s%d.json" % (fam, k))
            planted_file = os.path.join(tmp, "%s%d.planted.json" % (fam, k))
            with open(scene, "w") as f:
                subprocess.run([sys.executable, GENERATOR, fam, str(k), "--seed", str(a.seed), "--planted", planted_file],
                               stdout=f, check=True)
            planted = json.load(open(planted_file))["points"]
            bodies = len(json.load(open(scene))["bodies"])
            for label, path in tools:
                if label not in alive:
                    continue
                r = run_one(path, scene, planted, a.limit)
                target = TARGETS.get(fam, {}).get(k)
                ok = r["complete"] and r["planted"] is not False and r["certified"] == r["configurations"]
                r.update({"family": fam, "size": k, "bodies": bodies, "tool": label, "target": target,
                          "meets": (ok and r["wall"] <= target) if target else None})
                rows.append(r)
                print("%-9s %3d  %-8s %8.2f s wall %8.2f s CPU  %s, %d configuration(s), %d certified, planted %s%s" %
                      (fam, k, label, r["wall"], r["cpu"], "complete" if r["complete"] else "NOT complete",
                       r["configurations"], r["certified"],
                       {True: "found", False: "MISSING"}.get(r["planted"], "not checked (%d listed)" % r["listed"]),
                       (": " + r["why"]) if r["why"] else ""), file=sys.stderr, flush=True)
                if not ok:
                    alive.discard(label)
    write(a, tools, rows)


def write(a, tools, rows):
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    keys = ["family", "size", "bodies", "tool", "wall", "cpu", "complete", "configurations", "certified", "planted",
            "target", "meets", "rc", "why"]
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    cpu = platform.processor() or platform.machine()
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    with open(a.out + ".md", "w") as f:
        f.write("# Issue 28's scene families: solve time against size\n\n")
        f.write("`%s`, %s UTC, %s, %d cores. Tools: %s. Each solve: `rigid_incidence solve SCENE --json --quiet "
                "--max-seconds %g`; scenes from `scripts/make_scene_family.py FAMILY SIZE --seed %d` (planted, exact "
                "rational poses). \"planted\": the planted configuration is among the answers (1e-6 of the scene's size; "
                "\"not checked\" where the list was cut at --max-listed, the count exact). "
                "A family stops for a tool at its first size not complete, not all certified or without the planted "
                "configuration. \"target\": issue 28's (seconds of wall clock, complete, all certified, planted found).\n\n" %
                (" ".join(sys.argv), datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"), cpu, os.cpu_count(),
                 ", ".join("%s = `%s`" % (t[0], " ".join(t[1])) for t in tools), a.limit, a.seed))
        f.write("| family | size | bodies | tool | wall s | CPU s | complete | configurations | certified | planted | target | why not complete |\n")
        f.write("| :-- | --: | --: | :-- | --: | --: | :-- | --: | --: | :-- | :-- | :-- |\n")
        for r in rows:
            tgt = ""
            if r["target"]:
                tgt = ("met (%g s)" if r["meets"] else "missed (%g s)") % r["target"]
            f.write("| %s | %d | %d | %s | %s | %s | %s | %d | %d | %s | %s | %s |\n" %
                    (r["family"], r["size"], r["bodies"], r["tool"], seconds(r["wall"]), seconds(r["cpu"]),
                     "yes" if r["complete"] else "**no**", r["configurations"], r["certified"],
                     {True: "yes", False: "**no**"}.get(r["planted"], "not checked (%d listed)" % r.get("listed", 0)), tgt,
                     r["why"].replace("|", "/")))
        f.write("\nTargets not reached by any size run: ")
        missing = []
        for fam, t in TARGETS.items():
            for k, s in t.items():
                if not any(r["family"] == fam and r["size"] == k for r in rows) and fam in a.families.split(","):
                    missing.append("%s %d (%g s)" % (fam, k, s))
        f.write(", ".join(missing) if missing else "none")
        f.write(".\n\n![time against bodies](%s.svg)\n" % os.path.basename(a.out))
    svg(a.out + ".svg", rows, a.limit)


def svg(path, rows, limit):
    W, H, L, T, PW, PH = 780, 460, 70, 40, 520, 360
    series = {}
    for r in rows:
        series.setdefault((r["family"], r["tool"]), []).append(r)
    xmax = max([r["bodies"] for r in rows] + [2])
    lo, hi = 0.01, max([limit] + [r["wall"] for r in rows])
    def X(b):
        return L + PW * (b / xmax)
    def Y(t):
        t = min(max(t, lo), hi)
        return T + PH * (1 - (math.log10(t) - math.log10(lo)) / (math.log10(hi) - math.log10(lo)))
    colors = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"]
    o = ['<?xml version="1.0" encoding="UTF-8"?>',
         '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" font-family="sans-serif" font-size="11">' % (W, H + 20, W, H + 20),
         '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="22" font-size="14" font-weight="bold">Scene families: wall-clock seconds of a full solve against bodies</text>' % L,
         '<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' % (L, T, PW, PH)]
    e = math.floor(math.log10(lo))
    while 10 ** e <= hi * 1.0001:
        y = Y(10 ** e)
        o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/><text x="%d" y="%.1f" text-anchor="end">%g s</text>' %
                 (L, y, L + PW, y, L - 6, y + 4, 10 ** e))
        e += 1
    for b in range(0, xmax + 1, max(1, xmax // 10)):
        o.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (X(b), T + PH + 16, b))
    o.append('<text x="%d" y="%d" text-anchor="middle">bodies</text>' % (L + PW // 2, T + PH + 34))
    y_limit = Y(limit)
    o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#999" stroke-dasharray="4,3"/><text x="%d" y="%.1f" fill="#666">limit %g s</text>' %
             (L, y_limit, L + PW, y_limit, L + 4, y_limit - 4, limit))
    for i, ((fam, tool), rs) in enumerate(sorted(series.items())):
        c = colors[i % len(colors)]
        dash = "" if i < len(colors) else ' stroke-dasharray="5,3"'
        pts = " ".join("%.1f,%.1f" % (X(r["bodies"]), Y(r["wall"])) for r in rs)
        o.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="1.5"%s/>' % (pts, c, dash))
        for r in rs:
            ok = r["complete"] and r["planted"]
            o.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s" stroke="%s"/>' %
                     (X(r["bodies"]), Y(r["wall"]), c if ok else "white", c))
        ly = T + 14 + 16 * i
        o.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/><text x="%d" y="%d">%s (%s)</text>' %
                 (L + PW + 12, ly - 4, L + PW + 32, ly - 4, c, L + PW + 36, ly, fam, tool))
    o.append('<text x="%d" y="%d" fill="#666">open circle: not complete, or the planted configuration missing</text>' % (L, H + 12))
    o.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(o) + "\n")


if __name__ == "__main__":
    main()
