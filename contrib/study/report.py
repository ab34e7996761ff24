#!/usr/bin/python3
"""Tables, targets and plots of the wallette study.

Usage: contrib/study/report.py STUDY_DIRECTORY

Reads NAME/summary.json, curve.csv, cycles.csv and envelope.csv (and
NAME.cpu, the run's CPU seconds) of every specimen NAME = THICKNESS-SEED and
every sweep pair NAME = sweep-fbF_B-fmF_M in the study directory (written by
contrib/study/run) and writes there:
  study.csv   one row per specimen, then mean and CoV per thickness
  sweep.csv   one row per sweep pair, with the codes' strengths
  study.md    the tables, the codes' strengths and every validation criterion
              that the runs measure, each marked met / NOT met
  study_curves.png       the stress-strain curves, one panel per thickness
  study_degradation.png  unloading modulus / initial modulus against strain
  study_envelope.png     sigma/sigma_m against eps/eps_m of the envelope
                         with (eps/eps_m) exp(1 - eps/eps_m)
  sweep_strength.png     sweep peak against f_b per f_m, with EC6 f_k,
                         1.2 f_k, Kaushik et al. and the target band
  sweep_modulus.png      sweep initial modulus against 550 f'_m (+-40 %)
Needs /usr/bin/python3 with matplotlib and numpy.
"""
import csv
import json
import math
import os
import re
import sys
import time

import bonded

THICKNESSES = ("single", "double", "triple")
COLOURS = {1: "tab:blue", 2: "tab:orange", 3: "tab:green"}
# Eurocode 6 (EN 1996-1-1 Eq. 3.1, Table 3.3) and Kaushik, Rai & Jain 2007;
# what was confirmed and what is recalled: doc/references-brickwork-strength.md
EC6_K = 0.55          # clay units, group 1, general purpose mortar (recalled)
EC6_ALPHA, EC6_BETA = 0.7, 0.3  # exponents (confirmed)
EC6_LONGITUDINAL = 0.8  # factor on K with a longitudinal joint (recalled)
EC6_MEAN = 1.2          # mean / characteristic strength, EN 1052-1 (recalled)
EC6_KE = 1000           # E = 1000 f_k (confirmed, second-hand)
KAUSHIK = (0.63, 0.49, 0.32)  # f'_m = 0.63 f_b^0.49 f_j^0.32 (confirmed)
KAUSHIK_E = 550         # E = 550 f'_m (recalled)
MORTAR_STRENGTH = 5.0   # MPa, f_m of the examples' mortar
# the validation criteria (doc/brickwork.md, Validation)
BAND = (0.85, 1.15)     # Kaushik - 15 % to EC6 mean + 15 %
RATIO = (0.70, 0.90)    # double / single, triple / single peak
RMS_MAX = 0.12          # envelope RMS, before and after the peak
RMS_REACH = 2.0         # ... over 0.2 < eps/eps_m <= 2
MODULUS_TOL = 0.40      # initial modulus within 40 % of 550 f'_m


def ec6_fk(f_b, f_m, longitudinal=False):
    """EC6 characteristic strength, MPa."""
    k = EC6_K * (EC6_LONGITUDINAL if longitudinal else 1.0)
    return k * f_b ** EC6_ALPHA * f_m ** EC6_BETA


def kaushik(f_b, f_m):
    """Kaushik et al.'s mean prism strength, MPa."""
    c, a, b = KAUSHIK
    return c * f_b ** a * f_m ** b


def mark(ok):
    return "met" if ok else "**NOT met**"


