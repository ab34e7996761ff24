#!/usr/bin/python3
"""Cyclic wallette benchmark (called by ./run, which documents the options)."""
import argparse
import json
import os
import re
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(os.path.dirname(here)))
sys.path.insert(0, os.path.join(root, "contrib", "study"))
from study import set_entry  # noqa: E402
from report import envelope_fit, read_csv  # noqa: E402
sys.path.insert(0, os.path.dirname(here))
from wallette_common import (cells, cpu_seconds, read_rows,  # noqa: E402
                             write_rows)

THICKNESSES = ("single", "double", "triple")
# the examples' mesh criterion (doc/brickwork.md, Validation): the peak
# within 4 % of the next finer mesh
TARGET_CHANGE = 0.04
EXAMPLE_MESH = "4x2x2"


def run_case(thickness, mesh, half_step, ranks, directory):
    n_l, n_w, n_h = mesh.split("x")
    name = f"{thickness}-{mesh}" + ("-halfstep" if half_step else "")
    source = os.path.join(root, "prm", "examples",
                          f"wallette-{thickness}-cyclic.prm")
    text = open(source).read()
    out = os.path.join(directory, name)
    text = set_entry(text, "Output directory", out, "top")
    text = set_entry(text, "Elements along the length", n_l, "wallette")
    text = set_entry(text, "Elements along the width", n_w, "wallette")
    text = set_entry(text, "Elements along the height", n_h, "wallette")
    text = set_entry(text, "Random seed", "1", "wallette")
    # no VTU files (they change no number); the checkpoints stay as the
    # example sets them: a checkpoint lets the kept factorisation go, so
    # without them the chord corrections would take another path
    text = set_entry(text, "Write VTU", "false", "wallette")
    if half_step:
        m = re.search(r"^\s*set\s+Number of steps\s*=\s*(\d+)", text, re.M)
        text = set_entry(text, "Number of steps", str(2 * int(m.group(1))),
                         "wallette")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(f"# benchmark case {name}, from {os.path.relpath(source, root)}"
                "\n" + text)
    cmd = [os.path.join(root, "build", "masonry"), prm]
    if ranks > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
               str(ranks)] + cmd
    log = os.path.join(directory, name + ".log")
    print(f"benchmark: {name} on {ranks} rank(s) ...", flush=True)
    t0 = time.time()
    c0 = cpu_seconds()
    with open(log, "w") as f:
        code = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT,
                               cwd=directory)
    wall = time.time() - t0
    cpu = cpu_seconds() - c0
    try:
        s = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError):
        s = {"status": "no summary.json"}
    row = {"thickness": thickness, "mesh": mesh,
           "step": "half" if half_step else "example", "ranks": ranks,
           "status": s.get("status", "?"), "exit_code": code,
           "wall_seconds": round(wall, 2), "cpu_seconds": round(cpu, 2)}
    for key in ("n_cells", "n_dofs", "steps", "newton_iterations",
                "factorisations", "cut_backs", "deleted_cells",
                "seconds_assembly", "seconds_solve", "peak_stress",
                "strain_at_peak", "initial_modulus"):
        if key in s:
            row[key] = s[key]
    row.update(envelope(out))
    if "steps" in row and row["steps"]:
        row["newton_per_step"] = row["newton_iterations"] / row["steps"]
    if code != 0 or row["status"] != "completed":
        print(f"benchmark: {name} FAILED (exit code {code}, status "
              f"{row['status']}); log: {log}", file=sys.stderr, flush=True)
    else:
        print(f"benchmark: {name}: {wall:.0f} s, {row['steps']} steps, "
              f"{row['newton_per_step']:.2f} Newton iterations per step, peak "
              f"{row['peak_stress'] / 1e6:.3f} MPa", flush=True)
    return row


