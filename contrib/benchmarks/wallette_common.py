"""Shared helpers of the wallette benchmarks (wallette_cyclic,
wallette_convergence)."""
import csv
import os
import resource


def cells(mesh):
    """Cells per enlarged stretcher of a mesh "n_l x n_w x n_h"."""
    a, b, c = (int(x) for x in mesh.split("x"))
    return a * b * c


def cpu_seconds():
    """User + system seconds of the finished children (the ranks and
    mpirun): on a shared machine the wall time also counts the others'."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def read_rows(path):
    """The rows of an earlier results.csv, numbers as int or float, empty
    cells and the derived column change_to_finer left out."""
    rows = []
    if not os.path.exists(path):
        return rows
    with open(path) as f:
        for r in csv.DictReader(f):
            row = {}
            for k, v in r.items():
                if v == "" or k == "change_to_finer":
                    continue
                try:
                    row[k] = int(v)
                except ValueError:
                    try:
                        row[k] = float(v)
                    except ValueError:
                        row[k] = v
            rows.append(row)
    return rows


def write_rows(path, keys, rows):
    """results.csv: the columns keys of every row (other entries left out)."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
