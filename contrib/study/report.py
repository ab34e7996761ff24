#!/usr/bin/python3
"""Table and plots of the nine-wallette study.

Usage: contrib/study/report.py STUDY_DIRECTORY

Reads NAME/summary.json, curve.csv, cycles.csv and envelope.csv of every
specimen NAME = THICKNESS-SEED in the study directory (written by
contrib/study/run) and writes there:
  study.csv   one row per specimen, then mean and CoV per thickness
  study.md    the same as a markdown table, with the codes' strengths
  study_curves.png       the stress-strain curves, one panel per thickness
  study_degradation.png  unloading modulus / initial modulus against strain
  study_envelope.png     sigma/sigma_m against eps/eps_m of the envelope
                         with (eps/eps_m) exp(1 - eps/eps_m)
Needs /usr/bin/python3 with matplotlib and numpy.
"""
import csv
import json
import math
import os
import re
import sys
import time

THICKNESSES = ("single", "double", "triple")
COLOURS = {1: "tab:blue", 2: "tab:orange", 3: "tab:green"}
# Eurocode 6 (EN 1996-1-1 Eq. 3.1, Table 3.3) and Kaushik, Rai & Jain 2007,
# REFERENCES.md part B, marked *(check)* there
EC6_K = 0.55          # clay units, group 1, general purpose mortar
EC6_LONGITUDINAL = 0.8  # factor on K with a longitudinal joint (double, triple)
MORTAR_STRENGTH = 5.0   # MPa, f_m assumed (the joints of the model carry no f_m)


def read_csv(path):
    try:
        with open(path) as f:
            # an empty field (e.g. no common point) is None
            return [{k: float(v) if v != "" else None for k, v in row.items()}
                    for row in csv.DictReader(f)]
    except (OSError, ValueError):
        return []


def brick_strength(prm):
    """f_b, MPa: the `Compressive strength' of the damage-plasticity bricks
    in a specimen's parameter file (None if not found)."""
    try:
        text = open(prm).read()
    except OSError:
        return None
    m = re.search(r"^\s*set\s+Compressive strength\s*=\s*([0-9.eE+-]+)",
                  text, re.M)
    return float(m.group(1)) / 1e6 if m else None


def specimens(directory):
    found = []
    for t in THICKNESSES:
        for name in sorted(os.listdir(directory)):
            m = re.fullmatch(t + r"-(\d+)\.prm", name)
            if m:
                found.append((t, int(m.group(1))))
    return found


def load(directory, thickness, seed):
    name = f"{thickness}-{seed}"
    out = os.path.join(directory, name)
    s = {"name": name, "thickness": thickness, "seed": seed,
         "log": os.path.join(directory, name + ".log")}
    try:
        with open(os.path.join(out, "summary.json")) as f:
            s["summary"] = json.load(f)
    except (OSError, ValueError):
        s["summary"] = {"status": "no summary.json"}
    s["curve"] = read_csv(os.path.join(out, "curve.csv"))
    s["cycles"] = read_csv(os.path.join(out, "cycles.csv"))
    s["envelope"] = read_csv(os.path.join(out, "envelope.csv"))
    s["f_b"] = brick_strength(os.path.join(directory, name + ".prm"))
    j = s["summary"]
    row = {"specimen": name, "thickness": thickness, "seed": seed,
           "status": j.get("status", "?")}
    if s["curve"]:
        peak = max(s["curve"], key=lambda p: p["stress_Pa"])
        row["peak_stress_MPa"] = peak["stress_Pa"] / 1e6
        row["strain_at_peak"] = peak["strain"]
    if "initial_modulus" in j:
        row["initial_modulus_GPa"] = j["initial_modulus"] / 1e9
    cycles = [c for c in s["cycles"] if c["unloading_modulus_Pa"] > 0]
    if cycles:
        at_peak = max(cycles, key=lambda c: c["peak_stress_Pa"])
        row["stiffness_ratio_peak_cycle"] = at_peak["stiffness_ratio"]
        row["stiffness_ratio_last_cycle"] = cycles[-1]["stiffness_ratio"]
        row["last_amplitude"] = cycles[-1]["amplitude_strain"]
    if s["cycles"]:
        row["cycles"] = len(s["cycles"])
    if s["curve"]:
        row["deleted_cells"] = int(s["curve"][-1]["deleted_cells"])
    for key in ("steps", "newton_iterations", "cut_backs", "n_cells",
                "n_dofs"):
        if key in j:
            row[key] = j[key]
    if "wall_seconds" in j:
        row["wall_seconds"] = j["wall_seconds"]
    s["row"] = row
    return s