def read_cpu(directory, name):
    try:
        return float(open(os.path.join(directory, name + ".cpu")).read())
    except (OSError, ValueError):
        return None


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
    cpu = read_cpu(directory, name)
    if cpu is not None:
        row["cpu_seconds"] = cpu
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
    ("cpu_seconds", "CPU s", "{:.0f}"),
]
STATISTICS = COLUMNS[:7] + COLUMNS[9:11]


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
        f"strength') and f_m = f_j = {f_m:g} MPa (the examples' mortar: "
        "the detailed model's mortar cells; the simplified model takes it "
        "only through the joint stiffness). "
        "Eurocode 6 gives the characteristic (5 %) strength f_k = K f_b^0.7 "
        f"f_m^0.3 with K = {EC6_K} (clay, group 1; recalled), times "
        f"{EC6_LONGITUDINAL} with a longitudinal joint (double, triple; "
        f"recalled), and the mean {EC6_MEAN} f_k (EN 1052-1; recalled); "
        "Kaushik, Rai & Jain 2007 give the mean f'_m = 0.63 f_b^0.49 "
        "f_j^0.32 (confirmed) and E = 550 f'_m (recalled); EC6's E = 1000 "
        "f_k. Sources: doc/references-brickwork-strength.md.",
        "",
        "| thickness | model mean peak MPa | EC6 f_k MPa | EC6 mean MPa | "
        "model / EC6 mean | Kaushik f'_m MPa | model / f'_m | model E_0 GPa "
        "| 550 f'_m GPa | 1000 f_k GPa |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for t in THICKNESSES:
        mean = next((r for r in rows if r["specimen"] == f"{t} mean"), None)
        if not mean or "peak_stress_MPa" not in mean:
            continue
        f_k = ec6_fk(f_b, f_m, t != "single")
        f_kaushik = kaushik(f_b, f_m)
        peak = mean["peak_stress_MPa"]
        lines.append(
            f"| {t} | {peak:.2f} | {f_k:.2f} | {EC6_MEAN * f_k:.2f} | "
            f"{peak / (EC6_MEAN * f_k):.2f} | "
            f"{f_kaushik:.2f} | {peak / f_kaushik:.2f} | "
            f"{mean.get('initial_modulus_GPa', float('nan')):.2f} | "
            f"{KAUSHIK_E * f_kaushik / 1e3:.2f} | "
            f"{EC6_KE * f_k / 1e3:.2f} |")
    return "\n".join(lines)


def envelope_fit(data):
    """Per specimen: the RMS difference of the normalised backbone from
    (e/e_m) exp(1 - e/e_m) over its points with 0.2 < e/e_m <= 1 (before
    the peak) and 1 < e/e_m <= 2 (after it), and the last e/e_m reached."""
    out = {}
    for s in data:
        pts = backbone(s["curve"])
        if not pts:
            continue
        em, sm = max(pts, key=lambda p: p[1])
        if sm <= 0 or em <= 0:
            continue

        def rms(lo, hi):
            d = [y / sm - (x / em) * math.exp(1 - x / em) for x, y in pts
                 if lo < x / em <= hi]
            return math.sqrt(sum(v * v for v in d) / len(d)) if d else None
        out[s["name"]] = (rms(0.2, 1.0), rms(1.0, RMS_REACH),
                          max(x for x, _ in pts) / em)
    return out


def sweep_pairs(directory):
    found = []
    for name in sorted(os.listdir(directory)):
        m = re.fullmatch(r"sweep-fb([0-9.]+)-fm([0-9.]+)\.prm", name)
        if m:
            found.append((float(m.group(1)), float(m.group(2))))
    return sorted(found)


def sweep_header_inputs(prm):
    """The inputs `NAME = VALUE' (SI) that study.py wrote into the header
    comment of a sweep pair's parameter file (E_b, E_m, ...)."""
    out = {}
    try:
        with open(prm) as f:
            head = "".join(line for _, line in zip(range(3), f))
    except OSError:
        return out
    for m in re.finditer(r"\b(E_b|E_m|f_bt|f_mt|G_bt|G_bc) = ([0-9.e+-]+)",
                         head):
        out.setdefault(m.group(1), float(m.group(2)))
    m = re.search(r"\bmesh (\d+x\d+x\d+)", head)
    if m:
        out["mesh"] = m.group(1)
    return out


def series_modulus(E_b, E_m, h_b=0.065, h_m=0.010):
    """Modulus of a stack of units and bed joints loaded in series (each
    layer free to expand laterally): (h_b + h_m) / (h_b/E_b + h_m/E_m). An
    independent estimate of what the unit and mortar moduli give, without
    the lateral restraint of the layers and platens (which stiffens)."""
    return (h_b + h_m) / (h_b / E_b + h_m / E_m)


