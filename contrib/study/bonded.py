"""The `bonded' part of the wallette study: the thickness ratios double /
single and triple / single of the monotonic examples for every (f_b, f_m)
pair of the sweep (runs bonded-THICKNESS-fbF_B-fmF_M, written by study.py).

The validation asks for ratios of 0.70-0.90 on the nine cyclic specimens (f_b =
20, f_m = 5 MPa); this part measures whether the model's ratio depends on
the unit and mortar at all, i.e. whether any laboratory input of the sweep
makes a bonded wall weaker than its leaves' share of the plan."""
import csv
import os
import re

RATIO = (0.70, 0.90)  # the validation band for double / single, triple / single


def runs(directory):
    """{(f_b, f_m): {thickness: peak MPa or None}} of the bonded-* runs."""
    found = {}
    for name in sorted(os.listdir(directory)):
        m = re.fullmatch(r"bonded-(single|double|triple)-fb([0-9.]+)-fm"
                         r"([0-9.]+)\.prm", name)
        if m:
            pair = (float(m.group(2)), float(m.group(3)))
            found.setdefault(pair, {})[m.group(1)] = peak(
                os.path.join(directory, name[:-4], "curve.csv"))
    return found


def peak(path):
    """The largest stress (MPa) of a curve.csv that falls at least 2 %
    below it afterwards (a peak passed); None otherwise."""
    try:
        with open(path) as f:
            stress = [float(r["stress_Pa"]) for r in csv.DictReader(f)]
    except (OSError, KeyError, ValueError):
        return None
    if not stress:
        return None
    top = max(stress)
    passed = stress[-1] < 0.98 * top
    return top / 1e6 if passed else None


def section(directory, mesh_note=""):
    """Markdown lines of the bonded part (empty without bonded-* runs);
    writes bonded.csv."""
    found = runs(directory)
    if not found:
        return []
    rows = []
    for (f_b, f_m), p in sorted(found.items()):
        r = {"f_b": f_b, "f_m": f_m}
        for t in ("single", "double", "triple"):
            r[t] = p.get(t)
        for t in ("double", "triple"):
            if r["single"] and r[t]:
                r[t + "_ratio"] = r[t] / r["single"]
        rows.append(r)
    keys = ["f_b", "f_m", "single", "double", "triple", "double_ratio",
            "triple_ratio"]
    with open(os.path.join(directory, "bonded.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([r.get(k, "") for k in keys])

    def f(v, fmt):
        return "–" if v is None else format(v, fmt)

    def inside(v):
        return v is not None and RATIO[0] <= v <= RATIO[1]

    ratios = [r.get(k) for r in rows for k in ("double_ratio",
                                               "triple_ratio")]
    ratios = [v for v in ratios if v is not None]
    lines = ["## Bonded walls across the sweep", "",
             "The single, double and triple monotonic examples "
             "(prm/examples/wallette-THICKNESS-monotonic.prm) with the unit "
             "and mortar inputs of every sweep pair (study.py, "
             f"sweep_inputs()){mesh_note}; peak = the largest stress, counted "
             "only where the curve then falls 2 % below it (– otherwise). "
             "The validation band for the ratios: "
             f"{RATIO[0]:g}–{RATIO[1]:g}.", "",
             "| f_b MPa | f_m MPa | single MPa | double MPa | triple MPa | "
             "double / single | triple / single |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(
            f"| {r['f_b']:g} | {r['f_m']:g} | {f(r['single'], '.2f')} | "
            f"{f(r['double'], '.2f')} | {f(r['triple'], '.2f')} | "
            f"{f(r.get('double_ratio'), '.3f')} | "
            f"{f(r.get('triple_ratio'), '.3f')} |")
    if ratios:
        lines += ["", f"Ratios {min(ratios):.3f}–{max(ratios):.3f}; "
                  f"{sum(inside(v) for v in ratios)} of {len(ratios)} "
                  f"inside {RATIO[0]:g}–{RATIO[1]:g}.", ""]
    return lines