def envelope(out):
    """The envelope RMS before and after the peak (the study's measure,
    contrib/study/report.py) and the last cycle's peak (Pa) of the run in
    @p out (what of them there is)."""
    row = {}
    curve = read_csv(os.path.join(out, "curve.csv"))
    cycles = read_csv(os.path.join(out, "cycles.csv"))
    if not curve:
        return row
    fit = envelope_fit([{"name": "run", "curve": curve}]).get("run")
    if fit:
        for key, value in zip(("rms_before_peak", "rms_after_peak"), fit):
            if value is not None:
                row[key] = round(value, 4)
    if cycles:
        row["last_cycle_peak"] = cycles[-1]["peak_stress_Pa"]
    return row


KEYS = ["thickness", "mesh", "step", "ranks", "n_cells", "n_dofs", "steps",
        "newton_iterations", "newton_per_step", "factorisations", "cut_backs",
        "deleted_cells", "seconds_assembly", "seconds_solve", "wall_seconds",
        "cpu_seconds", "peak_stress", "strain_at_peak", "initial_modulus",
        "rms_before_peak", "rms_after_peak", "last_cycle_peak",
        "change_to_finer", "status", "exit_code"]



def add_changes(rows):
    """Relative change of the peak to the next finer mesh (same thickness,
    example step), and of the half-step run to the example step."""
    for t in THICKNESSES:
        mesh_rows = sorted([r for r in rows if r["thickness"] == t and
                            r["step"] == "example" and "peak_stress" in r],
                           key=lambda r: cells(r["mesh"]))
        for a, b in zip(mesh_rows, mesh_rows[1:]):
            a["change_to_finer"] = abs(a["peak_stress"] - b["peak_stress"]) / \
                b["peak_stress"]
        for r in rows:
            if r["thickness"] == t and r["step"] == "half" and \
                    "peak_stress" in r:
                ref = next((m for m in mesh_rows if m["mesh"] == r["mesh"]),
                           None)
                if ref:
                    r["change_to_finer"] = abs(ref["peak_stress"] -
                                               r["peak_stress"]) / \
                        r["peak_stress"]