def load_sweep(directory, f_b, f_m):
    name = f"sweep-fb{f_b:g}-fm{f_m:g}"
    out = os.path.join(directory, name)
    try:
        with open(os.path.join(out, "summary.json")) as f:
            j = json.load(f)
    except (OSError, ValueError):
        j = {"status": "no summary.json"}
    curve = read_csv(os.path.join(out, "curve.csv"))
    inputs = sweep_header_inputs(os.path.join(directory, name + ".prm"))
    E_b = inputs.get("E_b", 500 * f_b * 1e6)
    E_m = inputs.get("E_m", 200 * f_m * 1e6)
    r = {"name": name, "f_b": f_b, "f_m": f_m, "status": j.get("status", "?"),
         "mesh": inputs.get("mesh"),
         "E_m_GPa": E_m / 1e9, "E_b_GPa": E_b / 1e9,
         "E_series_GPa": series_modulus(E_b, E_m) / 1e9,
         "cpu_seconds": read_cpu(directory, name),
         "kaushik_MPa": kaushik(f_b, f_m), "ec6_fk_MPa": ec6_fk(f_b, f_m)}
    r["ec6_mean_MPa"] = EC6_MEAN * r["ec6_fk_MPa"]
    r["band_low_MPa"] = BAND[0] * r["kaushik_MPa"]
    r["band_high_MPa"] = BAND[1] * r["ec6_mean_MPa"]
    r["E_kaushik_GPa"] = KAUSHIK_E * r["kaushik_MPa"] / 1e3
    if curve:
        peak = max(curve, key=lambda p: p["stress_Pa"])
        r["peak_MPa"] = peak["stress_Pa"] / 1e6
        r["strain_at_peak"] = peak["strain"]
        # a peak at the last step is a lower bound, not the strength
        r["peak_reached"] = peak is not curve[-1] and \
            curve[-1]["stress_Pa"] < 0.98 * peak["stress_Pa"]
        r["in_band"] = r["peak_reached"] and \
            r["band_low_MPa"] <= r["peak_MPa"] <= r["band_high_MPa"]
    if "initial_modulus" in j:
        r["E0_GPa"] = j["initial_modulus"] / 1e9
        r["modulus_ratio"] = r["E0_GPa"] / r["E_kaushik_GPa"]
        r["modulus_ok"] = abs(r["modulus_ratio"] - 1) <= MODULUS_TOL
        if r.get("peak_reached"):
            # Kaushik's relation read as a property of one prism: its
            # modulus against 550 times its own strength, here the model's
            r["modulus_own_ratio"] = r["E0_GPa"] / (
                KAUSHIK_E * r["peak_MPa"] / 1e3)
            r["modulus_own_ok"] = \
                abs(r["modulus_own_ratio"] - 1) <= MODULUS_TOL
    r["curve"] = curve
    return r


SWEEP_KEYS = ["name", "mesh", "f_b", "f_m", "E_b_GPa", "E_m_GPa", "peak_MPa", "strain_at_peak",
              "peak_reached",
              "kaushik_MPa", "ec6_fk_MPa", "ec6_mean_MPa", "band_low_MPa",
              "band_high_MPa", "in_band", "E0_GPa", "E_series_GPa",
              "E_kaushik_GPa",
              "modulus_ratio", "modulus_ok", "modulus_own_ratio",
              "modulus_own_ok", "cpu_seconds", "status"]


def power_fit(sweep):
    """Least-squares fit of log peak = log C + a log f_b + b log f_m over
    the pairs that reached a peak (a run that stopped after its peak, by
    `Maximum steps' or a failed step, counts): (C, a, b), or None with
    fewer than 3 pairs."""
    import numpy as np
    ok = [r for r in sweep if r.get("peak_MPa", 0) > 0 and
          r.get("peak_reached")]
    if len(ok) < 3 or len({r["f_b"] for r in ok}) < 2 or \
            len({r["f_m"] for r in ok}) < 2:
        return None
    A = np.array([[1, math.log(r["f_b"]), math.log(r["f_m"])] for r in ok])
    y = np.array([math.log(r["peak_MPa"]) for r in ok])
    c, a, b = np.linalg.lstsq(A, y, rcond=None)[0]
    return math.exp(c), a, b


