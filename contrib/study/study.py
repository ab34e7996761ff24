#!/usr/bin/python3
"""Run the wallette study (called by contrib/study/run, which documents
the options): (a) the nine specimens, per thickness and seed a copy of the
cyclic example parameter file with the seed and the output directory
changed (with the detailed model, the default, see detailed_specimen());
(b) the single-leaf sweep over the unit strength f_b and the mortar
strength f_m: a monotonic copy of the single-leaf monotonic example
prm/examples/wallette-single-monotonic.prm (detailed model: the sweep's
f_b = 20, f_m = 5 MPa pair is that example with a longer target strain)
or of the single-leaf cyclic example (simplified model) with the
unit and mortar inputs of each pair (see sweep_inputs()); each a 1-rank
masonry run, several at a time, with its CPU time recorded; then report.py
writes the tables, the validation criteria and the plots."""
import argparse
import json
import math
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

# the validation sweep: unit strength f_b x mortar strength f_m, MPa
SWEEP_FB = (10.0, 20.0, 40.0)
SWEEP_FM = (2.0, 5.0, 12.0)
# the sweep runs monotonic past the peak (sweep_target()), nominal step
# 1e-4 (--quick: 2e-4 on the coarsest mesh)
SWEEP = {"Protocol": "monotonic", "Write VTU": "false"}
SWEEP_STEP = 1e-4
SWEEP_QUICK = dict(SWEEP, **{"Elements along the length": "2",
                             "Elements along the width": "1",
                             "Elements along the height": "1"})
SWEEP_QUICK_STEP = 2e-4
# the detailed sweep stops after this many times the nominal number of steps
SWEEP_STEP_CAP = 3
# ... the bonded part after this many: the double and triple walls with the
# examples' collar bed gap soften slowly past their peak and took up to 6.8
# times the nominal number of steps to the end of their run (2026-12-05:
# four of nine triple walls stopped at 3 times, before their curve fell
# 2 % below their peak)
BONDED_STEP_CAP = 8
# ... or once the stress has fallen below half its peak (`Collapse stress
# ratio' r: the stress below r x the peak and more than r x the peak below
# the largest stress of the loading leg, i.e. below min(r, 1 - r) x the peak
# in a monotonic run, so 0.5 is the largest useful value; status completed).
# The sweep's targets need the peak and the initial modulus only. In the
# 2026-11-29b runs, which went on to the target strain, no pair came back
# above its peak after falling below half of it, and the steps after that
# point took about a third of the sweep's CPU time (most of it 40/5's)
SWEEP_COLLAPSE_RATIO = 0.5
# the detailed sweep's mesh, cells per unit + joint along its length, width
# and height (--sweep-mesh): finer than the example's 4x2x2, whose peak lies
# 2.3 % above 6x3x3 and 5.0 % above 8x4x4 (single leaf, f_b = 20, f_m = 5
# MPa; contrib/benchmarks/wallette_convergence/README.md): the sweep
# compares strengths with a band, so it takes the finer mesh (sweep CPU 3.3 x the example mesh's,
# 9724a05:contrib/study/results-2026-11-29b)
SWEEP_MESH = "6x3x3"
# the detailed model's sweep and the mortar and bond of a specimen turned
# detailed come from the single-leaf monotonic example
DETAILED_BASE = os.path.join(root, "prm", "examples",
                             "wallette-single-monotonic.prm")
# the `bonded' part: every sweep pair in the single, double and triple
# monotonic examples, on this mesh (--bonded-mesh): the coarsest, 2x1x1,
# where the example mesh's ratios double / single and triple / single are
# within 1 % (0.952 / 0.956 against 0.956 / 0.965,
# doc/notes/bonded-wall-strength.md) and a triple wall takes 33-159 CPU s
# (9724a05:contrib/study/results-2026-11-29d) instead of about 450-550 on
# the example mesh
BONDED_MESH = "2x1x1"


def sweep_target(f_b, E_m, h_b, h_m):
    """Target strain of a sweep pair: 1.5 times the unit's strain at peak
    (0.004, the examples') plus the strain of the mortar joints at f_b
    (f_b h_m / ((h_b + h_m) E_m)), in [0.006, 0.03]: a soft mortar moves
    the peak far out (f_m = 2 MPa: E_m = 0.4 GPa)."""
    joint = f_b * h_m / ((h_b + h_m) * E_m)
    return min(0.03, max(0.006, 1.5 * (0.004 + joint)))