COLUMNS = [
    # key, heading, format
    ("peak_stress_MPa", "peak stress MPa", "{:.2f}"),
    ("strain_at_peak", "strain at peak", "{:.5f}"),
    ("initial_modulus_GPa", "initial modulus GPa", "{:.2f}"),
    ("stiffness_ratio_peak_cycle", "E_u/E_0 peak cycle", "{:.3f}"),
    ("stiffness_ratio_last_cycle", "E_u/E_0 last cycle", "{:.3f}"),
    ("cycles", "cycles", "{:.0f}"),
    ("deleted_cells", "deleted cells", "{:.0f}"),
    ("steps", "steps", "{:.0f}"),
    ("newton_iterations", "Newton iterations", "{:.0f}"),
    ("wall_seconds", "wall s", "{:.0f}"),
]
STATISTICS = COLUMNS[:7] + [COLUMNS[9]]


def mean_cov(values):
    values = [v for v in values if v is not None]
    if not values:
        return None, None
    m = sum(values) / len(values)
    if len(values) < 2 or m == 0:
        return m, None
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))
    return m, sd / abs(m)


def write_tables(directory, data):
    rows = []
    for t in THICKNESSES:
        group = [s["row"] for s in data if s["thickness"] == t]
        if not group:
            continue
        rows.extend(group)
        ok = [r for r in group if r["status"] == "completed"]
        mean = {"specimen": f"{t} mean", "thickness": t, "seed": "",
                "status": f"{len(ok)}/{len(group)} completed"}
        cov = {"specimen": f"{t} CoV", "thickness": t, "seed": "",
               "status": ""}
        for key, _, _ in STATISTICS:
            m, c = mean_cov([r.get(key) for r in ok])
            if m is not None:
                mean[key] = m
            if c is not None:
                cov[key] = c
        rows.extend([mean, cov])
    keys = ["specimen", "thickness", "seed"] + [k for k, _, _ in COLUMNS] + \
        ["status"]
    with open(os.path.join(directory, "study.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow(["" if r.get(k) is None else r.get(k) for k in keys])

    lines = ["| specimen | " + " | ".join(h for _, h, _ in COLUMNS) +
             " | status |",
             "|---|" + "---:|" * len(COLUMNS) + "---|"]
    for r in rows:
        cells = []
        for key, _, fmt in COLUMNS:
            v = r.get(key)
            if v is None:
                cells.append("")
            elif r["specimen"].endswith("CoV"):
                cells.append(f"{100 * v:.1f} %")
            else:
                cells.append(fmt.format(v))
        name = r["specimen"]
        if name.endswith(("mean", "CoV")):
            name = f"**{name}**"
        lines.append(f"| {name} | " + " | ".join(cells) +
                     f" | {r['status']} |")
    return rows, "\n".join(lines)


def codes_table(data, rows):
    f_b = next((s["f_b"] for s in data if s["f_b"]), None)
    if f_b is None:
        return ""
    f_m = MORTAR_STRENGTH
    lines = [
        f"Code strengths for f_b = {f_b:g} MPa (the bricks' `Compressive "
        f"strength') and f_m = f_j = {f_m:g} MPa (assumed: the joints of the "
        "model carry no mortar strength). Eurocode 6 gives the "
        "characteristic (5 %) strength f_k = K f_b^0.7 f_m^0.3 with K = "
        f"{EC6_K} (clay, group 1), times {EC6_LONGITUDINAL} with a "
        "longitudinal joint (double, triple); Kaushik, Rai & Jain 2007 give "
        "the mean f'_m = 0.63 f_b^0.49 f_j^0.32 and E = 550 f'_m. Both are "
        "marked *(check)* in REFERENCES.md part B.",
        "",
        "| thickness | model mean peak MPa | EC6 f_k MPa | model / f_k | "
        "Kaushik f'_m MPa | model / f'_m | model E_0 GPa | 550 f'_m GPa |",
        "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for t in THICKNESSES:
        mean = next((r for r in rows if r["specimen"] == f"{t} mean"), None)
        if not mean or "peak_stress_MPa" not in mean:
            continue
        k = EC6_K * (EC6_LONGITUDINAL if t != "single" else 1.0)
        f_k = k * f_b ** 0.7 * f_m ** 0.3
        f_kaushik = 0.63 * f_b ** 0.49 * f_m ** 0.32
        peak = mean["peak_stress_MPa"]
        lines.append(
            f"| {t} | {peak:.2f} | {f_k:.2f} | {peak / f_k:.2f} | "
            f"{f_kaushik:.2f} | {peak / f_kaushik:.2f} | "
            f"{mean.get('initial_modulus_GPa', float('nan')):.2f} | "
            f"{550 * f_kaushik / 1e3:.2f} |")
    return "\n".join(lines)


def envelope_fit(data):
    """Per specimen: the RMS difference of the normalised backbone from
    (e/e_m) exp(1 - e/e_m) over the points past 0.2 e_m."""
    out = {}
    for s in data:
        pts = backbone(s["curve"])
        if not pts:
            continue
        sm, em = max(pts, key=lambda p: p[1])[1], \
            max(pts, key=lambda p: p[1])[0]
        if sm <= 0 or em <= 0:
            continue
        d = [(y / sm - (x / em) * math.exp(1 - x / em)) for x, y in pts
             if x > 0.2 * em]
        if d:
            pre = [(y / sm - (x / em) * math.exp(1 - x / em)) for x, y in pts
                   if 0.2 * em < x <= em]
            post = [(y / sm - (x / em) * math.exp(1 - x / em)) for x, y in pts
                    if x > em]
            out[s["name"]] = (
                math.sqrt(sum(v * v for v in pre) / len(pre)) if pre else None,
                math.sqrt(sum(v * v for v in post) / len(post)) if post
                else None,
                max(x for x, _ in pts) / em)
    return out


def backbone(curve):
    """The points of the curve that go beyond every earlier strain: the
    envelope of the cyclic curve (strain, stress in MPa)."""
    pts, reach = [], -1.0
    for p in curve:
        if p["strain"] > reach + 1e-12:
            reach = p["strain"]
            pts.append((p["strain"], p["stress_Pa"] / 1e6))
    return pts


def plots(directory, data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    present = [t for t in THICKNESSES if any(s["thickness"] == t
                                             for s in data)]
    # the stress-strain curves
    fig, axes = plt.subplots(1, len(present), figsize=(4.2 * len(present), 4),
                             sharey=True, squeeze=False)
    for ax, t in zip(axes[0], present):
        for s in data:
            if s["thickness"] != t or not s["curve"]:
                continue
            x = [1e3 * p["strain"] for p in s["curve"]]
            y = [p["stress_Pa"] / 1e6 for p in s["curve"]]
            ax.plot(x, y, lw=0.8, color=COLOURS.get(s["seed"], None),
                    label=f"seed {s['seed']} "
                          f"({s['row'].get('peak_stress_MPa', 0):.1f} MPa)")
        ax.set_title(f"{t} thickness")
        ax.set_xlabel("strain (platen displacement / height) [‰]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper right")
        ax.set_ylim(bottom=0)
        ax.set_xlim(left=0)
    axes[0][0].set_ylabel("stress (force / gross area) [MPa]")
    fig.suptitle("Wallettes under cyclic compression: three specimens per "
                 "thickness", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "study_curves.png"), dpi=120)
    plt.close(fig)

    # stiffness degradation
    styles = {"single": "o-", "double": "s--", "triple": "^:"}
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for s in data:
        c = [c for c in s["cycles"] if c["unloading_modulus_Pa"] > 0]
        if not c:
            continue
        ax.plot([1e3 * x["amplitude_strain"] for x in c],
                [x["stiffness_ratio"] for x in c], styles[s["thickness"]],
                color=COLOURS.get(s["seed"], None), ms=4, lw=1,
                label=s["name"])
    ax.set_xlabel("strain at the turning point of the cycle [‰]")
    ax.set_ylabel("unloading modulus / initial modulus")
    ax.set_ylim(0, 1.15)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=3, loc="lower left")
    ax.set_title("Stiffness degradation (o single, □ double, △ triple)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "study_degradation.png"), dpi=120)
    plt.close(fig)

    # normalised envelope
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    xi = np.linspace(0, 3, 301)
    ax.plot(xi, xi * np.exp(1 - xi), "k-", lw=2.2, alpha=0.6,
            label=r"$(\varepsilon/\varepsilon_m)\,e^{1-\varepsilon/"
                  r"\varepsilon_m}$")
    markers = {"single": "o", "double": "s", "triple": "^"}
    for s in data:
        pts = backbone(s["curve"])
        if not pts:
            continue
        em, sm = max(pts, key=lambda p: p[1])
        if em <= 0 or sm <= 0:
            continue
        ax.plot([x / em for x, _ in pts], [y / sm for _, y in pts],
                {"single": "-", "double": "--", "triple": ":"}[s["thickness"]],
                color=COLOURS.get(s["seed"], None), lw=1)
        env = s["envelope"]
        if env:
            ax.plot([e["envelope_strain"] / em for e in env],
                    [e["envelope_stress_Pa"] / 1e6 / sm for e in env],
                    markers[s["thickness"]], color=COLOURS.get(s["seed"], None),
                    ms=4, label=s["name"])
    ax.set_xlabel(r"$\varepsilon/\varepsilon_m$")
    ax.set_ylabel(r"$\sigma/\sigma_m$")
    ax.set_xlim(0, 3)
    ax.set_ylim(0, 1.15)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    ax.set_title("Envelope (lines: backbone of the curve; markers: cycle "
                 "peaks)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "study_envelope.png"), dpi=120)
    plt.close(fig)


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        print(__doc__, file=sys.stderr)
        return 2
    directory = os.path.abspath(argv[0])
    found = specimens(directory)
    if not found:
        print(f"report: error: no specimens (THICKNESS-SEED.prm) in "
              f"{directory}", file=sys.stderr)
        return 1
    data = [load(directory, t, seed) for t, seed in found]
    rows, table = write_tables(directory, data)
    fits = envelope_fit(data)
    fit_lines = []
    if fits:
        fit_lines = [
            "Envelope shape: RMS of σ/σ_m − (ε/ε_m) exp(1 − ε/ε_m) along the "
            "backbone (the curve where it goes beyond every earlier strain), "
            "before the peak (0.2 < ε/ε_m ≤ 1) and after it; last ε/ε_m "
            "reached.",
            "",
            "| specimen | RMS before peak | RMS after peak | last ε/ε_m |",
            "|---|---:|---:|---:|"]
        for name, (pre, post, reach) in fits.items():
            f = (lambda v: "" if v is None else f"{v:.3f}")
            fit_lines.append(f"| {name} | {f(pre)} | {f(post)} | "
                             f"{reach:.2f} |")
    quick = any("(--quick)" in open(os.path.join(directory, s["name"] +
                                                 ".prm")).readline()
                for s in data)
    text = [f"# Wallette study{' (--quick smoke run)' if quick else ''}",
            "",
            f"Written by contrib/study/report.py on "
            f"{time.strftime('%Y-%m-%d %H:%M')} from the runs in "
            f"{directory}. Stress = platen force / gross area, strain = "
            "platen displacement / height; E_0 = initial modulus (secant of "
            "the first step); E_u/E_0 = unloading modulus (secant from the "
            "turning point to the end of the unloading) over E_0, at the "
            "cycle with the highest peak and at the last cycle; CoV = sample "
            "standard deviation / mean over the completed specimens.",
            "", table, "", codes_table(data, rows), "", *fit_lines, "",
            "Plots: study_curves.png, study_degradation.png, "
            "study_envelope.png.", ""]
    bad = [s for s in data if s["row"]["status"] != "completed"]
    if bad:
        text.append("Runs that did not complete:")
        text.append("")
        for s in bad:
            msg = s["summary"].get("message") or s["summary"].get("error") \
                or ""
            text.append(f"- {s['name']}: status {s['row']['status']} {msg} "
                        f"(log: {s['log']})")
        text.append("")
    with open(os.path.join(directory, "study.md"), "w") as f:
        f.write("\n".join(text))
    plots(directory, data)
    print("\n".join(text))
    print(f"report: wrote study.md, study.csv, study_curves.png, "
          f"study_degradation.png, study_envelope.png in {directory}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
