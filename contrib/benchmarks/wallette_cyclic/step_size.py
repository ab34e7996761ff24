#!/usr/bin/python3
"""Run time against error of the nominal step of a cyclic wallette example
(prm/examples/wallette-THICKNESS-cyclic.prm at its own mesh and seed): the
example with `Number of steps` = each of --steps (the nominal, largest,
step is `Target strain` / that number; `IMPL-EX minimum step` stays a
fraction of it) and a reference with a 4 x tighter `IMPL-EX damage
tolerance` (--reference-tolerance, at --reference-steps). Error: the
largest relative difference of a cycle peak (cycles.csv) from the
reference's, over the cycles before the reference's first cycle peak
below 0.95 of its highest (the cycles after it follow the collapse and the
deletions, whose order is decided at round-off level), and the envelope RMS of contrib/study/report.py before and after
the peak. Time: CPU seconds (user + system) of each run on
--threads assembly threads, one run at a time.

Writes step_size.csv, step_size.md and step_size.png into --output
(default build/benchmarks/wallette_cyclic).

Usage: contrib/benchmarks/wallette_cyclic/step_size.py [--thickness single]
       [--steps 80,40,20] [--reference-steps 80]
       [--reference-tolerance 0.0125] [--threads 1] [--output DIR]
       [--masonry BINARY] [--report-only]
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(os.path.dirname(here)))
sys.path.insert(0, os.path.join(root, "contrib", "study"))
from study import get_in, set_entry  # noqa: E402
import report  # noqa: E402
sys.path.insert(0, os.path.dirname(here))
from wallette_common import cpu_seconds  # noqa: E402

KEYS = ["case", "number_of_steps", "nominal_strain_step", "tolerance",
        "steps", "newton_iterations", "cpu_seconds", "wall_seconds", "peak_MPa",
        "max_cycle_peak_error", "rms_before", "rms_after", "reach",
        "status"]


def example_text(thickness):
    path = os.path.join(root, "prm", "examples",
                        f"wallette-{thickness}-cyclic.prm")
    return path, open(path).read()


def run(args, name, steps, tolerance):
    source, text = example_text(args.thickness)
    out = os.path.join(args.output, name)
    for key, value in (("Number of steps", str(steps)),
                       ("IMPL-EX damage tolerance", f"{tolerance:g}"),
                       ("Assembly threads", str(args.threads)),
                       ("Write VTU", "false"),
                       ("Checkpoint interval", "0")):
        text = set_entry(text, key, value, "wallette")
    text = set_entry(text, "Output directory", out, "top")
    prm = os.path.join(args.output, name + ".prm")
    with open(prm, "w") as f:
        f.write(f"# step-size case {name}, from "
                f"{os.path.relpath(source, root)}\n" + text)
    print(f"step_size: {name} ...", flush=True)
    t0, c0 = time.time(), cpu_seconds()
    with open(os.path.join(args.output, name + ".log"), "w") as f:
        code = subprocess.call([args.masonry, prm], stdout=f,
                               stderr=subprocess.STDOUT, cwd=args.output)
    if code != 0:
        print(f"step_size: {name} exited with {code}", file=sys.stderr)
    return time.time() - t0, cpu_seconds() - c0


def measure(directory):
    """Cycle peaks (MPa), summary and envelope fit of a finished run."""
    with open(os.path.join(directory, "cycles.csv")) as f:
        peaks = [float(r["peak_stress_Pa"]) / 1e6 for r in csv.DictReader(f)]
    with open(os.path.join(directory, "curve.csv")) as f:
        curve = [{"strain": float(r["strain"]),
                  "stress_Pa": float(r["stress_Pa"])}
                 for r in csv.DictReader(f)]
    summary = json.load(open(os.path.join(directory, "summary.json")))
    fit = report.envelope_fit([{"name": "x", "curve": curve}]).get(
        "x", (None, None, None))
    return peaks, summary, fit


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--thickness", default="single",
                   choices=("single", "double", "triple"))
    p.add_argument("--steps", default="80,40,20")
    p.add_argument("--reference-steps", type=int, default=80)
    p.add_argument("--reference-tolerance", type=float, default=0.0125)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--output", default=os.path.join(
        root, "build", "benchmarks", "wallette_cyclic"))
    p.add_argument("--masonry", default=os.path.join(root, "build",
                                                     "masonry"))
    p.add_argument("--report-only", action="store_true")
    args = p.parse_args()
    os.makedirs(args.output, exist_ok=True)
    _, text = example_text(args.thickness)
    tolerance = float(get_in(text, ["Wallette"], "IMPL-EX damage tolerance")
                      or 0.05)
    target = float(get_in(text, ["Wallette"], "Target strain"))
    cases = [(f"{args.thickness}-n{n}", n, tolerance)
             for n in (int(x) for x in args.steps.split(","))]
    cases.append((f"{args.thickness}-reference", args.reference_steps,
                  args.reference_tolerance))
    # CPU and wall seconds of the runs (kept for --report-only)
    times_file = os.path.join(args.output, "step_size_times.json")
    times = {}
    if os.path.exists(times_file):
        times = json.load(open(times_file))
    if not args.report_only:
        for name, n, tol in cases:
            times[name] = run(args, name, n, tol)
            with open(times_file, "w") as f:
                json.dump(times, f)
    ref_name = cases[-1][0]
    ref_peaks, _, _ = measure(os.path.join(args.output, ref_name))
    # the cycles before the reference's first peak below 0.95 of its highest
    last = len(ref_peaks)
    for k in range(ref_peaks.index(max(ref_peaks)), len(ref_peaks)):
        if ref_peaks[k] < 0.95 * max(ref_peaks):
            last = k
            break
    rows, per_cycle = [], {}
    for name, n, tol in cases:
        peaks, s, fit = measure(os.path.join(args.output, name))
        errors = [abs(a / b - 1) for a, b in zip(peaks[:last],
                                                  ref_peaks[:last])]
        wall, cpu = times.get(name, (s.get("wall_seconds"),
                                     s.get("cpu_seconds")))
        per_cycle[name] = [100 * (a / b - 1) for a, b in zip(peaks,
                                                               ref_peaks)]
        rows.append({"case": name, "number_of_steps": n,
                     "nominal_strain_step": target / n, "tolerance": tol,
                     "steps": s.get("steps"),
                     "newton_iterations": s.get("newton_iterations"),
                     "cpu_seconds": round(cpu, 1),
                     "wall_seconds": round(wall, 1),
                     "peak_MPa": round(max(peaks), 4),
                     "max_cycle_peak_error":
                         None if name == ref_name else round(max(errors), 5),
                     "rms_before": fit[0] and round(fit[0], 3),
                     "rms_after": fit[1] and round(fit[1], 3),
                     "reach": fit[2] and round(fit[2], 2),
                     "status": s.get("status")})
    with open(os.path.join(args.output, "step_size.csv"), "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=KEYS)
        w.writeheader()
        w.writerows(rows)
    lines = [f"# Nominal step of the {args.thickness} cyclic example: "
             "run time against error", "",
             f"Reference: {ref_name} (IMPL-EX damage tolerance "
             f"{args.reference_tolerance:g}, {args.reference_steps} nominal "
             f"steps). Error: largest |cycle peak / reference - 1| over "
             f"cycles 1-{last} (up to the reference's highest peak). "
             f"CPU s: user + system, {args.threads} assembly thread(s). "
             "RMS: envelope RMS before / after the peak (report.py); reach: "
             "last strain of the envelope / strain at the peak.", "",
             "| case | steps (nominal) | nominal strain step | tolerance | "
             "steps | Newton | CPU s | peak MPa | max cycle-peak error | "
             "RMS before / after | reach | status |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|"]
    for r in rows:
        err = ("—" if r["max_cycle_peak_error"] is None
               else f"{100 * r['max_cycle_peak_error']:.2f} %")
        lines.append(
            f"| {r['case']} | {r['number_of_steps']} | "
            f"{r['nominal_strain_step']:.2g} | {r['tolerance']:g} | "
            f"{r['steps']} | {r['newton_iterations']} | {r['cpu_seconds']} | "
            f"{r['peak_MPa']:.3f} | {err} | {r['rms_before']} / "
            f"{r['rms_after']} | {r['reach']} | {r['status']} |")
    lines += ["", "Cycle peaks against the reference, %:", "",
              "| case | " + " | ".join(f"cycle {k + 1}" for k in
                                      range(len(ref_peaks))) + " |",
              "|---|" + "---:|" * len(ref_peaks)]
    for name, _, _ in cases[:-1]:
        lines.append(f"| {name} | " + " | ".join(
            f"{e:+.2f}" for e in per_cycle[name]) + " |")
    lines.append(f"| {ref_name} (MPa) | " + " | ".join(
        f"{p:.3f}" for p in ref_peaks) + " |")
    with open(os.path.join(args.output, "step_size.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for r in rows[:-1]:
        ax.plot(r["cpu_seconds"], 100 * r["max_cycle_peak_error"], "o",
                color="C0")
        ax.annotate(f"{r['number_of_steps']} steps",
                    (r["cpu_seconds"], 100 * r["max_cycle_peak_error"]),
                    textcoords="offset points", xytext=(5, 5))
    ax.set_xlabel("CPU s")
    ax.set_ylabel(f"largest cycle-peak error, cycles 1-{last} (%)")
    ax.set_title(f"{args.thickness} cyclic example: nominal step\n"
                 f"(reference: tolerance {args.reference_tolerance:g}, "
                 f"{rows[-1]['cpu_seconds']} CPU s)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "step_size.png"), dpi=120)


if __name__ == "__main__":
    main()
