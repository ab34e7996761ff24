#!/usr/bin/python3
"""Run the nine-wallette study (called by contrib/study/run, which documents
the options): per thickness and seed, a copy of the example parameter file
with the seed and the output directory changed, run as a 1-rank masonry run,
several at a time; then report.py writes the table and the plots."""
import argparse
import json
import os
import re
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, here)
import report  # noqa: E402

THICKNESSES = ("single", "double", "triple")

# --quick: the coarsest mesh each bond accepts, four cycles, step 2e-4
QUICK = {
    "Elements along the width": "1",
    "Elements along the height": "1",
    "Cycle amplitudes": "0.002, 0.004, 0.006, 0.008",
    "Target strain": "0.008",
    "Number of steps": "40",
    "Write VTU": "false",
}
QUICK_LENGTH = {"single": "2", "double": "4", "triple": "4"}


def set_entry(text, name, value, where):
    """Replace the value of `set NAME = ...' (the first such line) keeping
    its indentation and comment, or add it after `set Analysis' (top-level
    entries) or at the start of subsection Wallette."""
    pattern = re.compile(r"^([ \t]*set[ \t]+" + re.escape(name) +
                         r"[ \t]*=)[^#\n]*(#.*)?$", re.M)
    m = pattern.search(text)
    if m:
        comment = "  " + m.group(2) if m.group(2) else ""
        return text[:m.start()] + m.group(1) + " " + value + comment + \
            text[m.end():]
    if where == "top":
        m = re.search(r"^set[ \t]+Analysis[ \t]*=.*$", text, re.M)
    else:
        m = re.search(r"^subsection[ \t]+Wallette[ \t]*$", text, re.M)
    if not m:
        raise SystemExit(f"study: error: cannot place `{name}' in the "
                         "parameter file")
    indent = "" if where == "top" else "  "
    return text[:m.end()] + f"\n{indent}set {name} = {value}" + text[m.end():]


def make_prm(thickness, seed, directory, quick):
    source = os.path.join(root, "prm", "examples",
                          f"wallette-{thickness}-cyclic.prm")
    with open(source) as f:
        text = f.read()
    name = f"{thickness}-{seed}"
    out = os.path.join(directory, name)
    text = set_entry(text, "Output directory", out, "top")
    text = set_entry(text, "Random seed", str(seed), "wallette")
    if quick:
        for key, value in QUICK.items():
            text = set_entry(text, key, value, "wallette")
        text = set_entry(text, "Elements along the length",
                         QUICK_LENGTH[thickness], "wallette")
    header = (f"# Study specimen {name}: {os.path.relpath(source, root)} "
              f"with Random seed = {seed}{' (--quick)' if quick else ''}, "
              "written by contrib/study/run.\n")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(header + text)
    return name, prm, out


def last_curve_line(out):
    """The last line of a running specimen's curve.csv, as a dict."""
    path = os.path.join(out, "curve.csv")
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    if len(lines) < 2:
        return None
    keys = lines[0].split(",")
    values = lines[-1].split(",")
    return dict(zip(keys, values)) if len(values) == len(keys) else None


def failure_line(log):
    """The masonry error line of a log (or its last line)."""
    try:
        with open(log) as f:
            lines = [l.rstrip() for l in f if l.strip()]
    except OSError:
        return "(no log)"
    for l in lines:
        if "error" in l.lower():
            return l
    return lines[-1] if lines else "(empty log)"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--output", default="")
    p.add_argument("--thickness", default=",".join(THICKNESSES))
    p.add_argument("--seeds", default="1,2,3")
    p.add_argument("--report-only", action="store_true")
    p.add_argument("--no-setup", action="store_true")
    args = p.parse_args()
    if args.jobs < 1:
        raise SystemExit("study: error: --jobs must be at least 1")
    thicknesses = [t for t in args.thickness.split(",") if t]
    for t in thicknesses:
        if t not in THICKNESSES:
            raise SystemExit(f"study: error: unknown thickness `{t}' "
                             f"(one of {', '.join(THICKNESSES)})")
    seeds = [int(s) for s in args.seeds.split(",") if s]
    directory = os.path.abspath(
        args.output or ("output/study-quick" if args.quick else "output/study"))
    os.makedirs(directory, exist_ok=True)
    masonry = os.path.join(root, "build", "masonry")

    if args.report_only:
        return report.main([directory])

    runs = [make_prm(t, s, directory, args.quick)
            for t in thicknesses for s in seeds]
    print(f"study: {len(runs)} runs, {min(args.jobs, len(runs))} at a time"
          f"{' (quick)' if args.quick else ''}, in {directory}/", flush=True)
    waiting = list(runs)
    running = {}
    failed = []
    start = time.time()
    last_status = start
    while waiting or running:
        while waiting and len(running) < args.jobs:
            name, prm, out = waiting.pop(0)
            log = os.path.join(directory, name + ".log")
            with open(log, "w") as f:
                proc = subprocess.Popen([masonry, prm], stdout=f,
                                        stderr=subprocess.STDOUT,
                                        cwd=directory)
            running[name] = (proc, out, log, time.time())
            print(f"study: started {name}", flush=True)
        time.sleep(1)
        for name in list(running):
            proc, out, log, t0 = running[name]
            code = proc.poll()
            if code is None:
                continue
            del running[name]
            seconds = time.time() - t0
            summary = {}
            try:
                with open(os.path.join(out, "summary.json")) as f:
                    summary = json.load(f)
            except (OSError, ValueError):
                pass
            status = summary.get("status", "no summary.json")
            if code == 0 and status == "completed":
                print(f"study: finished {name} in {seconds:.0f} s: peak "
                      f"{summary['peak_stress'] / 1e6:.2f} MPa at strain "
                      f"{summary['strain_at_peak']:.5f}, "
                      f"{len(summary.get('cycles', []))} cycles, "
                      f"{summary.get('deleted_cells', 0)} deleted cells",
                      flush=True)
            else:
                why = summary.get("message") or summary.get("error") or \
                    failure_line(log)
                print(f"study: FAILED {name} (exit code {code}, status "
                      f"{status}) after {seconds:.0f} s: {why}\n"
                      f"study:   log: {log}", file=sys.stderr, flush=True)
                failed.append(name)
        if running and time.time() - last_status > 60:
            last_status = time.time()
            parts = []
            for name, (proc, out, log, t0) in running.items():
                c = last_curve_line(out)
                if c:
                    parts.append(f"{name} step {c['step']} cycle {c['cycle']}"
                                 f" strain {float(c['strain']):.4f} stress "
                                 f"{float(c['stress_Pa']) / 1e6:.1f} MPa")
                else:
                    parts.append(f"{name} starting")
            print(f"study: {time.time() - start:.0f} s, "
                  f"{len(waiting)} waiting; " + "; ".join(parts), flush=True)
    print(f"study: all runs done in {time.time() - start:.0f} s", flush=True)
    code = report.main([directory])
    if failed:
        print(f"study: error: {len(failed)} of {len(runs)} runs failed: "
              f"{', '.join(failed)} (logs {directory}/NAME.log)",
              file=sys.stderr)
        return 1
    return code


if __name__ == "__main__":
    sys.exit(main())
