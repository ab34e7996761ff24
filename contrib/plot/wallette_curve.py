#!/usr/bin/python3
"""Plots of a wallette run (masonry runs this at the end of the run).

Usage: wallette_curve.py OUTPUT_DIRECTORY

Reads curve.csv (and cycles.csv for the cyclic protocol) in the directory
and writes curve.png (stress over strain, with the cycle peaks) and, for the
cyclic protocol, degradation.png (unloading modulus over the initial modulus
at each cycle's peak strain). Stress in MPa (platen force / gross area),
strain in 1e-3 (platen displacement / height).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(d):
    rows = list(csv.DictReader(open(os.path.join(d, "curve.csv"))))
    e = [1e3 * float(r["strain"]) for r in rows]
    s = [1e-6 * float(r["stress_Pa"]) for r in rows]
    plt.figure(figsize=(6, 4.5))
    plt.plot(e, s, "-", lw=1, marker="o" if len(e) < 80 else None, ms=3)
    cycles_csv = os.path.join(d, "cycles.csv")
    c = None
    if os.path.exists(cycles_csv):
        c = list(csv.DictReader(open(cycles_csv)))
        plt.plot([1e3 * float(r["strain_at_peak"]) for r in c],
                 [1e-6 * float(r["peak_stress_Pa"]) for r in c],
                 "k^", ms=4, label="cycle peaks")
        plt.legend()
    plt.xlabel("strain along the platen motion (1e-3)")
    plt.ylabel("stress = force / gross area (MPa)")
    plt.grid(alpha=0.3)
    plt.tight_layout()
    plt.savefig(os.path.join(d, "curve.png"), dpi=120)
    if c is not None:
        plt.figure(figsize=(6, 4.5))
        plt.plot([1e3 * float(r["strain_at_peak"]) for r in c],
                 [float(r["stiffness_ratio"]) for r in c], "o-")
        plt.xlabel("strain at the cycle peak (1e-3)")
        plt.ylabel("unloading modulus / initial modulus")
        plt.ylim(0, 1.05)
        plt.grid(alpha=0.3)
        plt.tight_layout()
        plt.savefig(os.path.join(d, "degradation.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
