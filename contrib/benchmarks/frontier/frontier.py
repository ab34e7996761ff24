"""Best objective against CPU time: uniform refinement against mesh adaptation.

For each case (a settlement example of prm/examples with Mohr-Coulomb joints)
this runs

  * uniform meshes 3x4, 6x8, 12x16, 24x32 blocks per half (each run stopped
    after --uniform-limit CPU seconds), and
  * adaptation: every optimiser x `lines'/`vertices' genes x start meshes
    3x4 and 6x8 per half, one thread, `Stall generations = 0', stopped after
    a CPU budget (--budget times the CPU time of uniform 12x16, at least
    --min-budget s; RLIMIT_CPU ends the run);
  * crack refinement (`Optimiser = crack refinement'): the settings of
    CRACK (start mesh, stages, marked fraction, marking, split: `lines'
    splits whole strips, `blocks' only the blocks next to cracks, reported
    as `local refinement'), each run to its end (stopped at
    --uniform-limit CPU s; --crack-runs selects by split).

--strategies selects what runs: `all' (default), or a comma-separated
subset of `uniform', `optimisers', `crack'.

The time axis is the CPU time (user + sys) of the masonry process, start-up
included: the machine this runs on is usually shared, so wall times are
inflated by other jobs while CPU times are not. An adaptation run's frontier
is its best fitness (the LP optimum of the best mesh so far, J) after every
generation against the CPU time the process had used when it printed that
generation; the analysis of the best mesh at the end of a finished run (one
more LP and the output) is not included.

Writes results.csv (every point), results.md (the table) and frontier.png
into the output directory (default build/benchmarks/frontier)."""
import argparse
import csv
import json
import math
import os
import re
import resource
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
CASES = {
    "bothwell": ("bothwell-vertical-settlement.prm",
                 "Bothwell vault, vertical settlement"),
    "corner": ("barrel-vault-corner-settlement.prm",
               "barrel vault, one corner settles"),
}
OPTIMISERS = ["genetic", "differential evolution", "cmaes", "particle swarm"]
GENERATION = re.compile(r"^\s*generation (\d+): best (\S+), mean \S+, (\d+) evaluations")
STAGE = re.compile(r"^\s*stage (\d+): (\d+) blocks .*, best (\S+),")
# crack refinement: (start mesh, stages, marked fraction, marking, split);
# `lines' splits whole strips, `blocks' only the blocks next to cracks
# (local refinement; `marking' is not used)
CRACK = [((3, 4), 3, 0.5, "per direction", "lines"),
         ((3, 4), 3, 0.6, "per direction", "lines"),
         ((3, 4), 4, 0.5, "per direction", "lines"),
         ((3, 4), 3, 0.7, "per direction", "lines"),
         ((6, 8), 1, 0.5, "per direction", "lines"),
         ((6, 8), 1, 0.6, "per direction", "lines"),
         ((3, 4), 3, 0.6, "joint", "lines"),
         ((3, 4), 3, 0.7, "joint", "blocks"),
         ((3, 4), 4, 0.5, "joint", "blocks"),
         ((3, 4), 4, 0.7, "joint", "blocks"),
         ((3, 4), 4, 0.9, "joint", "blocks"),
         ((6, 8), 1, 0.5, "joint", "blocks"),
         ((6, 8), 1, 0.7, "joint", "blocks"),
         ((6, 8), 2, 0.5, "joint", "blocks"),
         ((6, 8), 2, 0.7, "joint", "blocks")]
TICK = os.sysconf("SC_CLK_TCK")


def write_prm(case, nu, nv, out, optimiser="none", genes="lines", crack=None):
    """The example with nu x nv blocks per half, no picture, only the crack
    list as output, and the adaptation settings."""
    text = open(os.path.join(ROOT, "prm", "examples", CASES[case][0])).read()
    text = re.sub(r"(?m)^(\s*set Blocks along u\s*=).*$", r"\g<1> %d" % nu, text)
    text = re.sub(r"(?m)^(\s*set Blocks along v\s*=).*$", r"\g<1> %d" % nv, text)
    text += f"""
set Output directory = {out}
subsection Settlement
  set Write picture = false
end
subsection Postprocess
  subsection Rigid blocks
    set List of postprocessors = cracks
  end
end
subsection Adaptation
  set Optimiser         = {optimiser}
  set Mesh genes        = {genes}
  set Population size   = 16
  set Generations       = 100000
  set Stall generations = 0
  set Seed              = 1
  set Threads           = 1
""" + ("" if crack is None else f"""  subsection Crack refinement
    set Stages          = {crack[0]}
    set Marked fraction = {crack[1]}
    set Marking         = {crack[2]}
    set Split           = {crack[3]}
  end
""") + """end
"""
    os.makedirs(out, exist_ok=True)
    path = out.rstrip("/") + ".prm"
    open(path, "w").write(text)
    return path


