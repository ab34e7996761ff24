#!/usr/bin/env python3
"""A wallette run killed with SIGKILL at five points and resumed
(`Resume = true`) gives the curve and cycle table of the run never killed
(to 1e-12 relative) and complete VTU series (every step once, every file
there); a run sent SIGTERM stops at its next step with a checkpoint and
status `interrupted', and resumes to the same curve.

Usage: kill_resume.py MASONRY WORK_DIR EXAMPLE_PRM SHORT_PRM [TERM_TOLERANCE]

With `Newton chord across steps' (kill_resume_chord) a run stopped by a
signal off the checkpoint interval loses the factorisation that its next
step's chord corrections would have used, so (as the entry documents) the
resumed run equals the uninterrupted one to the Newton tolerance, not to
round-off, and a step may take one Newton iteration more: TERM_TOLERANCE is
then the relative tolerance of that comparison, without the Newton
iteration counts.

The example is cut down to a short cyclic run by SHORT_PRM (a coarse
simplified wallette, three amplitudes, a checkpoint every step, fields
every third step). The kill points are steps: the run is killed as soon as curve.csv
holds that many steps, wherever it is then (mid-step, writing a checkpoint
or fields).
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

masonry, work, example, short = sys.argv[1:5]
term_tolerance = float(sys.argv[5]) if len(sys.argv) > 5 else None
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)

text = open(example).read() + "\n" + open(short).read()
# pictures are not what this test is about
text += "\nsubsection Postprocess\n  subsection Wallette\n" \
        "    set List of postprocessors = curve tables, fields, joint fields\n" \
        "  end\nend\n"


def prm(name, directory, resume=False):
    with open(name, "w") as f:
        f.write(text + "\nset Output directory = %s\n" % directory)
        if resume:
            f.write("subsection Wallette\n  set Resume = true\nend\n")
    return name


def run(name, **kw):
    return subprocess.run([masonry, name], capture_output=True, text=True, **kw)


def steps(directory):
    try:
        with open(os.path.join(directory, "curve.csv")) as f:
            return sum(1 for _ in f) - 1
    except OSError:
        return 0


def table(path):
    with open(path) as f:
        return [[float(x) if x else 0.0 for x in row]
                for row in list(csv.reader(f))[1:]]


def largest_difference(a, b):
    if len(a) != len(b):
        return float("inf")
    worst = 0.0
    for ra, rb in zip(a, b):
        if len(ra) != len(rb):
            return float("inf")
        for x, y in zip(ra, rb):
            worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-300)
                        if x != y else 0.0)
    return worst


def series(directory, pvd):
    """The (time, file) entries of a PVD file, or None."""
    path = os.path.join(directory, pvd)
    if not os.path.exists(path):
        return None
    return [(d.get("timestep"), d.get("file"))
            for d in ET.parse(path).getroot().findall(".//DataSet")]


def series_problems(directory, pvd):
    entries = series(directory, pvd)
    if entries is None:
        return [pvd + " missing"]
    problems = []
    files = [f for _, f in entries]
    if len(set(files)) != len(files):
        problems.append(pvd + ": a file listed twice")
    if entries != series("full", pvd):
        problems.append(pvd + ": not the uninterrupted run's series")
    for f in files:
        if not os.path.exists(os.path.join(directory, f)):
            problems.append(pvd + ": " + f + " missing")
    return problems


full = run(prm("full.prm", "full"))
if full.returncode != 0:
    sys.exit("the uninterrupted run failed:\n" + full.stderr)
n_steps = steps("full")
reference = table("full/curve.csv"), table("full/cycles.csv")
n_fields = len(ET.parse("full/solution.pvd").getroot().findall(".//DataSet"))
print("uninterrupted run: %d steps, %d field outputs" % (n_steps, n_fields))

failures = 0


def without_iterations(rows):
    """curve.csv's rows without its newton_iterations column (the sixth)."""
    return [row[:5] + row[6:] for row in rows]


def compare(directory, label, tolerance=1e-12):
    global failures
    curve = table(directory + "/curve.csv")
    reference_curve = reference[0]
    if tolerance > 1e-12:
        curve = without_iterations(curve)
        reference_curve = without_iterations(reference_curve)
    d_curve = largest_difference(reference_curve, curve)
    d_cycles = largest_difference(reference[1],
                                  table(directory + "/cycles.csv"))
    problems = series_problems(directory, "solution.pvd") + \
        series_problems(directory, "interfaces.pvd")
    summary = json.load(open(directory + "/summary.json"))
    ok = d_curve <= tolerance and d_cycles <= tolerance and not problems and \
        summary.get("complete") is True
    equal = "equal (%g)" % tolerance
    print("%s: curve %s, cycle table %s, field series %s, complete %s" % (
        label, equal if d_curve <= tolerance else "differs (%g)" % d_curve,
        equal if d_cycles <= tolerance else "differs (%g)" % d_cycles,
        "whole" if not problems else "; ".join(problems),
        summary.get("complete")))
    if not ok:
        failures += 1


# SIGKILL at five steps, spread over the run
for k, fraction in enumerate([0.1, 0.3, 0.5, 0.7, 0.9]):
    target = max(3, int(fraction * n_steps))
    directory = "killed%d" % k
    process = subprocess.Popen([masonry, prm("kill.prm", directory)],
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    while process.poll() is None and steps(directory) < target:
        time.sleep(0.001)
    killed_at = steps(directory)
    if process.poll() is None:
        process.send_signal(signal.SIGKILL)
    process.wait()
    resumed = run(prm("resume.prm", directory, resume=True))
    if resumed.returncode != 0:
        print("killed after step %d: the resumed run failed: %s" %
              (killed_at, resumed.stderr.strip()))
        failures += 1
        continue
    compare(directory, "killed after step %d of %d, resumed" %
            (killed_at, n_steps))

# SIGTERM: stops at the next step, interrupted, with a checkpoint
process = subprocess.Popen([masonry, prm("term.prm", "term")],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           text=True)
while process.poll() is None and steps("term") < n_steps // 2:
    time.sleep(0.001)
process.send_signal(signal.SIGTERM)
out, err = process.communicate()
summary = json.load(open("term/summary.json"))
stopped = summary.get("status") == "interrupted" and \
    os.path.exists("term/checkpoint.0") and steps("term") < n_steps
print("SIGTERM after step %d: status %s, exit code %d, checkpoint %s" % (
    steps("term"), summary.get("status"), process.returncode,
    "written" if os.path.exists("term/checkpoint.0") else "missing"))
if not stopped:
    failures += 1
    print(err)
else:
    resumed = run(prm("resume.prm", "term", resume=True))
    compare("term", "after SIGTERM, resumed", term_tolerance or 1e-12)

if failures:
    sys.exit("kill_resume: %d failure(s)" % failures)
print("kill_resume: every interrupted run resumed to the uninterrupted one")