# the specimens' failure.png: small enough to keep with the results
FAILURE_PLOT = {"Width": "1200", "Height": "600"}
# --model: the entry of subsection Wallette that selects the model
MODEL_ENTRY = "Model"


def mortar_modulus(f_m):
    """E_m, Pa, of a mortar of compressive strength f_m (MPa): E_m = 200 f_m,
    the middle of the linear relation Kaushik et al. (2007) report for
    cement-lime mortars (recalled, see doc/references-brickwork-strength.md)."""
    return 200.0 * f_m * 1e6


def crushing_energy(f):
    """Compressive fracture energy, J/m^2, of a material of compressive
    strength f (MPa): G_c = 15 + 0.43 f - 0.0036 f^2 N/mm, the relation
    Lourenco (1996) recommends for masonry after Vonk's concrete tests
    (recalled, not confirmed; doc/references-brickwork-strength.md); used
    for the unit (f = f_b) and for the mortar (f = f_m)."""
    return (15 + 0.43 * f - 0.0036 * f ** 2) * 1e3


def sweep_inputs(f_b, f_m, nu_b=0.15, nu_m=0.2):
    """The laboratory inputs of one sweep pair (SI) from the unit and mortar
    strengths f_b, f_m (MPa). Unit: the normalised strength f_b itself
    (`Compressive strength definition' = normalised: the law derives its
    uniaxial strength 0.8 f_b and prints it), E_b = 400 f_b (Vermeltfoort:
    about 400 times the compressive strength for six clay bricks),
    tensile strength f_bt = 0.1 f_b (rule of thumb, assumed), tensile
    fracture energy G_bt = 80 J/m^2 (van der Pluijm's 0.06-0.13 N/mm for
    clay units, recalled), compressive fracture energy crushing_energy(f_b).
    Mortar: E_m = mortar_modulus(f_m), tensile strength f_mt = 0.1 f_m (the
    `mortar' law's default 0.5 MPa at 5 MPa, assumed), tensile fracture
    energy G_mt = 20 f_mt J/m^2 per MPa (the law's default 10 J/m^2 at
    0.5 MPa, scaled so that the mortar's characteristic length E_m G_mt /
    f_mt^2 is the same for every f_m: assumed), compressive softening with
    G_mc = crushing_energy(f_m): the confined mortar peaks at f_m + k p and
    its cohesive part then softens, the frictional part k p stays, so the
    layer squeezed between the units has a bounded strength."""
    return {"f_b": f_b * 1e6,
            "f_bt": 0.1 * f_b * 1e6, "E_b": 400 * f_b * 1e6,
            "nu_b": nu_b, "G_bt": 80.0, "G_bc": crushing_energy(f_b),
            "f_m": f_m * 1e6, "f_mt": 0.1 * f_m * 1e6, "G_mt": 2.0 * f_m,
            "G_mc": crushing_energy(f_m),
            "E_m": mortar_modulus(f_m), "nu_m": nu_m}


def joint_penalties(E_b, E_m, nu_b, nu_m, h_m):
    """Lourenco-Rots penalties of a zero-thickness joint for units enlarged
    by half a joint: k_n = E_b E_m / (h_m (E_b - E_m)), the same with the
    shear moduli for k_s (Pa/m)."""
    G_b, G_m = E_b / (2 * (1 + nu_b)), E_m / (2 * (1 + nu_m))
    return (E_b * E_m / (h_m * (E_b - E_m)), G_b * G_m / (h_m * (G_b - G_m)))


