#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Stage benchmarks against their floors (issue 9); rewrites the generated part of docs/PERFORMANCE.md.

Run by `make -f Makefile.examples bench` (not part of the tests). For the unstructured beam of the
paper with its cut at three sizes (about 10^4, 10^5 and 5x10^5 tets) and for the 256k-DOF CG-FEM
reference (pipelines/reference), every stage runs RUNS times; GNU time gives its wall time and
peak RSS; the tables show medians. Side by side in the same run:
  xfem-solve     vs bench/bare_cholmod (G's: the same reader, bare CHOLMOD analyse+factor+solve) on
                 the same matrix (zero-row enriched DOFs pinned first, as xfem-solve does);
  xfem-assemble  vs bench/bare_assemble (the same element matrices in memory, no file I/O);
  every stage    vs `cat` of the bytes it reads and writes (the I/O floor).
Meshes are generated once into bench/out/cache (mesh generation is not a benchmarked stage).
Everything between the markers <!-- bench:begin --> and <!-- bench:end --> of docs/PERFORMANCE.md
is replaced; the rest of the file is left as it is.

Also the organ example (pipelines/organ without its PNG) at two sizes, whole pipeline.
Usage: bench/bench.py [--build DIR] [--runs N] [--large-runs N] [--sizes H1 H2 H3] [--quick] [--scale] [--no-write]
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN, END = "<!-- bench:begin -->", "<!-- bench:end -->"
STAGES = ["classify", "enrich", "assemble", "solve", "visualize", "rmserror"]
BEAM_HI = ["0.03", "0.06", "0.2"]


def log(msg):
    print("bench: " + msg, file=sys.stderr, flush=True)


class Runner:
    def __init__(self, build, work):
        self.tools = os.path.join(build, "tools")
        self.bench = os.path.join(build, "bench")
        self.work = work
        self.tfile = os.path.join(work, ".time")

    def tool(self, name):
        return os.path.join(self.tools, name)

    def timed(self, cmd, cwd):
        """Runs cmd under GNU time; returns (wall s, peak RSS MB, stdout, stderr)."""
        full = ["/usr/bin/time", "-f", "%e %M", "-o", self.tfile] + cmd
        t0 = time.perf_counter()
        p = subprocess.run(full, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        wall = time.perf_counter() - t0  # GNU time's %e has 10 ms resolution: too coarse for the small cases
        if p.returncode != 0:
            raise SystemExit("bench: command failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr[-2000:]))
        with open(self.tfile) as f:
            rss = f.read().split()[-1]
        return wall, int(rss) / 1024.0, p.stdout, p.stderr


def size_of(paths, cwd):
    total = 0
    for p in paths:
        p = os.path.join(cwd, p)
        if os.path.isdir(p):
            total += sum(os.path.getsize(os.path.join(p, f)) for f in os.listdir(p))
        else:
            total += os.path.getsize(p)
    return total


def expand(paths, cwd):
    out = []
    for p in paths:
        if os.path.isdir(os.path.join(cwd, p)):
            out += sorted(os.path.join(p, f) for f in os.listdir(os.path.join(cwd, p)))
        else:
            out.append(p)
    return out


def med(values):
    return statistics.median(values) if values else float("nan")


def fit_exponent(xs, ys):
    """Least-squares slope of log y over log x."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-6)) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


def machine():
    model = "unknown"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as f:
        mem_kb = int(f.readline().split()[1])
    return {"nproc": os.cpu_count(), "model": model, "mem_gb": mem_kb / 1024 / 1024,
            "load": open("/proc/loadavg").read().split()[:3]}


def ensure_mesh(r, cache, case):
    """The cached mesh and the wall time / peak RSS of generating it (timed once, when generated)."""
    path = os.path.join(cache, case["mesh_file"])
    timing = path + ".time.json"
    if not os.path.exists(path) or not os.path.exists(timing):
        log("generating %s (cached; timed once): %s" % (case["mesh_file"], " ".join(case["mesh_cmd"])))
        w, m, _, _ = r.timed([r.tool("xfem-mesh"), "-q"] + case["mesh_cmd"] + ["-o", path + ".tmp.vtu"], cache)
        os.replace(path + ".tmp.vtu", path)
        with open(timing, "w") as f:
            json.dump({"wall": w, "rss": m}, f)
    return path, json.load(open(timing))


def mpirun(processes):
    """mpirun with what a shared 2-core box (and root) needs."""
    cmd = ["mpirun", "-np", str(processes), "--oversubscribe", "--bind-to", "none", "--mca", "mpi_yield_when_idle", "1"]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    return cmd


def stage_commands(case, r, ref):
    """stage -> (command, inputs, outputs); paths relative to the case's work dir."""
    problem = case.get("problem", os.path.join(ROOT, "pipelines", "beam", "problem.json"))
    cut = ["--cut", "cut.vtp"] if case["cut"] else []
    cmds = {
        "classify": ([r.tool("xfem-classify"), "-q", "mesh.vtu"] + cut + ["-o", "classified.vtu", "--summary", "counts.json"],
                     ["mesh.vtu"] + (["cut.vtp"] if case["cut"] else []), ["classified.vtu"]),
        "enrich": ([r.tool("xfem-enrich"), "-q", "classified.vtu", "-o", "enriched.vtu"], ["classified.vtu"], ["enriched.vtu"]),
        "assemble": ([r.tool("xfem-assemble"), "enriched.vtu"] + cut + ["--problem", problem, "-o", "system"],
                     ["enriched.vtu", problem] + (["cut.vtp"] if case["cut"] else []), ["system"]),
        "solve": ([r.tool("xfem-solve"), "-q", "system", "-o", "u.mtx", "--report", "solve.json"], ["system"], ["u.mtx"]),
        # Without --png: the picture is VTK's OpenGL rendering under xvfb, not the tool's work.
        "visualize": ([r.tool("xfem-visualize"), "-q", "enriched.vtu", "--cut", "cut.vtp", "--solution", "u.mtx",
                       "--problem", problem, "-o", "deformed.vtu", "--faces", "wound.vtp"],
                      ["enriched.vtu", "cut.vtp", "u.mtx", problem], ["deformed.vtu", "wound.vtp"]),
        # --cut also for the reference: xfem-enrich output is read as an X-FEM mesh (no enriched DOFs there)
        "rmserror": ([r.tool("xfem-rmserror"), "-q", "enriched.vtu", "--cut", "cut.vtp", "--solution", "u.mtx", "--reference",
                      ref["enriched"], "--reference-solution", ref["u"], "-o", "rms.json"],
                     ["enriched.vtu", "cut.vtp", "u.mtx", ref["enriched"], ref["u"]], ["rms.json"]),
    }
    return cmds


def io_floor(r, cwd, inputs, outputs, runs):
    """Median time of `cat inputs > /dev/null; cat outputs > copy` (the same bytes read and written)."""
    ins = " ".join("'%s'" % p for p in expand(inputs, cwd))
    outs = " ".join("'%s'" % p for p in expand(outputs, cwd))
    times = []
    for _ in range(runs):
        w, _, _, _ = r.timed(["sh", "-c", "cat %s >/dev/null; cat %s > .io_copy; rm -f .io_copy" % (ins, outs)], cwd)
        times.append(w)
    return med(times)


def run_case(r, case, runs, cache, ref):
    cwd = os.path.join(r.work, case["name"])
    if os.path.isdir(cwd):
        shutil.rmtree(cwd)
    os.makedirs(cwd)
    mesh_path, mesh_time = ensure_mesh(r, cache, case)
    shutil.copy(mesh_path, os.path.join(cwd, "mesh.vtu"))
    cut_cmd = case.get("cut_cmd", ["cut-rect", "--beam-cut"])
    cut_cache = os.path.join(cache, case.get("cut_file", "cut.vtp"))
    if not os.path.exists(cut_cache):
        subprocess.run([r.tool("xfem-mesh"), "-q"] + cut_cmd + ["-o", cut_cache], check=True)
    shutil.copy(cut_cache, os.path.join(cwd, "cut.vtp"))
    if ref is None:  # the reference case compares with itself (plain mesh mode of xfem-rmserror)
        ref = {"enriched": os.path.join(cwd, "enriched.vtu"), "u": os.path.join(cwd, "u.mtx")}
    cmds = stage_commands(case, r, ref)
    res = {"name": case["name"], "label": case["label"], "mesh_cmd": case["mesh_cmd"], "stages": {},
           "mesh": mesh_time, "scale": case.get("scale", False), "extra": case.get("extra", False), "cut": case["cut"]}
    for stage in case.get("stages", STAGES):
        cmd, inputs, outputs = cmds[stage]
        walls, rsss, extra = [], [], []
        n = case.get("runs", runs)
        for i in range(n):
            w, m, out, err = r.timed(cmd, cwd)
            walls.append(w)
            rsss.append(m)
            if stage == "assemble":
                t = re.search(r"time: read ([0-9.]+) s, pattern ([0-9.]+) s, plain tets ([0-9.]+) s, enriched tets "
                              r"([0-9.]+) s, loads ([0-9.]+) s, write ([0-9.]+) s", err)
                extra.append({k: float(v) for k, v in zip(["read", "pattern", "plain", "enriched", "loads", "write"],
                                                          t.groups())})
            elif stage == "solve":
                rep = json.load(open(os.path.join(cwd, "solve.json")))
                extra.append({"lib": rep["setup_seconds"] + rep["solve_seconds"]})
                res["backend"], res["processes"] = rep["backend"], rep.get("processes", 1)
                res["iterations"] = rep.get("iterations")
                # the floor of the backend xfem-solve chose, alternating with the tool's runs
                if rep["backend"] == "cholmod":
                    if i == 0:
                        pinned = os.path.join(cwd, "system_pinned")
                        subprocess.run([os.path.join(r.bench, "pin_unsupported"), "system", pinned], cwd=cwd,
                                       check=True, stdout=subprocess.DEVNULL)
                    bw, bm, bout, _ = r.timed([os.path.join(r.bench, "bare_cholmod"), "system_pinned"], cwd)
                    b = json.loads(bout.strip().splitlines()[-1])
                    extra[-1].update({"bare_wall": bw, "bare_rss": bm,
                                      "bare_lib": b["analyze_seconds"] + b["factor_seconds"] + b["solve_seconds"]})
                elif not case["cut"]:  # bare PETSc GAMG on as many ranks (the field split has no bare twin)
                    bw, bm, bout, _ = r.timed(mpirun(res["processes"]) + [os.path.join(r.bench, "bare_petsc"), "system"],
                                              cwd)
                    b = json.loads(bout.strip().splitlines()[-1])
                    extra[-1].update({"bare_wall": bw, "bare_rss": bm, "bare_lib": b["setup_seconds"] + b["solve_seconds"],
                                      "bare_iterations": b["iterations"]})
            log("%s %s run %d/%d: %.2f s, %.0f MB" % (case["name"], stage, i + 1, n, w, m))
        st = {"wall": med(walls), "rss": med(rsss), "walls": walls,
              "bytes_in": size_of(inputs, cwd), "bytes_out": size_of(outputs, cwd),
              "io_floor": io_floor(r, cwd, inputs, outputs, n)}
        for key in (extra[0].keys() if extra else []):
            st[key] = med([e[key] for e in extra])
        res["stages"][stage] = st
        if stage == "classify":
            counts = json.load(open(os.path.join(cwd, "counts.json")))
            res["points"], res["tets"] = counts["points"], counts["tets"]
            res["cut_tets"] = counts["partial"] + counts["complete"]
        elif stage == "assemble":
            sysj = json.load(open(os.path.join(cwd, "system", "system.json")))
            res["dofs"], res["nnz"] = sysj["dofs"], sysj["nonzeros"]
            bw, bm, bout, _ = r.timed([os.path.join(r.bench, "bare_assemble"), "enriched.vtu",
                                       "cut.vtp" if case["cut"] else "",
                                       case.get("problem", os.path.join(ROOT, "pipelines", "beam", "problem.json")),
                                       "0", str(n)], cwd)
            b = json.loads(bout.strip().splitlines()[-1])
            st.update({"bare_loop": b["loop_seconds"], "bare_compute": b["compute_seconds"],
                       "bare_library": b["library_seconds"], "enriched_tets": b["enriched_tets"]})
            log("%s bare_assemble: loop %.3f s, compute %.3f s, library %.3f s" %
                (case["name"], b["loop_seconds"], b["compute_seconds"], b["library_seconds"]))
        elif stage == "solve":
            res["lnz"] = json.load(open(os.path.join(cwd, "solve.json"))).get("factor_nonzeros")
    # keep what the next cases need (the reference solution), drop the bulky rest
    for f in ("deformed.vtu", "system", "system_pinned", "classified.vtu", "mesh.vtu"):
        p = os.path.join(cwd, f)
        if os.path.isdir(p):
            shutil.rmtree(p)
        elif os.path.exists(p):
            os.remove(p)
    return res, ref


# ---------------------------------------------------------------------------------------------- report
def fmt_s(x):
    return "%.3g" % x if x < 10 else "%.1f" % x


def mb(b):
    return b / 1e6


PIPELINE = ["classify", "enrich", "assemble", "solve", "visualize"]


def pipeline_table(cases):
    """Whole pipeline (default commands) per case: mesh + stages to deformed.vtu, peak memory."""
    L = ["### Whole pipeline, default commands", "",
         "From `xfem-mesh` to deformed.vtu (without PNG): the stage medians added up; mesh generation timed once, "
         "when the mesh was generated. Peak = the largest peak RSS of any stage (they run one after another). "
         "Solve floor: the bare library call of the backend xfem-solve chose, on as many processes.", "",
         "| case | backend | mesh | classify | enrich | assemble | solve | visualize | whole (w/o mesh) | peak RSS | "
         "whole / solve floor |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        st = c["stages"]
        stages = sum(st[k]["wall"] for k in PIPELINE)
        whole = stages + c["mesh"]["wall"]
        peak = max([st[k]["rss"] for k in PIPELINE] + [c["mesh"]["rss"]])
        backend = c.get("backend", "?") + (" x %d" % c["processes"] if c.get("backend") == "petsc" else "")
        if c.get("iterations"):
            backend += ", %d it." % c["iterations"]
        floor = st["solve"].get("bare_wall")
        L.append("| %s | %s | %s | %s | %s s (%s s) | %.1f GB | %s |" % (
            c["label"], backend, fmt_s(c["mesh"]["wall"]), " | ".join(fmt_s(st[k]["wall"]) for k in PIPELINE),
            fmt_s(whole), fmt_s(stages), peak / 1024.0,
            "%s / %s s = **%.2f**" % (fmt_s(whole), fmt_s(floor), whole / floor) if floor else "n/a"))
    L.append("")
    return L


def growth_rows(cases, stages):
    xs = [c["tets"] for c in cases]
    rows = []
    for s in ["mesh"] + stages:
        ys = [c["mesh"]["wall"] if s == "mesh" else c["stages"][s]["wall"] for c in cases]
        rows.append("| %s | %s | %.2f |" % (s, " | ".join(fmt_s(y) + " s" for y in ys), fit_exponent(xs, ys)))
    return rows


def report(cases, mach, runs, args):
    # the scale cases and the organ example: in the inputs, whole-pipeline, floor and I/O tables only
    scale = [c for c in cases if c.get("scale") or c.get("extra")]
    cases = [c for c in cases if not (c.get("scale") or c.get("extra"))]
    beam = [c for c in cases if c["name"] != "reference"]
    ref = [c for c in cases if c["name"] == "reference"]
    largest = max(beam, key=lambda c: c["tets"]) if beam else None
    L = []
    L.append(BEGIN)
    L.append("## Measured by `make -f Makefile.examples bench`")
    L.append("")
    L.append("Generated by bench/bench.py: everything between the `bench:begin` / `bench:end` markers is rewritten "
             "on every run, the sections after it are hand-written.")
    L.append("")
    L.append("Machine: %d cores (`nproc`), %s (/proc/cpuinfo), %.1f GB memory; load average %s at the start "
             "(the machine is shared, single runs vary)." % (mach["nproc"], mach["model"], mach["mem_gb"],
                                                             " ".join(mach["load"])))
    L.append("Each stage ran %d times, %d for the largest beam and the reference (peak RSS from GNU time, "
             "`/usr/bin/time -f '%%e %%M'`, wall time around it from Python's perf_counter as %%e has only 10 ms "
             "resolution); the tables give medians. Floors ran alternating with the tools, as often (bare_assemble: "
             "the minimum of its in-process repeats)." % (runs, args.large_runs))
    L.append("")
    L.append("### Inputs")
    L.append("")
    L.append("| case | mesh (`xfem-mesh ...`, cached in bench/out/cache) | points | tets | cut tets | "
             "enriched tets | 3N (DOFs) | nnz(K), lower | xfem-solve backend (auto) | nnz(L), CHOLMOD |")
    L.append("|---|---|---|---|---|---|---|---|---|---|")
    for c in cases + scale:
        L.append("| %s | `%s` | %d | %d | %d | %d | %d | %d | %s | %s |" % (
            c["label"], " ".join(c["mesh_cmd"]), c["points"], c["tets"], c["cut_tets"],
            c["stages"]["assemble"]["enriched_tets"], c["dofs"], c["nnz"],
            c.get("backend", "?") + (" on %d processes" % c["processes"] if c.get("backend") == "petsc" else ""),
            "%d" % c["lnz"] if c.get("lnz") else "-"))
    L.append("")
    L.extend(pipeline_table(cases + scale))
    L.append("")
    L.append("### Wall time, peak memory, throughput per stage")
    L.append("")
    L.append("| stage | " + " | ".join(c["label"] for c in cases) + " |")
    L.append("|---|" + "---|" * len(cases))
    for stage in STAGES:
        cells = []
        for c in cases:
            s = c["stages"][stage]
            cell = "%s s, %.0f MB" % (fmt_s(s["wall"]), s["rss"])
            if stage in ("classify", "assemble"):
                cell += ", %.2f M tets/s" % (c["tets"] / s["wall"] / 1e6)
            if stage == "solve":
                cell += ", %.2f M nnz/s" % (c["nnz"] / s["wall"] / 1e6)
            cells.append(cell)
        L.append("| %s | %s |" % (stage, " | ".join(cells)))
    L.append("")
    L.append("Throughput = tets (classify, assemble) or non-zeros of K's lower triangle (solve) over the whole "
             "process's wall time, file I/O included.")
    L.append("")
    L.append("### Against the floor")
    L.append("")
    L.append("Ratio = tool / floor (1.00 = at the floor). Solve: the bare library calls of the backend xfem-solve "
             "chose, on the same files: bench/bare_cholmod (analyse + factor + solve), or bench/bare_petsc under "
             "mpirun on as many ranks (MatLoad, elimination, GAMG setup + CG; uncut systems only: the field split "
             "of cut systems has no bare twin), whole process and library part. Assemble: bench/bare_assemble, "
             "the same element matrices in memory (problem.json's rule, the cut-conforming one by default), one "
             "thread; the floor is the faster of its element loop without scatter and the library's "
             "stiffness_matrix (pattern + loop + scatter, enriched tets in threads), compared with the tool's own "
             "reported assembly time (pattern + plain + enriched tets) and with its whole wall time. Every "
             "stage: `cat` of the bytes it reads and writes (I/O floor; the next table).")
    L.append("")
    L.append("| case | solve: wall tool / bare | solve: library tool / bare | assemble: reported / floor | "
             "assemble: wall / floor | assemble: wall / (floor + `cat` of its bytes) | "
             "assemble: floor (loop w/o scatter, library, plain loop with scatter) |")
    L.append("|---|---|---|---|---|---|---|")
    for c in cases + scale:
        so, a = c["stages"]["solve"], c["stages"]["assemble"]
        floor = min(a["bare_compute"], a["bare_library"])
        reported = a["pattern"] + a["plain"] + a["enriched"]
        ratio = lambda x, y: "%s / %s s = **%.2f**" % (fmt_s(x), fmt_s(y), x / y) if y else "n/a"
        L.append("| %s | %s | %s | %s / %s s = **%.2f** | %s / %s s = **%.2f** | "
                 "%s / %s s = **%.2f** | %s, %s, %s s |" % (
                     c["label"], ratio(so["wall"], so.get("bare_wall")), ratio(so["lib"], so.get("bare_lib")),
                     fmt_s(reported), fmt_s(floor), reported / floor, fmt_s(a["wall"]), fmt_s(floor), a["wall"] / floor,
                     fmt_s(a["wall"]), fmt_s(floor + a["io_floor"]), a["wall"] / (floor + a["io_floor"]),
                     fmt_s(a["bare_compute"]), fmt_s(a["bare_library"]), fmt_s(a["bare_loop"])))
    L.append("")
    L.append("xfem-assemble's own breakdown (medians, s): ")
    L.append("")
    L.append("| case | read | pattern | plain tets | enriched tets | loads | write | wall |")
    L.append("|---|---|---|---|---|---|---|---|")
    for c in cases + scale:
        a = c["stages"]["assemble"]
        L.append("| %s | %s |" % (c["label"], " | ".join(fmt_s(a[k]) for k in
                                                          ("read", "pattern", "plain", "enriched", "loads", "write", "wall"))))
    L.append("")
    L.append("### File I/O against the raw bytes")
    L.append("")
    L.append("Bytes = sizes of the files a stage reads and writes; `cat` = `cat INPUTS >/dev/null; cat OUTPUTS > copy` "
             "(page cache, the same bytes). Ratio = stage wall / cat time: the whole stage, compute included, "
             "over moving its bytes.")
    L.append("")
    L.append("| case | stage | read MB | written MB | wall s | cat s | stage MB/s | cat MB/s | wall / cat |")
    L.append("|---|---|---|---|---|---|---|---|---|")
    for c in cases + scale:
        for stage in STAGES:
            if stage not in c["stages"]:
                continue
            s = c["stages"][stage]
            tot = mb(s["bytes_in"] + s["bytes_out"])
            L.append("| %s | %s | %.1f | %.1f | %s | %s | %.0f | %.0f | %.1f |" % (
                c["label"], stage, mb(s["bytes_in"]), mb(s["bytes_out"]), fmt_s(s["wall"]), fmt_s(s["io_floor"]),
                tot / s["wall"], tot / max(s["io_floor"], 1e-3), s["wall"] / max(s["io_floor"], 1e-3)))
    L.append("")
    if len(beam) >= 2:
        L.append("### Growth with size (unstructured beam)")
        L.append("")
        L.append("Exponent p of wall ~ tets^p, least squares over the %d sizes (1 = linear)." % len(beam))
        L.append("")
        L.append("| stage | " + " | ".join("%s (%d tets)" % (c["label"], c["tets"]) for c in beam) + " | p |")
        L.append("|---|" + "---|" * (len(beam) + 1))
        xs = [c["tets"] for c in beam]
        rows = [(s, [c["stages"][s]["wall"] for c in beam]) for s in STAGES]
        rows.append(("solve, library part", [c["stages"]["solve"]["lib"] for c in beam]))
        if all(c["stages"]["solve"].get("bare_lib") and c.get("backend") == "cholmod" for c in beam):
            rows.append(("bare CHOLMOD, library part", [c["stages"]["solve"]["bare_lib"] for c in beam]))
        rows.append(("assemble, reported", [sum(c["stages"]["assemble"][k] for k in ("pattern", "plain", "enriched"))
                                            for c in beam]))
        for name, ys in rows:
            L.append("| %s | %s | %.2f |" % (name, " | ".join(fmt_s(y) + " s" for y in ys), fit_exponent(xs, ys)))
        L.append("")
    if largest:
        L.append("### Largest case (%s, %d tets): each stage against its floor" % (largest["label"], largest["tets"]))
        L.append("")
        L.append("| stage | floor | ratio | within 2x |")
        L.append("|---|---|---|---|")
        st = largest["stages"]
        a = st["assemble"]
        afloor = min(a["bare_compute"], a["bare_library"])
        rows = []
        if st["solve"].get("bare_wall"):
            rows += [("solve", "bare library, whole process", st["solve"]["wall"] / st["solve"]["bare_wall"]),
                     ("solve (library part)", "bare library calls", st["solve"]["lib"] / st["solve"]["bare_lib"])]
        rows += [("assemble", "bare element loop in memory, vs the tool's whole wall time", a["wall"] / afloor),
                ("assemble", "bare element loop in memory + `cat` of its bytes", a["wall"] / (afloor + a["io_floor"]))]
        for s in ("classify", "enrich", "visualize", "rmserror"):
            rows.append((s, "`cat` of its bytes", st[s]["wall"] / max(st[s]["io_floor"], 1e-3)))
        for s, f, q in rows:
            L.append("| %s | %s | %.2f | %s |" % (s, f, q, "yes" if q <= 2 else "no (see \"Why not at the floor\")"))
        L.append("")
    for kind in ("reference", "beam"):
        pair = ([c for c in cases + scale if c["name"] in ("reference", "reference-1M")] if kind == "reference" else
                [c for c in cases + scale if c is largest or c["name"] == "beam-1M"])
        if len(pair) == 2 and any(c.get("scale") for c in pair):
            L.append("### Growth to the scale case (%s)" % " -> ".join(c["label"] for c in pair))
            L.append("")
            L.append("Exponent p of wall ~ tets^p between the two sizes (1 = linear).")
            L.append("")
            L.append("| stage | " + " | ".join("%s (%d tets)" % (c["label"], c["tets"]) for c in pair) + " | p |")
            L.append("|---|---|---|---|")
            L.extend(growth_rows(pair, PIPELINE))
            L.append("")
    L.append("### Commands")
    L.append("")
    L.append("```")
    L.append("make -f Makefile.examples bench BENCH_ARGS=\"%s\"   # this run: %d run(s) per stage, %d for the largest beam "
             "and the reference" % (" ".join(a for a in sys.argv[1:] if a not in ("--build", "build", "--from-results")
                                             and not a.startswith("/")), runs, args.large_runs))
    L.append("# per case, in bench/out/<case>/ (P = pipelines/beam/problem.json; the reference case has no --cut):")
    L.append("xfem-classify -q mesh.vtu --cut cut.vtp -o classified.vtu --summary counts.json")
    L.append("xfem-enrich -q classified.vtu -o enriched.vtu")
    L.append("xfem-assemble enriched.vtu --cut cut.vtp --problem P -o system")
    L.append("xfem-solve -q system -o u.mtx --report solve.json")
    L.append("xfem-visualize -q enriched.vtu --cut cut.vtp --solution u.mtx --problem P -o deformed.vtu --faces wound.vtp")
    L.append("xfem-rmserror -q enriched.vtu --cut cut.vtp --solution u.mtx --reference ../reference/enriched.vtu \\")
    L.append("    --reference-solution ../reference/u.mtx -o rms.json   # the reference against itself for its own row")
    L.append("bare_assemble enriched.vtu cut.vtp P 0 RUNS                   # floor of xfem-assemble")
    L.append("pin_unsupported system system_pinned && bare_cholmod system_pinned   # floor of xfem-solve (CHOLMOD)")
    L.append("mpirun -np P bare_petsc system                                    # floor of xfem-solve (PETSc, uncut)")
    L.append("# the organ cases: the same stages with pipelines/organ/problem.json and `xfem-mesh cut-sine`, no rmserror")
    L.append("# --scale adds, one run each, no rmserror: the 1.14M-DOF reference and the ~1M-tet cut beam")
    L.append("# --quick: one run per stage and floor instead of %d / %d" % (5, 3))
    L.append("```")
    L.append(END)
    return "\n".join(L)


def write_doc(path, block):
    text = open(path).read() if os.path.exists(path) else "# Performance\n\n"
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        text = head + block + tail
    else:  # first run: after the title
        lines = text.split("\n", 1)
        text = lines[0] + "\n\n" + block + "\n" + (lines[1] if len(lines) > 1 else "")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--runs", type=int, default=5, help="runs per stage and floor (median)")
    ap.add_argument("--large-runs", type=int, default=3, help="runs for the largest beam and the reference")
    ap.add_argument("--sizes", nargs=3, default=["0.007", "0.0034", "0.002"],
                    help="target edge lengths H of the three unstructured beams (m)")
    ap.add_argument("--scale", action="store_true",
                    help="also the scale cases, one run each: the 1.14M-DOF reference (box 30 60 200) and the cut "
                         "beam of about 1M tets (H 0.0016)")
    ap.add_argument("--scale-size", default="0.0016", help="H of the scale beam (m)")
    ap.add_argument("--only-scale", action="store_true", help="run only the scale cases (quick look; not for the doc)")
    ap.add_argument("--quick", action="store_true", help="one run per stage and floor (--runs 1 --large-runs 1): "
                    "single runs, for a shared machine")
    ap.add_argument("--no-write", action="store_true", help="print the tables instead of writing docs/PERFORMANCE.md")
    ap.add_argument("--from-results", action="store_true", help="no runs: the tables from bench/out/results.json "
                    "of the last run (with the same --runs / --quick)")
    args = ap.parse_args()
    if args.quick:
        args.runs, args.large_runs = 1, 1
    build = os.path.abspath(args.build)
    for exe in ("tools/xfem-classify", "bench/bare_cholmod", "bench/bare_petsc", "bench/bare_assemble",
                "bench/pin_unsupported"):
        if not os.access(os.path.join(build, exe), os.X_OK):
            raise SystemExit("bench: %s missing: build first (make -f Makefile.examples build)" % os.path.join(build, exe))
    work = os.path.join(ROOT, "bench", "out")
    cache = os.path.join(work, "cache")
    os.makedirs(cache, exist_ok=True)
    r = Runner(build, work)
    mach = machine()
    start = time.time()
    cases = [{"name": "reference", "label": "reference 256k DOFs", "cut": False, "runs": args.large_runs,
              "mesh_file": "reference.vtu",
              "mesh_cmd": ["box", "--cells", "18", "36", "120", "--hi"] + BEAM_HI + ["--beam-cut"]}]
    for label, h in zip(("S", "M", "L"), args.sizes):
        cases.append({"name": "beam-" + label, "label": "beam %s (H %s)" % (label, h), "cut": True,
                      "mesh_file": "beam-%s.vtu" % h,
                      "mesh_cmd": ["unstructured-box", "--hi"] + BEAM_HI + ["--size", h]})
    cases[-1]["runs"] = args.large_runs
    scale_stages = ["classify", "enrich", "assemble", "solve", "visualize"]
    # The organ example (pipelines/organ, without its PNG) at its default size, and at the ~900 tets
    # of the issue's first measurement: small pipelines where the tools' start-up counts.
    for label, h in (("organ S", "0.022"), ("organ", "0.006")):
        cases.append({"name": label.replace(" ", "-"), "label": "%s (H %s)" % (label, h), "cut": True, "extra": True,
                      "mesh_file": "organ-%s.vtu" % h, "stages": scale_stages, "cut_file": "cut-sine.vtp",
                      "cut_cmd": ["cut-sine"], "problem": os.path.join(ROOT, "pipelines", "organ", "problem.json"),
                      "mesh_cmd": ["organ", "--size", h]})
    if args.scale or args.only_scale:
        cases.append({"name": "reference-1M", "label": "reference 1.14M DOFs", "cut": False, "runs": 1, "scale": True,
                      "mesh_file": "reference-1M.vtu", "stages": scale_stages,
                      "mesh_cmd": ["box", "--cells", "30", "60", "200", "--hi"] + BEAM_HI + ["--beam-cut"]})
        cases.append({"name": "beam-1M", "label": "beam 1M (H %s)" % args.scale_size, "cut": True, "runs": 1,
                      "scale": True, "mesh_file": "beam-%s.vtu" % args.scale_size, "stages": scale_stages,
                      "mesh_cmd": ["unstructured-box", "--hi"] + BEAM_HI + ["--size", args.scale_size]})
    if args.only_scale:
        cases = [c for c in cases if c.get("scale")]
    results, ref = [], None
    if args.from_results:  # the tables again from a finished run's measurements
        saved = json.load(open(os.path.join(work, "results.json")))
        mach, results = saved["machine"], saved["cases"]
        cases = []
    for case in cases:
        log("case %s" % case["name"])
        res, got = run_case(r, case, args.runs, cache, ref)
        if case["name"] == "reference":
            ref = got
        results.append(res)
        with open(os.path.join(work, "results.json"), "w") as f:  # after every case: nothing measured is lost
            json.dump({"machine": mach, "cases": results}, f, indent=1)
    block = report(results, mach, args.runs, args)
    log("done in %.0f s" % (time.time() - start))
    if args.no_write:
        print(block)
    else:
        write_doc(os.path.join(ROOT, "docs", "PERFORMANCE.md"), block)
        log("wrote docs/PERFORMANCE.md")


if __name__ == "__main__":
    main()