def cpu_of(pid):
    """CPU seconds (user + sys, all threads) a running process has used."""
    try:
        fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / TICK
    except (OSError, IndexError, ValueError):
        return math.nan


def run(masonry, prm, limit):
    """Runs masonry on prm with a CPU limit of `limit' s. Returns (points,
    cpu, wall, finished, log): points = [(cpu, generation, evaluations,
    best)] from the generation lines, cpu the process's total CPU time."""
    def limits():
        soft = max(1, math.ceil(limit))
        resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 2))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    p = subprocess.Popen([masonry, prm], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, env=env,
                         preexec_fn=limits, text=True)
    points, log = [], []
    for line in p.stdout:
        log.append(line)
        m = GENERATION.match(line)
        if m:
            points.append((cpu_of(p.pid), int(m.group(1)), int(m.group(3)),
                           float(m.group(2))))
        m = STAGE.match(line)
        if m:
            points.append((cpu_of(p.pid), int(m.group(1)), int(m.group(2)),
                           float(m.group(3))))
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    cpu = usage.ru_utime + usage.ru_stime
    return points, cpu, time.time() - start, p.returncode == 0, "".join(log)


def objective(out):
    """The LP optimum of a finished run (summary.json)."""
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["objective"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "benchmarks",
                                                  "frontier"))
    ap.add_argument("--masonry", default=os.path.join(ROOT, "build", "masonry"))
    ap.add_argument("--quick", action="store_true",
                    help="smoke check: uniform 3x4 and 6x8, the genetic "
                    "algorithm with line genes from 3x4 for 3 CPU s")
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--uniform-limit", type=float, default=600,
                    help="CPU seconds after which a uniform run is stopped")
    ap.add_argument("--finest", default="24x32",
                    help="finest uniform mesh per half (3x4, 6x8, 12x16 or 24x32)")
    ap.add_argument("--budget", type=float, default=1.0,
                    help="adaptation budget, times the CPU s of uniform 12x16")
    ap.add_argument("--min-budget", type=float, default=5.0)
    ap.add_argument("--optimiser-runs", default="",
                    help="only these optimiser runs, e.g. "
                    "'genetic:lines:3x4,cmaes:vertices:3x4' (default: every "
                    "optimiser x lines/vertices x 3x4/6x8)")
    ap.add_argument("--crack-runs", default="",
                    help="only the crack refinements that split these "
                    "(comma-separated: lines, blocks; default: both)")
    ap.add_argument("--strategies", default="all",
                    help="all, or a comma-separated subset of uniform, "
                    "optimisers, crack")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    uniform_meshes = [(3, 4), (6, 8), (12, 16), (24, 32)]
    finest = tuple(int(x) for x in args.finest.split("x"))
    uniform_meshes = uniform_meshes[:uniform_meshes.index(finest) + 1]
    if args.quick:
        uniform_meshes = [(3, 4), (6, 8)]
    strategies = (["uniform", "optimisers", "crack"] if args.strategies == "all"
                  else args.strategies.split(","))
    rows = []  # case, strategy, start, genes, cpu, wall, generation, evaluations, best, final
    for case in args.cases.split(","):
        uniform = {}
        for nu, nv in uniform_meshes:
            name = f"{case}_uniform_{nu}x{nv}"
            prm = write_prm(case, nu, nv, os.path.join(args.out, name))
            _, cpu, wall, ok, log = run(args.masonry, prm, args.uniform_limit)
            value = objective(os.path.join(args.out, name)) if ok else math.nan
            uniform[(nu, nv)] = (value, cpu, ok)
            rows.append([case, "uniform", f"{nu}x{nv}", "", f"{cpu:.3f}",
                         f"{wall:.2f}", "", 1, f"{value:.10g}",
                         "done" if ok else "stopped"])
            print(f"{name}: {value:.6g} J, {cpu:.2f} CPU s, {wall:.1f} s wall"
                  f"{'' if ok else ' (stopped at the CPU limit)'}", flush=True)
            if not ok:
                break
        reference = uniform.get((12, 16), uniform[max(uniform)])
        budget = 3.0 if args.quick else max(args.min_budget,
                                            args.budget * reference[1])
        runs = [("genetic", "lines", (3, 4))] if args.quick else [
            (o, g, s) for s in [(3, 4), (6, 8)] for g in ["lines", "vertices"]
            for o in OPTIMISERS]
        if args.optimiser_runs:
            runs = [(o, g, tuple(int(x) for x in m.split("x")))
                    for o, g, m in (r.split(":") for r in
                                    args.optimiser_runs.split(","))]
        if "optimisers" not in strategies:
            runs = []
        for optimiser, genes, (nu, nv) in runs:
            name = f"{case}_{optimiser.replace(' ', '_')}_{genes}_{nu}x{nv}"
            prm = write_prm(case, nu, nv, os.path.join(args.out, name),
                            optimiser, genes)
            points, cpu, wall, ok, log = run(args.masonry, prm, budget)
            for c, g, e, best in points:
                rows.append([case, optimiser, f"{nu}x{nv}", genes, f"{c:.3f}",
                             "", g, e, f"{best:.10g}", "generation"])
            last = points[-1] if points else (cpu, -1, 0, math.nan)
            rows.append([case, optimiser, f"{nu}x{nv}", genes, f"{cpu:.3f}",
                         f"{wall:.2f}", last[1], last[2], f"{last[3]:.10g}",
                         "done" if ok else "stopped"])
            print(f"{name}: best {last[3]:.6g} J after {last[2]} evaluations, "
                  f"{cpu:.2f} CPU s", flush=True)
        crack = ([((3, 4), 2, 0.6, "joint", "lines"),
                  ((3, 4), 2, 0.6, "joint", "blocks")] if args.quick
                 else CRACK)
        if args.crack_runs:
            crack = [c for c in crack if c[4] in args.crack_runs.split(",")]
        for (nu, nv), stages, fraction, marking, split in (
                crack if "crack" in strategies else []):
            strategy = ("local refinement" if split == "blocks"
                        else "crack refinement")
            label = (f"S{stages} f{fraction}"
                     + ("" if split == "blocks" else f" {marking}"))
            name = (f"{case}_crack_{nu}x{nv}_{stages}_{fraction}_"
                    f"{marking.replace(' ', '_')}_{split}")
            out = os.path.join(args.out, name)
            prm = write_prm(case, nu, nv, out, "crack refinement",
                            crack=(stages, fraction, marking, split))
            points, cpu, wall, ok, log = run(args.masonry, prm,
                                             args.uniform_limit)
            value = objective(out) if ok else math.nan
            blocks = json.load(open(os.path.join(out, "summary.json")))[
                "n_blocks"] if ok else 0
            for c, g, b, best in points:
                rows.append([case, strategy, f"{nu}x{nv}", label,
                             f"{c:.3f}", "", g, b, f"{best:.10g}",
                             "generation"])
            rows.append([case, strategy, f"{nu}x{nv}", label,
                         f"{cpu:.3f}", f"{wall:.2f}", len(points), blocks,
                         f"{value:.10g}", "done" if ok else "stopped"])
            if ok:
                rows.append([case, strategy, f"{nu}x{nv}", label,
                             f"{cpu:.3f}", "", len(points), blocks,
                             f"{value:.10g}", "generation"])
            print(f"{name}: {value:.6g} J with {blocks} blocks, {cpu:.2f} CPU s, "
                  f"{wall:.1f} s wall", flush=True)
    with open(os.path.join(args.out, "results.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "strategy", "start_mesh", "genes", "cpu_seconds",
                    "wall_seconds", "generation", "evaluations", "objective_J",
                    "kind"])
        w.writerows(rows)
    report(args.out, rows)