def set_in(text, path, name, value, add=True):
    """Set `set NAME = VALUE' inside the nested subsections PATH (a list,
    [] = top level) of a parameter file, keeping the line's comment; add
    the line (and missing subsections) if ADD. Returns (text, found)."""
    lines = text.split("\n")
    stack, pattern = [], re.compile(r"^([ \t]*set[ \t]+" + re.escape(name) +
                                    r"[ \t]*=)[^#]*(#.*)?$")
    opened = None
    for i, line in enumerate(lines):
        m = re.match(r"^\s*subsection\s+(.*?)\s*$", line)
        if m:
            stack.append(m.group(1))
            if stack == path and opened is None:
                opened = i
            continue
        if re.match(r"^\s*end\s*$", line):
            if stack:
                stack.pop()
            continue
        m = pattern.match(line)
        if m and stack == path:
            comment = "  " + m.group(2) if m.group(2) else ""
            lines[i] = m.group(1) + " " + value + comment
            return "\n".join(lines), True
    if not add:
        return text, False
    indent = "  " * len(path)
    if opened is not None or not path:
        at = opened + 1 if path else next(
            (i + 1 for i, l in enumerate(lines)
             if re.match(r"^set[ \t]+Analysis", l)), 0)
        lines.insert(at, f"{indent}set {name} = {value}")
        return "\n".join(lines), False
    block = [f"{'  ' * k}subsection {p}" for k, p in enumerate(path)] + \
        [f"{indent}set {name} = {value}"] + \
        [f"{'  ' * k}end" for k in reversed(range(len(path)))]
    return "\n".join(lines + block) + "\n", False


def get_in(text, path, name):
    """The value of `set NAME' inside PATH (None if absent)."""
    stack = []
    for line in text.split("\n"):
        m = re.match(r"^\s*subsection\s+(.*?)\s*$", line)
        if m:
            stack.append(m.group(1))
            continue
        if re.match(r"^\s*end\s*$", line):
            stack and stack.pop()
            continue
        m = re.match(r"^\s*set\s+" + re.escape(name) + r"\s*=\s*([^#]*)",
                     line)
        if m and stack == path:
            return m.group(1).strip()
    return None


def parse_mesh(text):
    """`LxWxH' (cells per unit + joint) as three positive integers."""
    parts = text.split("x")
    if len(parts) != 3 or not all(p.isdigit() and int(p) > 0 for p in parts):
        raise SystemExit(f"study: error: --sweep-mesh `{text}' is not LxWxH "
                         "with three positive integers (e.g. 6x3x3)")
    return [int(p) for p in parts]


def make_sweep_prm(f_b, f_m, directory, quick, model, mesh=SWEEP_MESH):
    """The single-leaf wallette for one (f_b, f_m) pair (see the module
    documentation); returns (name, prm, out)."""
    if model == "detailed":
        return make_detailed_sweep_prm(f_b, f_m, directory, quick, mesh)
    source = os.path.join(root, "prm", "examples",
                          "wallette-single-cyclic.prm")
    text = open(source).read()
    name = f"sweep-fb{f_b:g}-fm{f_m:g}"
    out = os.path.join(directory, name)
    text = set_entry(text, "Output directory", out, "top")
    text = set_entry(text, "Assembly threads", "1", "wallette")
    x = sweep_inputs(f_b, f_m)
    h_b = float(get_in(text, ["Wallette"], "Brick height") or 0.065)
    h_m = float(get_in(text, ["Wallette"], "Joint thickness") or 0.01)
    target = sweep_target(x["f_b"], x["E_m"], h_b, h_m)
    step = SWEEP_QUICK_STEP if quick else SWEEP_STEP
    settings = dict(SWEEP_QUICK if quick else SWEEP,
                    **{"Target strain": f"{target:.4g}",
                       "Number of steps": str(math.ceil(target / step))})
    for key, value in settings.items():
        text, _ = set_in(text, ["Wallette"], key, value)
    if model != "simplified":
        text, _ = set_in(text, ["Wallette"], MODEL_ENTRY, model)
    brick = ["Brick material", "Damage plasticity"]
    for key, value in (("Compressive strength", x["f_b"]),
                       ("Tensile strength", x["f_bt"]),
                       ("Young's modulus", x["E_b"]),
                       ("Poisson's ratio", x["nu_b"])):
        text, _ = set_in(text, brick, key, f"{value:.6g}")
    law = (get_in(text, ["Interface law"], "Law") or "bilinear").strip()
    used = ["E_b", "f_b", "f_bt"]
    if law == "composite":
        comp = ["Interface law", "Composite"]
        for key, value in (("Unit Young's modulus", x["E_b"]),
                           ("Unit Poisson's ratio", x["nu_b"]),
                           ("Mortar Young's modulus", x["E_m"]),
                           ("Mortar Poisson's ratio", x["nu_m"]),
                           ("Joint thickness", h_m)):
            text, _ = set_in(text, comp, key, f"{value:.6g}")
        used.append("E_m (penalties by the law)")
    else:
        k_n, k_s = joint_penalties(x["E_b"], x["E_m"], x["nu_b"], x["nu_m"],
                                   h_m)
        text, _ = set_in(text, ["Interface law"], "Normal stiffness",
                         f"{k_n:.6g}")
        text, _ = set_in(text, ["Interface law"], "Shear stiffness",
                         f"{k_s:.6g}")
        used.append(f"E_m (k_n = {k_n:.3g}, k_s = {k_s:.3g} Pa/m)")
    # a mortar strength entry, wherever the model has one
    found = False
    for path in (["Interface law", "Composite"], ["Mortar material"],
                 ["Mortar material", "Mortar"],
                 ["Mortar material", "Damage plasticity"], ["Wallette"]):
        for key in ("Mortar compressive strength", "Compressive strength"):
            if key == "Compressive strength" and "Mortar" not in path[0]:
                continue
            text, hit = set_in(text, path, key, f"{x['f_m']:.6g}", add=False)
            found = found or hit
    if found:
        used.append("f_m (mortar strength entry)")
    header = (f"# Study sweep pair {name}: {os.path.relpath(source, root)}, "
              f"monotonic to strain {target:.4g}, f_b = {f_b:g} MPa, f_m = {f_m:g} MPa, "
              f"E_b = {x['E_b']:.4g} Pa, f_bt = {x['f_bt']:.4g} Pa, "
              f"E_m = {x['E_m']:.4g} Pa (200 f_m), model {model}"
              f"{' (--quick)' if quick else ''}, written by contrib/study/run."
              f"\n# inputs the model uses: {', '.join(used)}"
              f"{'' if found else '; no mortar strength entry (f_m enters through E_m only)'}\n")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(header + text)
    return name, prm, out


