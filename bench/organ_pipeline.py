#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Organ S's pipeline stage by stage, two (or more) builds side by side (issue 35, sixth part).

Each round runs, for every build in turn (the order alternates from round to round), the whole
pipeline in that build's own directory:
  xfem-mesh organ --size SIZE, xfem-mesh cut-sine, xfem-classify, xfem-enrich,
  xfem-assemble (pipelines/organ/problem.json), xfem-solve
and each tool's `--version` (its floor: process start and shared libraries, no work). Per stage:
wall time (perf_counter around the process) and CPU time (user + system of the child, from
wait4's rusage, microseconds), medians over the rounds; for xfem-assemble also its own reported
"enriched tets" time and the wall time outside it. The load average is printed before and after.
At the end every output file of every build is compared byte for byte with the first build's.

Usage: bench/organ_pipeline.py BIN [BIN ...] [--size 0.022] [--runs 9]
  e.g. bench/organ_pipeline.py /work/wt/integ/build/tools build/tools --runs 11
Exit status 1 if any output differs between the builds.
"""
import argparse
import filecmp
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROBLEM = os.path.join(ROOT, "pipelines", "organ", "problem.json")


def run(argv, cwd):
    """Runs argv in cwd; returns (wall s, cpu s, stderr text). Fails loudly on a non-zero exit."""
    start = time.perf_counter()
    p = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode(errors="replace")
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - start
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(argv), err))
    return wall, usage.ru_utime + usage.ru_stime, err


def stages(bin_dir, size):
    t = lambda name: os.path.join(bin_dir, name)
    return [
        ("mesh organ", [t("xfem-mesh"), "-q", "organ", "--size", size, "-o", "organ.vtu"]),
        ("mesh cut-sine", [t("xfem-mesh"), "-q", "cut-sine", "-o", "cut.vtp"]),
        ("classify", [t("xfem-classify"), "-q", "organ.vtu", "--cut", "cut.vtp", "-o", "classified.vtu"]),
        ("enrich", [t("xfem-enrich"), "-q", "classified.vtu", "-o", "enriched.vtu"]),
        # not -q: its time line gives the enriched tets' share
        ("assemble", [t("xfem-assemble"), "enriched.vtu", "--cut", "cut.vtp", "--problem", PROBLEM, "-o", "sys"]),
        ("solve", [t("xfem-solve"), "-q", "sys", "-o", "u.mtx"]),
    ]


FLOORS = ["xfem-mesh", "xfem-classify", "xfem-enrich", "xfem-assemble", "xfem-solve"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bins", nargs="+", help="directories holding the tools, one per build")
    ap.add_argument("--size", default="0.022")
    ap.add_argument("--runs", type=int, default=9)
    args = ap.parse_args()
    bins = [os.path.abspath(b) for b in args.bins]
    tmp = tempfile.mkdtemp(prefix="organ_pipeline.")
    dirs = []
    for i, _ in enumerate(bins):
        dirs.append(os.path.join(tmp, "build%d" % i))
        os.mkdir(dirs[-1])
    wall, cpu = {}, {}  # (build, row) -> [seconds]
    add = lambda d, key, v: d.setdefault(key, []).append(v)
    print("load before: %.2f %.2f %.2f" % os.getloadavg())
    for r in range(args.runs):
        order = list(range(len(bins)))
        if r % 2:
            order.reverse()
        for b in order:
            total_w = total_c = 0.0
            for name, argv in stages(bins[b], args.size):
                w, c, err = run(argv, dirs[b])
                add(wall, (b, name), w)
                add(cpu, (b, name), c)
                total_w += w
                total_c += c
                if name == "assemble":
                    m = re.search(r"enriched tets ([0-9.]+) s", err)
                    enr = float(m.group(1)) if m else float("nan")
                    add(wall, (b, "assemble enriched tets"), enr)  # the tool's own report
                    add(cpu, (b, "assemble enriched tets"), float("nan"))
                    add(wall, (b, "assemble outside enriched tets"), w - enr)
                    add(cpu, (b, "assemble outside enriched tets"), float("nan"))
                    total_w -= enr
            add(wall, (b, "pipeline outside enriched tets"), total_w)
            add(cpu, (b, "pipeline outside enriched tets"), float("nan"))
            for tool in FLOORS:
                w, c, _ = run([os.path.join(bins[b], tool), "--version"], dirs[b])
                add(wall, (b, tool + " --version"), w)
                add(cpu, (b, tool + " --version"), c)
    print("load after: %.2f %.2f %.2f" % os.getloadavg())
    rows = [n for n, _ in stages(bins[0], args.size)] + ["assemble enriched tets", "assemble outside enriched tets",
                                                         "pipeline outside enriched tets"]
    rows += [t + " --version" for t in FLOORS]
    for i, b in enumerate(bins):
        print("build %d: %s" % (i, b))
    head = "%-34s" % ("organ --size %s, %d runs" % (args.size, args.runs))
    for i in range(len(bins)):
        head += " %10s %10s" % ("wall %d" % i, "cpu %d" % i)
    if len(bins) > 1:
        head += " %8s" % "wall %d/0" % (len(bins) - 1)
    print(head + "   (medians, ms)")
    for row in rows:
        line = "%-34s" % row
        for i in range(len(bins)):
            cw = [x for x in cpu[(i, row)] if x == x]
            line += " %10.1f %10s" % (1e3 * statistics.median(wall[(i, row)]),
                                      "%.1f" % (1e3 * statistics.median(cw)) if cw else "-")
        if len(bins) > 1:
            line += " %8.3f" % (statistics.median(wall[(len(bins) - 1, row)]) / statistics.median(wall[(0, row)]))
        print(line)
    # Byte for byte: every file each build wrote, against the first build's.
    differ = 0
    names = []
    for base, _, files in os.walk(dirs[0]):
        names += [os.path.relpath(os.path.join(base, f), dirs[0]) for f in files]
    for i in range(1, len(bins)):
        for n in sorted(names):
            other = os.path.join(dirs[i], n)
            if not os.path.exists(other) or not filecmp.cmp(os.path.join(dirs[0], n), other, shallow=False):
                print("DIFFERS: build %d's %s" % (i, n))
                differ += 1
    if len(bins) > 1:
        print("outputs: %d files per build, %s" % (len(names), "all identical byte for byte" if not differ
                                                       else "%d differ" % differ))
    subprocess.run(["rm", "-rf", tmp])
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
