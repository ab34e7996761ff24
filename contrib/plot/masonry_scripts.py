#!/usr/bin/python3
"""Run masonry's picture scripts in one Python process.

masonry calls this runner (masonry::run_scripts(), include/masonry/core/
scripts.h) with the scripts of one run, so that Python starts and imports
matplotlib once per run instead of once per picture. Each script runs as
its own `__main__` with its own arguments. A script that writes a file
writes it under a temporary name in the same directory (the argument
"{output}" stands for it), and the runner renames it to its final name only
when the script succeeded: a picture is whole or absent, never half
written.

Usage: masonry_scripts.py JOBS
JOBS is a JSON list of {"script": path, "arguments": [...], "output": path
or ""}. The runner prints one line per job, "masonry-job N ok" or
"masonry-job N error CAUSE", CAUSE being the real reason in one line (a
missing Debian package, a full disk, the script's exception and line).
"""
import contextlib
import errno
import io
import json
import os
import runpy
import sys
import traceback

# Python modules the scripts import, and the Debian packages that hold them
PACKAGES = {
    "matplotlib": "python3-matplotlib",
    "mpl_toolkits": "python3-matplotlib",
    "numpy": "python3-numpy",
    "plotly": "python3-plotly",
    "meshio": "python3-meshio",
    "h5py": "python3-h5py",
}


def cause(exc, script):
    """The reason of a failed script, in one line."""
    if isinstance(exc, ModuleNotFoundError):
        name = (exc.name or "?").split(".")[0]
        package = PACKAGES.get(name, f"python3-{name}")
        return f"missing Python module '{name}' (install the Debian package {package})"
    if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT,
                                                  errno.EFBIG, errno.EIO):
        # "write failed:" tells the C++ side to end the run
        return f"write failed: {exc.strerror}"
    if isinstance(exc, MemoryError):
        return "out of memory"
    if isinstance(exc, SystemExit):
        return f"{os.path.basename(script)} stopped with exit code {exc.code}"
    if isinstance(exc, OSError):
        where = f" '{exc.filename}'" if exc.filename else ""
        return f"{exc.strerror or exc}{where}"
    lines = str(exc).strip().splitlines()
    text = f"{type(exc).__name__}: {lines[0] if lines else ''}".rstrip(": ")
    # the innermost line of the script (or of a module it calls) that raised
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if f.filename == script]
    if frames:
        text += f" ({os.path.basename(script)} line {frames[-1].lineno})"
    return text


def temporary_name(output):
    """A name next to @p output, with its extension (matplotlib chooses
    the format by it), hidden while it is written."""
    directory, name = os.path.split(output)
    stem, extension = os.path.splitext(name)
    return os.path.join(directory, f".{stem}.{os.getpid()}.part{extension}")


def run(job):
    """Run one job; return None or the cause of its failure."""
    script, output = job["script"], job.get("output", "")
    partial = temporary_name(output) if output else ""
    arguments = [partial if a == "{output}" else a for a in job["arguments"]]
    saved = sys.argv
    sys.argv = [script] + arguments
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            runpy.run_path(script, run_name="__main__")
        if partial:
            if not os.path.isfile(partial):
                return f"{os.path.basename(script)} wrote no file"
            os.replace(partial, output)
        return None
    except SystemExit as exc:
        if exc.code in (None, 0) and (not partial or os.path.isfile(partial)):
            if partial:
                os.replace(partial, output)
            return None
        return cause(exc, script)
    except BaseException as exc:  # noqa: B902 (every failure is reported)
        return cause(exc, script)
    finally:
        sys.argv = saved
        if partial and os.path.exists(partial):
            with contextlib.suppress(OSError):
                os.remove(partial)
        if "matplotlib.pyplot" in sys.modules:
            sys.modules["matplotlib.pyplot"].close("all")


def main():
    jobs = json.loads(sys.argv[1])
    for number, job in enumerate(jobs):
        why = run(job)
        print(f"masonry-job {number} " + ("ok" if why is None else "error " + why.replace("\n", " ")),
              flush=True)


if __name__ == "__main__":
    main()