def make_detailed_sweep_prm(f_b, f_m, directory, quick, mesh=SWEEP_MESH,
                            thickness=None):
    """The sweep pair for the detailed model: the single-leaf monotonic
    example (DETAILED_BASE) with the unit and mortar inputs of
    sweep_inputs(), on the mesh @p mesh (`LxWxH'; --quick: the coarsest),
    run to sweep_target(), with only the curve tables written (no VTU, no
    plots). With @p thickness (the `bonded' part) the monotonic example of
    that thickness instead, named bonded-THICKNESS-fbF_B-fmF_M."""
    if thickness is None:
        source, name = DETAILED_BASE, f"sweep-fb{f_b:g}-fm{f_m:g}"
    else:
        source = os.path.join(root, "prm", "examples",
                              f"wallette-{thickness}-monotonic.prm")
        name = f"bonded-{thickness}-fb{f_b:g}-fm{f_m:g}"
    text = open(source).read()
    out = os.path.join(directory, name)
    text = set_entry(text, "Output directory", out, "top")
    text = set_entry(text, "Assembly threads", "1", "wallette")
    x = sweep_inputs(f_b, f_m)
    h_b = float(get_in(text, ["Wallette"], "Brick height"))
    h_m = float(get_in(text, ["Wallette"], "Joint thickness"))
    target = sweep_target(x["f_b"], x["E_m"], h_b, h_m)
    step = SWEEP_QUICK_STEP if quick else SWEEP_STEP
    n = math.ceil(target / step)
    # past the peak a failed wallette can crawl on with steps of a few
    # thousandths of the nominal one; stop at SWEEP_STEP_CAP (the bonded
    # part: BONDED_STEP_CAP) x the nominal number of steps (status
    # `interrupted')
    settings = {"Target strain": f"{target:.4g}",
                "Number of steps": str(n),
                "Maximum steps": str((SWEEP_STEP_CAP if thickness is None
                                      else BONDED_STEP_CAP) * n),
                "Collapse stress ratio": f"{SWEEP_COLLAPSE_RATIO:g}",
                "Output interval": "0", "Write VTU": "false"}
    cells = [2, 1, 1] if quick else parse_mesh(mesh)
    settings.update({"Elements along the length": str(cells[0]),
                     "Elements along the width": str(cells[1]),
                     "Elements along the height": str(cells[2])})
    for key, value in settings.items():
        text, _ = set_in(text, ["Wallette"], key, value)
    text, _ = set_in(text, ["Postprocess", "Wallette"],
                     "List of postprocessors", "curve tables")
    brick = ["Brick material", "Damage plasticity"]
    for key, value in (("Compressive strength", x["f_b"]),
                       ("Tensile strength", x["f_bt"]),
                       ("Young's modulus", x["E_b"]),
                       ("Poisson's ratio", x["nu_b"]),
                       ("Tensile fracture energy", x["G_bt"]),
                       ("Compressive fracture energy", x["G_bc"])):
        text, _ = set_in(text, brick, key, f"{value:.6g}")
    mortar = ["Mortar material", "Mortar"]
    for key, value in (("Compressive strength", x["f_m"]),
                       ("Tensile strength", x["f_mt"]),
                       ("Tensile fracture energy", x["G_mt"]),
                       ("Compressive fracture energy", x["G_mc"]),
                       ("Young's modulus", x["E_m"]),
                       ("Poisson's ratio", x["nu_m"])):
        text, _ = set_in(text, mortar, key, f"{value:.6g}")
    inputs = ", ".join(f"{k} = {v:.4g}" for k, v in x.items())
    header = (f"# Study sweep pair {name}: {os.path.relpath(source, root)}, "
              f"monotonic to strain {target:.4g} or until the stress falls "
              f"below {SWEEP_COLLAPSE_RATIO:g} of its peak, model detailed, mesh "
              f"{'x'.join(map(str, cells))}"
              f"{' (--quick)' if quick else ''}, written by "
              f"contrib/study/run.\n# inputs (SI, sweep_inputs()): {inputs}\n")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(header + text)
    return name, prm, out


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


