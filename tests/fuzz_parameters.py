#!/usr/bin/python3
"""Fuzz test of masonry's parameter reading: hostile parameter files.

  fuzz_parameters.py generate EXAMPLES_DIR OUT_DIR [--count N] [--seed S]
      writes OUT_DIR/*.prm, mutated copies of the examples (0, negative,
      1e-300, 1e300, nan, inf, words and empty values in numeric entries, bad
      function expressions, overlong values and names, include cycles, a
      byte-order mark, empty files, bad output directories, ...), and
      OUT_DIR/manifest.txt: one line `name mode` per file, mode `validate`
      (masonry --validate) or `run` (a real run, chosen where it is cheap).

  fuzz_parameters.py run MASONRY OUT_DIR [--timeout T] [--jobs J]
        [--all-run] [--table-only]
      runs every file of the manifest (--all-run: every file as a real run)
      and sorts the outcomes: `clean error' (exit 1, one line
      `masonry: error: ...' naming an entry, or the file for file-level
      errors), `correct' (exit 0, every number in summary.json and the CSV
      files finite), `unclear error' (exit non-zero, but not one line or
      naming no entry), `crash' (a signal other than SIGABRT), `abort'
      (SIGABRT, an MPI abort), `hang' (over the time limit), `nan' (exit 0
      with a non-finite or null number in the results). Exit code 1 if any
      outcome is not `clean error' or `correct' (unless --table-only).

Only the Python standard library; deterministic for a given seed.
"""
import json
import os
import random
import re
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
BAD_NUMBERS = ["0", "-1", "1e-300", "1e300", "-1e300", "nan", "inf", "-inf",
               "abc", ""]
BAD_FUNCTIONS = ["foo", "t", "nan", "(x+1", "x/0", "sqrt(-1)", "1e300",
                 "-1e300", "x*1e305", "", "0;0"]
# entries whose value is a function of x, y, z (components ';'-separated)
FUNCTIONS = {"Settlement": 3, "Surface load": 1, "Thickness": 1}


def parse(lines):
    """(index, section path, name, value) of every `set' line."""
    entries, sections = [], []
    for i, line in enumerate(lines):
        code = line.split("#", 1)[0].strip()
        if code.startswith("subsection "):
            sections.append(code[11:].strip())
        elif code == "end" and sections:
            sections.pop()
        elif code.startswith("set ") and "=" in code:
            name, value = code[4:].split("=", 1)
            entries.append((i, "/".join(sections), name.strip(),
                            value.strip()))
    return entries


def with_value(lines, index, name, value):
    out = list(lines)
    indent = re.match(r"\s*", lines[index]).group(0)
    out[index] = "%sset %s = %s" % (indent, name, value)
    return out


def analysis_of(lines):
    for _, path, name, value in parse(lines):
        if path == "" and name == "Analysis":
            return value
    return ""


def cheap_run(lines):
    """A real run for small rigid-block models, without the picture."""
    analysis = analysis_of(lines)
    if any("Optimiser" in line for line in lines):
        return None  # adapted runs solve hundreds of LPs
    if analysis not in ("settlement", "limit load", "minimum thickness"):
        return None
    section = analysis[0].upper() + analysis[1:]
    out = []
    for line in lines:
        out.append(line)
        if line.strip() == "subsection " + section:
            out.append("  set Write picture = false")
    return out