def report(directory, rows):
    write_rows(os.path.join(directory, "results.csv"), KEYS, rows)
    lines = [
        "| thickness | mesh | step | cells | DOFs | steps | factorisations | "
        "deleted | wall s | CPU s | peak MPa | strain at peak | change to "
        "finer | RMS before / after the peak | last cycle's peak MPa | "
        "status |",
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
        "---:|---|"]

    def f(r, key, fmt):
        return fmt.format(r[key]) if key in r else ""
    for r in rows:
        change = f"{100 * r['change_to_finer']:.2f} %" \
            if "change_to_finer" in r else ""
        step = "example" if r["step"] == "example" else "half"
        rms = (f"{r['rms_before_peak']:.3f} / {r['rms_after_peak']:.3f}"
               if "rms_before_peak" in r and "rms_after_peak" in r else "")
        lines.append(
            f"| {r['thickness']} | {r['mesh']} | {step} | {f(r, 'n_cells', '{}')} | "
            f"{f(r, 'n_dofs', '{}')} | {f(r, 'steps', '{}')} | "
            f"{f(r, 'factorisations', '{}')} | "
            f"{f(r, 'deleted_cells', '{}')} | {r['wall_seconds']:.0f} | "
            f"{f(r, 'cpu_seconds', '{:.0f}')} | "
            + (f"{r['peak_stress'] / 1e6:.3f}" if 'peak_stress' in r else "")
            + f" | {f(r, 'strain_at_peak', '{:.5f}')} | {change} | {rms} | "
            + (f"{r['last_cycle_peak'] / 1e6:.2f}"
               if 'last_cycle_peak' in r else "")
            + f" | {r['status']} |")
    verdict = []
    for t in THICKNESSES:
        good = [r for r in rows if r["thickness"] == t and
                r["step"] == "example" and r.get("change_to_finer") is not None
                and r["change_to_finer"] <= TARGET_CHANGE]
        if not [r for r in rows if r["thickness"] == t]:
            continue
        if not good:
            verdict.append(f"- {t}: no mesh has its peak within "
                           f"{100 * TARGET_CHANGE:.0f} % of the next finer "
                           "one (or the finer run is missing).")
            continue
        r = min(good, key=lambda r: r["cpu_seconds"])
        verdict.append(
            f"- {t}: coarsest adequate mesh {r['mesh']} "
            f"(change {100 * r['change_to_finer']:.2f} %), "
            f"{r['cpu_seconds']:.0f} CPU s on {r['ranks']} rank(s).")
    text = "\n".join(lines) + "\n\n" + "\n".join(verdict) + "\n"
    with open(os.path.join(directory, "results.md"), "w") as fmd:
        fmd.write(text)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for t, mk in zip(THICKNESSES, "os^"):
        pts = [r for r in rows if r["thickness"] == t and
               r["step"] == "example" and "change_to_finer" in r]
        if not pts:
            continue
        ax.loglog([r["cpu_seconds"] for r in pts],
                  [max(100 * r["change_to_finer"], 1e-3) for r in pts],
                  mk + "-", label=t)
        for r in pts:
            ax.annotate(r["mesh"], (r["cpu_seconds"],
                                    max(100 * r["change_to_finer"], 1e-3)),
                        textcoords="offset points", xytext=(4, 4),
                        fontsize=8)
    ax.axhline(100 * TARGET_CHANGE, color="grey", ls="--", lw=0.8)
    ax.set_xlabel("CPU time [s]")
    ax.set_ylabel("change of peak stress to the next finer mesh [%]")
    ax.set_title("Cyclic wallettes: run time against mesh error\n"
                 f"(labels: cells per unit + joint; line: "
                 f"{100 * TARGET_CHANGE:.0f} %)",
                 fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "time_vs_change.png"), dpi=120)
    print(text)
    print(f"benchmark: wrote results.csv, results.md, time_vs_change.png in "
          f"{directory}/")


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--thickness", default=",".join(THICKNESSES))
    p.add_argument("--meshes", default="2x1x1,4x2x2,6x3x3")
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--output", default=os.path.join(
        root, "build", "benchmarks", "wallette_cyclic"))
    p.add_argument("--no-half-step", action="store_true")
    p.add_argument("--fresh", action="store_true",
                   help="forget the rows of earlier runs in the directory")
    p.add_argument("--report-only", action="store_true")
    p.add_argument("--no-setup", action="store_true")
    args = p.parse_args()
    directory = os.path.abspath(args.output)
    os.makedirs(directory, exist_ok=True)
    # the rows of earlier runs into this directory: a case run again
    # replaces its row, so the table can be built up thickness by thickness
    old = os.path.join(directory, "results.csv")
    rows = [] if args.fresh else read_rows(old)
    if not rows and args.report_only:
        raise SystemExit(f"benchmark: error: no {old} to report on")

    def put(row):
        key = (row["thickness"], row["mesh"], row["step"])
        rows[:] = [r for r in rows if (r["thickness"], r["mesh"], r["step"])
                   != key] + [row]

    if not args.report_only:
        for t in args.thickness.split(","):
            for mesh in args.meshes.split(","):
                put(run_case(t, mesh, False, args.ranks, directory))
                add_changes(rows)
                report(directory, rows)   # partial results as they come
            if not args.no_half_step:
                put(run_case(t, EXAMPLE_MESH, True, args.ranks, directory))
                add_changes(rows)
                report(directory, rows)
    order = {t: i for i, t in enumerate(THICKNESSES)}
    rows.sort(key=lambda r: (order.get(r["thickness"], 9), r["step"] != "example",
                             cells(r["mesh"])))
    add_changes(rows)
    report(directory, rows)
    return 0 if all(r["status"] == "completed" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