def make_prm(thickness, seed, directory, quick, model="simplified"):
    source = os.path.join(root, "prm", "examples",
                          f"wallette-{thickness}-cyclic.prm")
    with open(source) as f:
        text = f.read()
    name = f"{thickness}-{seed}"
    out = os.path.join(directory, name)
    text = set_entry(text, "Output directory", out, "top")
    text = set_entry(text, "Random seed", str(seed), "wallette")
    # the study runs specimens side by side (--jobs), one core each
    text = set_entry(text, "Assembly threads", "1", "wallette")
    if quick:
        for key, value in QUICK.items():
            text = set_entry(text, key, value, "wallette")
        text = set_entry(text, "Elements along the length",
                         QUICK_LENGTH[thickness], "wallette")
    if model != "simplified":
        text = detailed_specimen(text, model)
    # failure.png of every specimen (doc/brickwork.md, `failure plot')
    listed = get_in(text, ["Postprocess", "Wallette"],
                    "List of postprocessors") or \
        "curve tables, fields, joint fields, curve plot"
    if "failure plot" not in listed:
        listed += ", failure plot"
    text, _ = set_in(text, ["Postprocess", "Wallette"],
                     "List of postprocessors", listed)
    for key, value in FAILURE_PLOT.items():
        text, _ = set_in(text, ["Postprocess", "Wallette", "Failure plot"],
                         key, value)
    header = (f"# Study specimen {name}: {os.path.relpath(source, root)} "
              f"with Random seed = {seed}, model {model}"
              f"{' (--quick)' if quick else ''}, "
              "written by contrib/study/run.\n")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(header + text)
    return name, prm, out


def top_block(text, name):
    """(start, end) of the top-level `subsection NAME' ... `end' block of a
    parameter file (end after the newline), or None."""
    lines = text.split("\n")
    start, depth, offset = None, 0, 0
    for line in lines:
        n = len(line) + 1
        if re.match(r"^\s*subsection\s+", line):
            if depth == 0 and re.match(r"^subsection\s+" + re.escape(name) +
                                       r"\s*$", line):
                start = offset
            depth += 1
        elif re.match(r"^\s*end\s*$", line):
            depth -= 1
            if depth == 0 and start is not None:
                return start, min(offset + n, len(text))
        offset += n
    return None