def sweep_section(directory, sweep):
    keys = SWEEP_KEYS
    with open(os.path.join(directory, "sweep.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in sweep:
            w.writerow(["" if r.get(k) is None else r.get(k) for k in keys])
    f = (lambda v, fmt="{:.2f}": "" if v is None else fmt.format(v))
    meshes = sorted({r["mesh"] for r in sweep if r.get("mesh")})
    mesh_text = (f"Mesh: {', '.join(meshes)} cells per unit + joint (length "
                 "x width x height; study.py --sweep-mesh). " if meshes
                 else "")
    lines = [
        "## Single-leaf sweep",
        "",
        "The single-leaf wallette run monotonic past the peak (to the "
        "strain in each sweep-*.prm) for every pair of unit strength f_b "
        "and mortar strength f_m; the other unit and mortar inputs follow "
        "from f_b and f_m by the relations of contrib/study/study.py, "
        "sweep_inputs() (unit: the normalised strength f_b, from which "
        "the law derives its uniaxial strength 0.8 f_b, E_b = 400 f_b, "
        "tensile strength 0.1 f_b; mortar E_m = 200 f_m, compressive "
        "softening with the crushing energy 15 + 0.43 f_m - 0.0036 f_m² "
        "N/mm; the values of each pair: the header of "
        "its sweep-*.prm; sources: doc/references-brickwork-strength.md). "
        f"{mesh_text}Target band: "
        f"{BAND[0]} × Kaushik to {BAND[1]} × EC6 mean; modulus within "
        f"±{100 * MODULUS_TOL:.0f} % of 550 f'_m. E_series = "
        "(h_b + h_m)/(h_b/E_b + h_m/E_m), the unit and mortar moduli in "
        "series (no lateral restraint): what the inputs alone give. "
        "E_0 / 550 peak: the same relation applied to the model's own "
        "peak (Kaushik's E = 550 f'_m relates a prism's modulus to that "
        "prism's strength); E_0 / 550 f'_m takes Kaushik's predicted "
        "strength instead, so it also carries the strength's error.",
        "",
        "A peak marked * is at the end of the run (the stress still "
        "rising or within 2 % of it): a lower bound, counted as not met and "
        "left out of the fit.",
        "",
        "| f_b MPa | f_m MPa | E_b GPa | E_m GPa | model peak MPa | "
        "Kaushik MPa | EC6 f_k MPa | EC6 mean MPa | band MPa | peak in band | "
        "E_0 GPa | E_series GPa | 550 f'_m GPa | E_0 / 550 f'_m | modulus | "
        "E_0 / 550 peak | modulus (own peak) | CPU s | status |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|---:|---:|"
        "---:|---|---:|---|---:|---|"]
    for r in sweep:
        lines.append(
            f"| {r['f_b']:g} | {r['f_m']:g} | {r['E_b_GPa']:.1f} | "
            f"{r['E_m_GPa']:.1f} | "
            f"{f(r.get('peak_MPa'))}{'' if r.get('peak_reached') else '*'}"
            f" | {r['kaushik_MPa']:.2f} | "
            f"{r['ec6_fk_MPa']:.2f} | {r['ec6_mean_MPa']:.2f} | "
            f"{r['band_low_MPa']:.1f}–{r['band_high_MPa']:.1f} | "
            f"{mark(r.get('in_band', False))} | {f(r.get('E0_GPa'))} | "
            f"{r['E_series_GPa']:.2f} | "
            f"{r['E_kaushik_GPa']:.2f} | {f(r.get('modulus_ratio'))} | "
            f"{mark(r.get('modulus_ok', False))} | "
            f"{f(r.get('modulus_own_ratio'))} | "
            f"{mark(r.get('modulus_own_ok', False))} | "
            f"{f(r.get('cpu_seconds'), '{:.1f}')} | {r['status']} |")
    return lines


def targets(data, rows, fits, sweep, fit):
    """The met / not met lines of the targets the runs measure."""
    out = ["## Validation criteria measured by these runs", ""]
    if sweep:
        n = len(sweep)
        inside = [r for r in sweep if r.get("in_band")]
        ratios = [r["peak_MPa"] / r["band_high_MPa"] for r in sweep
                  if "peak_MPa" in r]
        out.append(
            f"- {mark(len(inside) == n)}: single leaf, all {n} (f_b, f_m) "
            f"pairs with the peak between {BAND[0]} × Kaushik and "
            f"{BAND[1]} × EC6 mean: {len(inside)} of {n} inside"
            + (f"; peak / upper end {min(ratios):.2f}–{max(ratios):.2f}"
               if ratios else "") + ".")
        if fit:
            c, a, b = fit
            lo_a, hi_a = min(KAUSHIK[1], EC6_ALPHA), max(KAUSHIK[1],
                                                         EC6_ALPHA)
            lo_b, hi_b = min(KAUSHIK[2], EC6_BETA), max(KAUSHIK[2], EC6_BETA)
            ok = lo_a / 3 <= a <= 3 * hi_a and lo_b / 3 <= b <= 3 * hi_b
            out.append(
                f"- {mark(ok)}: power-law fit of the model's peak, "
                f"{c:.3g} f_b^{a:.3f} f_m^{b:.3f}, against EC6 (0.7, 0.3) "
                "and Kaushik (0.49, 0.32); criterion: both exponents "
                "positive and within a factor 3 of the codes' range.")
        else:
            out.append("- not measured: power-law fit (fewer than 3 "
                       "completed pairs over two f_b and two f_m).")
        good = [r for r in sweep if r.get("modulus_ok")]
        mr = [r["modulus_ratio"] for r in sweep if "modulus_ratio" in r]
        out.append(
            f"- {mark(len(good) == n)}: initial modulus within "
            f"±{100 * MODULUS_TOL:.0f} % of 550 f'_m for every pair: "
            f"{len(good)} of {n}"
            + (f"; E_0 / 550 f'_m = {min(mr):.2f}–{max(mr):.2f}" if mr
               else "") + " (f'_m: Kaushik's predicted strength).")
        own = [r for r in sweep if r.get("modulus_own_ok")]
        mo = [r["modulus_own_ratio"] for r in sweep
              if "modulus_own_ratio" in r]
        out.append(
            f"- {mark(len(own) == n)}: the same with f'_m = the model's own "
            f"peak (Kaushik's relation between one prism's modulus and its "
            f"strength): {len(own)} of {n}"
            + (f"; E_0 / (550 × peak) = {min(mo):.2f}–{max(mo):.2f}" if mo
               else "") + ".")
    means = {r["thickness"]: r.get("peak_stress_MPa") for r in rows
             if r["specimen"].endswith(" mean")}
    if means.get("single"):
        for t in ("double", "triple"):
            if means.get(t):
                q = means[t] / means["single"]
                out.append(
                    f"- {mark(RATIO[0] <= q <= RATIO[1])}: {t} / single "
                    f"mean peak = {means[t]:.2f} / {means['single']:.2f} = "
                    f"{q:.3f} (target {RATIO[0]}–{RATIO[1]}).")
    if fits:
        bad = [n for n, (pre, post, reach) in fits.items()
               if pre is None or post is None or pre > RMS_MAX or
               post > RMS_MAX]
        pres = [v[0] for v in fits.values() if v[0] is not None]
        posts = [v[1] for v in fits.values() if v[1] is not None]
        out.append(
            f"- {mark(not bad)}: envelope RMS of σ/σ_m − (ε/ε_m) exp(1 − "
            f"ε/ε_m) ≤ {RMS_MAX} over 0.2 < ε/ε_m ≤ {RMS_REACH:g}, before "
            f"and after the peak, for every specimen: "
            f"{len(fits) - len(bad)} of {len(fits)} meet it"
            + (f"; before {min(pres):.3f}–{max(pres):.3f}" if pres else "")
            + (f", after {min(posts):.3f}–{max(posts):.3f}" if posts else
               ", no point after the peak") + ".")
    out.append("")
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


def sweep_plots(directory, sweep, fit):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.ticker import NullFormatter

    fms = sorted({r["f_m"] for r in sweep})
    fig, axes = plt.subplots(1, len(fms), figsize=(4.2 * len(fms), 4.2),
                             sharey=True, squeeze=False)
    fb = np.geomspace(min(r["f_b"] for r in sweep) * 0.9,
                      max(r["f_b"] for r in sweep) * 1.1, 50)
    for ax, f_m in zip(axes[0], fms):
        k = kaushik(fb, f_m)
        e = ec6_fk(fb, f_m)
        ax.fill_between(fb, BAND[0] * k, BAND[1] * EC6_MEAN * e,
                        color="tab:green", alpha=0.15,
                        label="target band")
        ax.plot(fb, e, "k--", lw=1, label="EC6 f_k")
        ax.plot(fb, EC6_MEAN * e, "k-", lw=1.2,
                label=f"EC6 mean {EC6_MEAN} f_k")
        ax.plot(fb, k, "b:", lw=1.5, label="Kaushik et al. f'_m")
        ax.plot(fb, fb, color="0.6", lw=0.8, label="f_b")
        if fit:
            c, a, b = fit
            ax.plot(fb, c * fb ** a * f_m ** b, "r-", lw=0.8, alpha=0.7,
                    label=f"fit {c:.2g} f_b^{a:.2f} f_m^{b:.2f}")
        pts = [r for r in sweep if r["f_m"] == f_m and "peak_MPa" in r]
        ax.plot([r["f_b"] for r in pts], [r["peak_MPa"] for r in pts],
                "ro", ms=6, label="model peak")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.yaxis.set_minor_formatter(NullFormatter())
        ax.set_xticks([10, 20, 40])
        ax.set_xticklabels(["10", "20", "40"])
        ax.set_yticks([2, 5, 10, 20, 40])
        ax.set_yticklabels(["2", "5", "10", "20", "40"])
        ax.set_title(f"f_m = {f_m:g} MPa", fontsize=10)
        ax.set_xlabel("unit strength f_b [MPa]")
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("compressive strength [MPa]")
    axes[0][-1].legend(fontsize=7, loc="upper left")
    fig.suptitle("Single-leaf wallette: model peak against the codes",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "sweep_strength.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5.2, 4.6))
    pts = [r for r in sweep if "E0_GPa" in r]
    top = max([r["E_kaushik_GPa"] for r in sweep] +
              [r["E0_GPa"] / r["modulus_own_ratio"] for r in pts
               if "modulus_own_ratio" in r] +
              [r["E0_GPa"] for r in pts] + [1]) * 1.2
    x = np.linspace(0, top, 10)
    ax.fill_between(x, (1 - MODULUS_TOL) * x, (1 + MODULUS_TOL) * x,
                    color="tab:green", alpha=0.15, label="±40 %")
    ax.plot(x, x, "k-", lw=1)
    for r in pts:
        ax.plot(r["E_kaushik_GPa"], r["E0_GPa"], "o",
                color={10.0: "tab:blue", 20.0: "tab:orange",
                       40.0: "tab:red"}.get(r["f_b"], "k"), ms=6)
        ax.annotate(f"{r['f_b']:g}/{r['f_m']:g}",
                    (r["E_kaushik_GPa"], r["E0_GPa"]), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
        if "modulus_own_ratio" in r:
            ax.plot(r["E0_GPa"] / r["modulus_own_ratio"], r["E0_GPa"], "o",
                    mfc="none",
                    color={10.0: "tab:blue", 20.0: "tab:orange",
                           40.0: "tab:red"}.get(r["f_b"], "k"), ms=6)
    ax.set_xlim(0, top)
    ax.set_ylim(0, top)
    ax.set_xlabel("550 f'_m [GPa]: filled f'_m Kaushik et al., "
                  "open f'_m = model peak", fontsize=8)
    ax.set_ylabel("model initial modulus E_0 [GPa]")
    ax.set_title("Initial modulus (labels f_b/f_m in MPa)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "sweep_modulus.png"), dpi=110)
    plt.close(fig)


def bonded_mesh_note(directory):
    """The note ", mesh LxWxH cells per unit + joint" of the bonded runs,
    from the header of the first one's parameter file ("" without)."""
    for name in sorted(os.listdir(directory)):
        if name.startswith("bonded-") and name.endswith(".prm"):
            with open(os.path.join(directory, name)) as f:
                m = re.search(r"\bmesh (\d+x\d+x\d+)", f.readline())
            return f", mesh {m.group(1)} cells per unit + joint" if m else ""
    return ""


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        print(__doc__, file=sys.stderr)
        return 2
    directory = os.path.abspath(argv[0])
    found = specimens(directory)
    pairs = sweep_pairs(directory)
    bonded_lines = bonded.section(directory, bonded_mesh_note(directory))
    if not found and not pairs and not bonded_lines:
        print(f"report: error: no specimens (THICKNESS-SEED.prm), no sweep "
              f"pairs (sweep-fbF_B-fmF_M.prm) and no bonded runs "
              f"(bonded-THICKNESS-fbF_B-fmF_M.prm) in {directory}",
              file=sys.stderr)
        return 1
    data = [load(directory, t, seed) for t, seed in found]
    sweep = [load_sweep(directory, f_b, f_m) for f_b, f_m in pairs]
    rows, table = write_tables(directory, data) if data else ([], "")
    fits = envelope_fit(data)
    fit = power_fit(sweep) if sweep else None
    fit_lines = []
    if fits:
        fit_lines = [
            "Envelope shape: RMS of σ/σ_m − (ε/ε_m) exp(1 − ε/ε_m) along the "
            "backbone (the curve where it goes beyond every earlier strain), "
            f"before the peak (0.2 < ε/ε_m ≤ 1) and after it (1 < ε/ε_m ≤ "
            f"{RMS_REACH:g}); last ε/ε_m reached.",
            "",
            "| specimen | RMS before peak | RMS after peak | last ε/ε_m | "
            f"≤ {RMS_MAX} |",
            "|---|---:|---:|---:|---|"]
        for name, (pre, post, reach) in fits.items():
            f = (lambda v: "" if v is None else f"{v:.3f}")
            ok = pre is not None and post is not None and pre <= RMS_MAX \
                and post <= RMS_MAX
            fit_lines.append(f"| {name} | {f(pre)} | {f(post)} | "
                             f"{reach:.2f} | {mark(ok)} |")
    names = [s["name"] for s in data] + [r["name"] for r in sweep]
    # the bonded part's runs say their model too
    names += sorted(f[:-4] for f in os.listdir(directory)
                    if f.startswith("bonded-") and f.endswith(".prm"))
    headers = [open(os.path.join(directory, n + ".prm")).readline()
               for n in names]
    quick = any("(--quick)" in h for h in headers)
    models = sorted({m.group(1) for h in headers
                     for m in [re.search(r"model (\w+)", h)] if m})
    cpu = [v for v in [s["row"].get("cpu_seconds") for s in data] +
           [r.get("cpu_seconds") for r in sweep] if v is not None]
    text = [f"# Wallette study{' (--quick smoke run)' if quick else ''}",
            "",
            f"Written by contrib/study/report.py on "
            f"{time.strftime('%Y-%m-%d %H:%M')} from the runs in the "
            f"study directory `{os.path.basename(directory)}'; model: {', '.join(models) or 'simplified'}. "
            "Stress = platen force / gross area, strain = "
            "platen displacement / height; E_0 = initial modulus (secant of "
            "the first step); E_u/E_0 = unloading modulus (secant from the "
            "turning point to the end of the unloading) over E_0, at the "
            "cycle with the highest peak and at the last cycle; CoV = sample "
            "standard deviation / mean over the completed specimens; CPU s = "
            "user + system seconds of the run (1 rank)"
            + (f"; all runs together {sum(cpu):.0f} CPU s" if cpu else "")
            + ".", ""]
    text += targets(data, rows, fits, sweep, fit)
    if data:
        text += ["## The specimens", "", table, "", codes_table(data, rows),
                 "", *fit_lines, "",
                 "Plots: study_curves.png, study_degradation.png, "
                 "study_envelope.png"
                 + ("; the failed wallette of each specimen: "
                    "NAME/failure.png" if any(os.path.exists(os.path.join(
                        directory, s["name"], "failure.png")) for s in data)
                    else "") + ".", ""]
    if sweep:
        text += sweep_section(directory, sweep)
        text += ["", "Plots: sweep_strength.png, sweep_modulus.png.", ""]
    text += bonded_lines
    bad = [(s["name"], s["row"]["status"], s["summary"], s["log"])
           for s in data if s["row"]["status"] != "completed"]
    bad += [(r["name"], r["status"], {}, os.path.join(directory,
                                                      r["name"] + ".log"))
            for r in sweep if r["status"] != "completed"]
    if bad:
        text.append("Runs that did not complete:")
        text.append("")
        for name, status, summary, log in bad:
            msg = summary.get("message") or summary.get("error") or ""
            text.append(f"- {name}: status {status} {msg} (log: "
                        f"{os.path.basename(log)})")
        text.append("")
    with open(os.path.join(directory, "study.md"), "w") as f:
        f.write("\n".join(text))
    written = ["study.md"]
    if data:
        plots(directory, data)
        written += ["study.csv", "study_curves.png", "study_degradation.png",
                    "study_envelope.png"]
    if sweep:
        sweep_plots(directory, sweep, fit)
        written += ["sweep.csv", "sweep_strength.png", "sweep_modulus.png"]
    if bonded_lines:
        written.append("bonded.csv")
    print("\n".join(text))
    print(f"report: wrote {', '.join(written)} in {directory}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