def generate(examples, out_dir, count, seed):
    rng = random.Random(seed)
    os.makedirs(out_dir, exist_ok=True)
    for f in os.listdir(out_dir):
        if f.endswith(".prm") or f == "manifest.txt":
            os.remove(os.path.join(out_dir, f))
    files = sorted(f for f in os.listdir(examples) if f.endswith(".prm"))
    texts = {}
    for f in files:
        with open(os.path.join(examples, f)) as fin:
            texts[f[:-4]] = fin.read().splitlines()
    manifest = []

    def emit(name, lines, mode="validate", raw=None, output=True):
        body = list(lines)
        if output:
            body.append("set Output directory = out/" + name)
        with open(os.path.join(out_dir, name + ".prm"), "wb") as fout:
            data = ("\n".join(body) + "\n").encode()
            fout.write(raw if raw is not None else data)
        manifest.append((name, mode))

    # --- the cases of the issue, always present ---------------------------
    arch = texts.get("arch-vertical-settlement", [])
    seismic = texts.get("bothwell-seismic", [])
    single = texts.get("wallette-single-monotonic", [])
    emit("empty", [], raw=b"")
    emit("empty-comment", ["# nothing"], output=False)
    emit("bom", arch, "run", raw=("\ufeff" + "\n".join(
        cheap_run(arch) + ["set Output directory = out/bom"]) + "\n").encode())
    emit("self-include", ["include self-include.prm"] + arch)
    with open(os.path.join(out_dir, "cycle-b.inc"), "w") as fout:
        fout.write("include cycle-a.prm\n")
    emit("cycle-a", ["include cycle-b.inc"] + arch)
    os.makedirs(os.path.join(out_dir, "a-directory"), exist_ok=True)
    emit("include-directory", ["include a-directory"] + arch)
    emit("include-missing", ["include no-such-file.prm"] + arch)
    for i, _, name, value in parse(arch):
        if name == "Settlement":
            emit("long-value", with_value(arch, i, name, "0; 0; -0.01" +
                                          " " * 5 + "+0" * 20000))
            emit("long-value-2", with_value(arch, i, name, "x" * 40000))
        if name == "Settling edges":
            emit("double-space", with_value(arch, i, name,
                                            "springing  right"),
                 "run")
            emit("double-space-2", with_value(cheap_run(arch),
                                              i + 1, name,
                                              "springing \t right"), "run")
    emit("long-name", arch + ["set " + "N" * 40000 + " = 1"])
    emit("long-subsection", arch + ["subsection " + "S" * 40000, "end"])
    for k, directory in enumerate(["/proc/x", "/dev/null",
                                   "fuzz-a-file/sub", ""]):
        with open(os.path.join(out_dir, "fuzz-a-file"), "w") as fout:
            fout.write("a regular file\n")
        emit("output-directory-%d" % k,
             arch + ["set Output directory = " + directory], output=False)
    # a result file that cannot be written: a directory of that name
    os.makedirs(os.path.join(out_dir, "out", "blocked", "blocks.csv"),
                exist_ok=True)
    emit("blocked-result", cheap_run(arch), "run", output=False,
         raw=("\n".join(cheap_run(arch) + ["set Output directory = "
                                           "out/blocked"]) + "\n").encode())
    for i, path, name, value in parse(seismic):
        if name == "Live acceleration":
            emit("live-acceleration-1e300",
                 with_value(seismic, i, name, "1e300; 0; 0"))
    for i, path, name, value in parse(single):
        if name in ("Joint thickness", "Brick width"):
            emit(name.replace(" ", "-").lower() + "-1e300",
                 with_value(single, i, name, "1e300"))
    emit("resume-without-checkpoint", [
        line + ("\n  set Resume = true" if line.strip() == "subsection "
                "Wallette" else "") for line in single])
    emit("impl-ex-1e-300", [
        line + ("\n  set IMPL-EX damage tolerance = 1e-300"
                if line.strip() == "subsection Wallette" else "")
        for line in single])
    for what in ("Cohesion", "Tensile strength", "Compressive strength"):
        emit("mohr-coulomb-" + what.replace(" ", "-").lower(),
             cheap_run(arch) + ["subsection Interface model",
                                "  set Model = mohr coulomb",
                                "  subsection Mohr coulomb",
                                "    set " + what + " = 1e300", "  end",
                                "end"], "run")
    emit("point-load-1e300", [
        line + ("\n  set Point loads = 0, 0.5, 0.5, 0, 0, -1e300"
                if line.strip() == "subsection Limit load" else "")
        for line in seismic])

    # --- random mutations of numeric entries and expressions -------------
    candidates = []
    for stem, lines in sorted(texts.items()):
        for i, path, name, value in parse(lines):
            if name in ("Output directory", "Analysis"):
                continue
            if name in FUNCTIONS:
                for bad in BAD_FUNCTIONS:
                    v = bad if FUNCTIONS[name] == 1 else "0; 0; " + bad
                    candidates.append((stem, i, name, v))
                for bad in ("-1e300", "1e300"):
                    candidates.append((stem, i, name, bad))
            elif all(NUMBER.match(x.strip())
                     for x in re.split(r"[;,]", value) if x.strip()):
                parts = re.split(r"([;,])", value)
                for bad in BAD_NUMBERS:
                    if len(parts) > 1:
                        # one component of a vector
                        k = 2 * rng.randrange((len(parts) + 1) // 2)
                        p = list(parts)
                        p[k] = bad
                        candidates.append((stem, i, name, "".join(p)))
                    else:
                        candidates.append((stem, i, name, bad))
            else:
                for bad in ("", "???", "1e300", "nan"):
                    candidates.append((stem, i, name, bad))
    rng.shuffle(candidates)
    n_random = max(0, count - len(manifest))
    for k, (stem, i, name, value) in enumerate(candidates[:n_random]):
        lines = texts[stem]
        cheap = cheap_run(lines)
        tag = "%03d-%s-%s" % (k, stem, re.sub(r"[^a-z0-9]+", "-",
                                             name.lower()).strip("-"))
        if cheap is not None and rng.random() < 0.6:
            # the picture line is inserted after the analysis section line
            inserted = [n for n, l in enumerate(cheap)
                        if l.strip() == "set Write picture = false"]
            index = i + (1 if inserted and inserted[0] <= i else 0)
            emit(tag, with_value(cheap, index, name, value), "run")
        else:
            emit(tag, with_value(lines, i, name, value))
    with open(os.path.join(out_dir, "manifest.txt"), "w") as fout:
        for name, mode in manifest:
            fout.write("%s %s\n" % (name, mode))
    print("fuzz: %d files (%d real runs) in %s" % (
        len(manifest), sum(1 for _, m in manifest if m == "run"), out_dir))


# errors about the file itself, not one of its entries
FILE_LEVEL = ("no Analysis set", "include", "cannot open the parameter file",
              "is a directory", "not a parameter file")


def non_finite_in(directory):
    """A description of the first non-finite number in the results."""
    summary = os.path.join(directory, "summary.json")
    if os.path.exists(summary):
        with open(summary) as fin:
            text = fin.read()
        if re.search(r"\b(nan|NaN|inf|Infinity|null)\b", text):
            return "summary.json"
    if os.path.isdir(directory):
        for f in os.listdir(directory):
            if f.endswith(".csv"):
                with open(os.path.join(directory, f), errors="replace") as fin:
                    next(fin, None)
                    for line in fin:
                        if re.search(r"(?i)(^|[^a-z])(nan|inf)", line):
                            return f
    return ""


def classify(masonry, out_dir, name, mode, timeout):
    prm = name + ".prm"
    command = [masonry] + (["--validate"] if mode == "validate" else []) + \
        [prm]
    start = time.time()
    try:
        p = subprocess.run(command, cwd=out_dir, capture_output=True,
                           timeout=timeout, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return name, mode, "hang", "over %g s" % timeout, timeout
    seconds = time.time() - start
    err = p.stderr.decode(errors="replace")
    lines = [l for l in err.splitlines() if l.strip()]
    first = lines[0][:160] if lines else ""
    if p.returncode < 0:
        kind = "abort" if -p.returncode == signal.SIGABRT else "crash"
        return name, mode, kind, "signal %d %s" % (-p.returncode, first), \
            seconds
    if "MPI_ABORT" in err or "Assertion" in err or p.returncode >= 128:
        return name, mode, "abort", first, seconds
    if p.returncode == 0:
        if mode == "run":
            bad = non_finite_in(os.path.join(out_dir, "out", name))
            if bad:
                return name, mode, "nan", bad, seconds
        return name, mode, "correct", "", seconds
    if len(lines) == 1 and lines[0].startswith("masonry: error:") and (
            "entry '" in lines[0] or "subsection '" in lines[0] or
            any(k in lines[0] for k in FILE_LEVEL) or
            (mode == "run" and "are incomplete; summary.json has status"
             in lines[0])):
        return name, mode, "clean error", first, seconds
    return name, mode, "unclear error", first, seconds


def run(masonry, out_dir, timeout, jobs, all_run, table_only):
    with open(os.path.join(out_dir, "manifest.txt")) as fin:
        cases = [l.split() for l in fin if l.strip()]
    if all_run:
        cases = [(n, "run") for n, _ in cases]
    masonry = os.path.abspath(masonry)
    with ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(
            lambda c: classify(masonry, out_dir, c[0], c[1], timeout), cases))
    kinds = ["clean error", "correct", "unclear error", "crash", "abort",
             "hang", "nan"]
    counts = {k: 0 for k in kinds}
    for _, _, kind, _, _ in results:
        counts[kind] += 1
    bad = [r for r in results if r[2] not in ("clean error", "correct")]
    for name, mode, kind, detail, seconds in bad:
        print("fuzz: %-13s %-8s %s: %s" % (kind, mode, name, detail))
    print("fuzz: %d files (%d real runs), %.0f s in total: %s" % (
        len(results), sum(1 for r in results if r[1] == "run"),
        sum(r[4] for r in results),
        ", ".join("%s %d" % (k, counts[k]) for k in kinds)))
    slowest = max(results, key=lambda r: r[4])
    print("fuzz: slowest %s (%s) %.1f s" % (slowest[0], slowest[1],
                                           slowest[4]))
    return 0 if table_only or not bad else 1


def main(argv):
    if len(argv) >= 3 and argv[0] == "generate":
        count = int(argv[argv.index("--count") + 1]) \
            if "--count" in argv else 300
        seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 1
        generate(argv[1], argv[2], count, seed)
        return 0
    if len(argv) >= 3 and argv[0] == "run":
        timeout = float(argv[argv.index("--timeout") + 1]) \
            if "--timeout" in argv else 30
        jobs = int(argv[argv.index("--jobs") + 1]) if "--jobs" in argv else 2
        return run(argv[1], argv[2], timeout, jobs, "--all-run" in argv,
                   "--table-only" in argv)
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