def detailed_specimen(text, model):
    """A cyclic example turned into the detailed model: if it does not
    select the model itself, `Model = detailed' in subsection Wallette and
    the mortar law and the bond interfaces of DETAILED_BASE (f_m = 5 MPa,
    composite bond with friction), and
    the units' `Tension-compression interaction'; the example's unit
    strength (20 MPa) and its loading are kept."""
    if get_in(text, ["Wallette"], MODEL_ENTRY) == model:
        return text
    text, _ = set_in(text, ["Wallette"], MODEL_ENTRY, model)
    text, _ = set_in(text, ["Brick material", "Damage plasticity"],
                     "Tension-compression interaction", "true")
    detailed = open(DETAILED_BASE).read()
    for block in ("Mortar material", "Interface law"):
        new = top_block(detailed, block)
        new_text = detailed[new[0]:new[1]] if new else ""
        old = top_block(text, block)
        if old:
            text = text[:old[0]] + new_text + text[old[1]:]
        else:
            text = text.rstrip("\n") + "\n\n" + new_text
    return text


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
    p.add_argument("--part", default="specimens,sweep")
    p.add_argument("--model", default="detailed",
                   choices=("simplified", "detailed"))
    p.add_argument("--sweep-mesh", default=SWEEP_MESH)
    p.add_argument("--bonded-mesh", default=BONDED_MESH)
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
    parse_mesh(args.sweep_mesh)
    parse_mesh(args.bonded_mesh)
    seeds = [int(s) for s in args.seeds.split(",") if s]
    parts = [x for x in args.part.split(",") if x]
    for x in parts:
        if x not in ("specimens", "sweep", "bonded"):
            raise SystemExit(f"study: error: unknown part `{x}' (specimens, "
                             "sweep, bonded)")
    directory = os.path.abspath(
        args.output or ("output/study-quick" if args.quick else "output/study"))
    os.makedirs(directory, exist_ok=True)
    masonry = os.path.join(root, "build", "masonry")

    if args.report_only:
        return report.main([directory])

    runs = []
    if "specimens" in parts:
        # seed by seed, so that a study cut short has every thickness
        # (with one job; with more, the longest first, below)
        runs += [make_prm(t, s, directory, args.quick, args.model)
                 for s in seeds for t in thicknesses]
    if "sweep" in parts:
        runs += [make_sweep_prm(f_b, f_m, directory, args.quick, args.model,
                                args.sweep_mesh)
                 for f_b in SWEEP_FB for f_m in SWEEP_FM]
    if "bonded" in parts:
        if args.model != "detailed":
            raise SystemExit("study: error: --part bonded needs --model "
                             "detailed (the bonded examples' joints)")
        runs += [make_detailed_sweep_prm(f_b, f_m, directory, args.quick,
                                         args.bonded_mesh, t)
                 for f_b in SWEEP_FB for f_m in SWEEP_FM
                 for t in thicknesses]
    if args.jobs > 1:
        # the longest runs first (contrib/study/results: a triple specimen
        # took about 2.5 times a double's CPU time and 6 times a single's,
        # a sweep pair 12-101 s), so that the last ones to finish are short
        # and the cores stay busy to the end
        rank = {"triple": 0, "double": 1, "sweep": 2, "single": 3}
        runs.sort(key=lambda run: rank.get(
            run[0].split("-")[1 if run[0].startswith("bonded-") else 0], 2))
    print(f"study: {len(runs)} runs, {min(args.jobs, len(runs))} at a time"
          f"{' (quick)' if args.quick else ''}, model {args.model}, in "
          f"{directory}/", flush=True)
    cpu_total = 0.0
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
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid == 0:
                continue
            code = os.waitstatus_to_exitcode(status)
            proc.returncode = code
            del running[name]
            seconds = time.time() - t0
            cpu = usage.ru_utime + usage.ru_stime
            cpu_total += cpu
            with open(os.path.join(directory, name + ".cpu"), "w") as f:
                f.write(f"{cpu:.2f}\n")
            summary = {}
            try:
                with open(os.path.join(out, "summary.json")) as f:
                    summary = json.load(f)
            except (OSError, ValueError):
                pass
            status = summary.get("status", "no summary.json")
            if code == 0 and (status == "completed" or
                              (status == "interrupted" and
                               name.startswith(("sweep-", "bonded-")))):
                print(f"study: finished {name} in {seconds:.0f} s "
                      f"({cpu:.0f} CPU s): peak "
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
    print(f"study: all runs done in {time.time() - start:.0f} s, "
          f"{cpu_total:.0f} CPU s (user + sys)", flush=True)
    code = report.main([directory])
    if failed:
        print(f"study: error: {len(failed)} of {len(runs)} runs failed: "
              f"{', '.join(failed)} (logs {directory}/NAME.log)",
              file=sys.stderr)
        return 1
    return code


if __name__ == "__main__":
    sys.exit(main())