def report(out, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    cases = list(dict.fromkeys(r[0] for r in rows))
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 4.6),
                             squeeze=False)
    md = ["| case | strategy | start mesh | genes / settings | evaluations "
          "(crack: final blocks) | best objective (J) | CPU s | wall s "
          "| CPU s to uniform 6x8 | CPU s to uniform 12x16 "
          "| ÷ uniform 12x16's CPU s |",
          "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for ax, case in zip(axes[0], cases):
        uni = [r for r in rows if r[0] == case and r[1] == "uniform"]
        done = {r[2]: (float(r[8]), float(r[4])) for r in uni if r[9] == "done"}
        for r in uni:
            md.append(f"| {case} | uniform | {r[2]} | | 1 | "
                      + (f"{float(r[8]):.6g}" if r[9] == "done" else "not finished")
                      + f" | {float(r[4]):.2f} | {float(r[5]):.2f} | | | |")
        xs = [done[m][1] for m in done]
        ax.plot(xs, [done[m][0] for m in done], "ko-", lw=2, label="uniform", zorder=5)
        for m in done:
            ax.annotate(m, (done[m][1], done[m][0]), textcoords="offset points",
                        xytext=(4, -10), fontsize=8)
        strategies = list(dict.fromkeys((r[1], r[2], r[3]) for r in rows
                                        if r[0] == case and r[1] != "uniform"))
        for s in strategies:
            pts = [r for r in rows if r[0] == case and (r[1], r[2], r[3]) == s]
            gens = [r for r in pts if r[9] == "generation"]
            end = [r for r in pts if r[9] != "generation"][-1]
            def first_reaching(target):
                for r in gens:
                    if float(r[8]) >= target * (1 - 1e-9) - 1e-9:
                        return f"{float(r[4]):.2f}"
                return "not reached"
            t6 = first_reaching(done["6x8"][0]) if "6x8" in done else ""
            t12 = first_reaching(done["12x16"][0]) if "12x16" in done else ""
            wall = f"{float(end[5]):.2f}" if end[5] else ""
            ratio = (f"{float(t12) / done['12x16'][1]:.2f}"
                     if t12 not in ("", "not reached") else "")
            md.append(f"| {case} | {s[0]} | {s[1]} | {s[2]} | {end[7]} | "
                      f"{float(end[8]):.6g} | {float(end[4]):.2f} | {wall} "
                      f"| {t6} | {t12} | {ratio} |")
            if gens:
                x = [float(r[4]) for r in gens] + [float(end[4])]
                y = [float(r[8]) for r in gens] + [float(gens[-1][8])]
                if s[0] in OPTIMISERS:
                    ax.step(x, y, "-" if s[2] == "lines" else ":",
                            where="post", color="C%d" % OPTIMISERS.index(s[0]),
                            lw=1 if s[1] == "3x4" else 2.5,
                            label=f"{s[0]}, {s[2]}, from {s[1]}")
                else:
                    crack = [t for t in strategies if t[0] not in OPTIMISERS]
                    ax.step(x[:-1], y[:-1],
                            "--" if s[0] == "local refinement" else "-",
                            where="post", marker="s",
                            ms=3, color="C%d" % (4 + crack.index(s) % 6),
                            lw=1.5, label=f"{s[0]}, {s[2]}, from {s[1]}")
        if "12x16" in done:
            t12, f12 = done["12x16"][1], done["12x16"][0]
            ax.axvline(t12 / 5, color="r", lw=0.8, ls=":")
            ax.axhline(f12, color="r", lw=0.8, ls=":")
            ax.annotate("target: uniform 12x16 objective\nin 1/5 of its CPU time",
                        (t12 / 5, f12), textcoords="offset points",
                        xytext=(4, 4), fontsize=7, color="r")
        ax.set_xscale("log")
        ax.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("CPU time of the run, user + sys [s]")
        ax.set_ylabel("best objective: work of the loads - dissipation [J]")
        ax.set_title(CASES[case][1], fontsize=10)
        ax.grid(True, which="both", lw=0.3)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=7)
    fig.tight_layout(rect=(0, 0.2, 1, 1))
    fig.savefig(os.path.join(out, "frontier.png"), dpi=80)
    open(os.path.join(out, "results.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--report-only":
        report(sys.argv[2], list(csv.reader(open(os.path.join(sys.argv[2], "results.csv"))))[1:])
    else:
        main()
