"""Plot the convergence history of a mesh adaptation (adaptation.csv):
best and mean fitness per generation against evaluations.

Usage: /usr/bin/python3 adaptation_plot.py adaptation.csv adaptation.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(source, target):
    with open(source) as f:
        header = f.readline().lstrip("# ").strip()
        rows = list(csv.DictReader(f))
    evaluations = [int(r["evaluations"]) for r in rows]
    best = [float(r["best"]) for r in rows]
    mean = [float(r["mean"]) if float(r["mean"]) > -1e299 else float("nan") for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(evaluations, best, "o-", label="best")
    ax.plot(evaluations, mean, "s--", label="population mean", alpha=0.7)
    ax.set_xlabel("fitness evaluations")
    ax.set_ylabel(header.split(":")[-1].replace("best and mean", "").replace("per generation", "").strip())
    ax.set_title("Mesh adaptation")
    ax.legend()
    fig.tight_layout()
    fig.savefig(target, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
