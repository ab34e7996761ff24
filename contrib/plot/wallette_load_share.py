#!/usr/bin/python3
"""Where the vertical load of a detailed wallette goes, and what has failed,
at one step (default: the peak of curve.csv): the table of the diagnosis in
doc/notes/bonded-wall-strength.md.

Usage: wallette_load_share.py OUTPUT_DIRECTORY [--strain EPS]
                              [--section X --png FILE]

Needs a `Model = detailed` run with the `fields` and `joint fields`
postprocessors written at the step looked at (`Output interval = 1` to be
sure that the peak is among them; the nearest written step is used and
printed). The cells are grouped by what they are:
  unit, in a collar plane   unit cells whose centre lies in the plane of a
                            collar joint (headers and closers bridging it)
  unit, elsewhere           the other unit cells
  mortar, collar            mortar cells in a collar plane (the collar joints
                            of the stretcher courses, and the crossings of
                            header-course perpends with it)
  mortar, head              the other vertical-joint mortar (perpends)
Only the cells cut by the mid-height plane of a course count (bed joints are
horizontal layers and carry the full force in series); for each group the
table gives its share of that plane's area and of the vertical force, its
mean vertical stress, its mean lateral stress in the thickness direction
(y, tension positive) and the largest, the number of cells with tensile
damage > 0.9 and of deleted cells (all courses together). Then, for every
joint type of interfaces.vtu, the largest normal opening and slip.
With --section X it also draws the y-z section at x = X (m) of the vertical
and lateral stress (cells whose x-range contains X) to FILE.
The collar planes follow from the wallette's `Brick width` w and `Joint
thickness` h_m: y in [k (w + h_m) - h_m, k (w + h_m)], k = 1 .. n - 1.
Needs /usr/bin/python3 with numpy and meshio (and matplotlib for --png).
"""
import argparse
import csv
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

try:
    import meshio
except ImportError:
    sys.exit("wallette_load_share: needs python3-meshio (apt-get install python3-meshio)")

def read_vtu(path):
    """Points, connectivity (one row per cell) and the point and cell data
    arrays of a VTU file (meshio reads deal.II's and masonry's VTU)."""
    mesh = meshio.read(path)
    points = np.asarray(mesh.points, dtype=float)
    conn = np.concatenate([block.data for block in mesh.cells])
    data = {}
    for name, values in mesh.point_data.items():
        data[name] = np.asarray(values, dtype=float)
    for name, blocks in mesh.cell_data.items():
        data[name] = np.concatenate([np.asarray(b, dtype=float) for b in blocks])
    return points, conn, data


def first_value(prm, name):
    m = re.search(r"set\s+%s\s*=\s*([^\s#]+)" % re.escape(name), prm)
    if not m:
        raise SystemExit("wallette_load_share: no '%s' in parameters.prm" % name)
    return float(m.group(1))


def written_steps(out, name):
    """(strain, file) of every step in NAME.pvd (its timestep is the strain)."""
    root = ET.parse(os.path.join(out, name + ".pvd")).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--strain", type=float, help="strain of the step (default: the peak)")
    ap.add_argument("--section", type=float, help="x of the y-z section, m")
    ap.add_argument("--png", help="file of the section picture")
    a = ap.parse_args()

    summary = json.load(open(os.path.join(a.out, "summary.json")))
    prm = open(os.path.join(a.out, "parameters.prm")).read()
    w, h_b = first_value(prm, "Brick width"), first_value(prm, "Brick height")
    h_m = summary["joint_thickness"]
    thickness, length = summary["thickness"], summary["length"]
    n_leaves = int(round((thickness + h_m) / (w + h_m)))
    collars = [(k * (w + h_m) - h_m, k * (w + h_m)) for k in range(1, n_leaves)]

    rows = list(csv.DictReader(open(os.path.join(a.out, "curve.csv"))))
    if a.strain is None:
        peak = max(rows, key=lambda r: float(r["stress_Pa"]))
        target = float(peak["strain"])
    else:
        target = a.strain
    strain, vtu = min(written_steps(a.out, "solution"), key=lambda s: abs(s[0] - target))
    row = min(rows, key=lambda r: abs(float(r["strain"]) - strain))
    vtu = os.path.join(a.out, vtu.replace(".pvtu", ".0.vtu"))

    points, conn, data = read_vtu(vtu)
    x = points[conn]  # the undeformed cells (the VTU has the reference points)
    lo, hi = x.min(1), x.max(1)
    centre, size = 0.5 * (lo + hi), hi - lo
    cell = {k: v[conn].mean(1) for k, v in data.items() if v.ndim == 1}
    unit = np.round(cell["region"]) == 0
    dt = np.where(unit, cell["damage_tension"], cell.get("mortar_damage_tension", 0 * unit))
    deleted = cell.get("deleted", 0 * unit) > 0.5
    tol = 1e-6
    in_collar = np.zeros(len(conn), bool)
    for y0, y1 in collars:
        in_collar |= (centre[:, 1] > y0 - tol) & (centre[:, 1] < y1 + tol)
    vertical = (size[:, 2] > h_m + tol) | unit  # not a bed-joint cell
    n_courses = int(round((summary["height"] + h_m) / (h_b + h_m)))
    mid = [k * (h_b + h_m) + h_b / 2 for k in range(n_courses)]
    groups = [
        ("unit, in a collar plane", unit & in_collar),
        ("unit, elsewhere", unit & ~in_collar),
        ("mortar, collar", ~unit & in_collar & vertical),
        ("mortar, head", ~unit & ~in_collar & vertical),
    ]
    force = float(row["force_N"])
    print(
        "%s: step at strain %.5f, stress %.3f MPa, %s deleted cells; %d leaves, collar planes %s"
        % (a.out, strain, float(row["stress_Pa"]) / 1e6, row["deleted_cells"], n_leaves,
           ", ".join("y = %.4f-%.4f m" % c for c in collars) or "none")
    )
    print("| cells | area % | force % | mean σ_zz MPa | mean σ_yy MPa | max σ_yy MPa | d_t > 0.9 | deleted |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, mask in groups:
        area = force_sum = szz = syy = 0.0
        syy_max = -np.inf
        for z in mid:
            s = mask & (lo[:, 2] <= z) & (hi[:, 2] >= z)
            ai = size[s, 0] * size[s, 1]
            area += ai.sum()
            force_sum += -(cell["stress_zz"][s] * ai).sum()
            szz += -(cell["stress_zz"][s] * ai).sum()
            syy += (cell["stress_yy"][s] * ai).sum()
            if s.any():
                syy_max = max(syy_max, cell["stress_yy"][s].max())
        if area == 0:
            continue
        print(
            "| %s | %.1f | %.1f | %.2f | %.2f | %.2f | %d | %d |"
            % (name, 100 * area / (n_courses * length * thickness), 100 * force_sum / (n_courses * force),
               szz / area / 1e6, syy / area / 1e6, syy_max / 1e6, (mask & (dt > 0.9)).sum(), (mask & deleted).sum())
        )
    bed = ~unit & ~vertical
    vol = size[:, 0] * size[:, 1] * size[:, 2]
    print(
        "bed-joint mortar: %d cells, mean sigma_xx %.2f MPa, sigma_yy %.2f MPa, %d with d_t > 0.9, %d deleted"
        % (bed.sum(), np.average(cell["stress_xx"][bed], weights=vol[bed]) / 1e6,
           np.average(cell["stress_yy"][bed], weights=vol[bed]) / 1e6, (bed & (dt > 0.9)).sum(), (bed & deleted).sum())
    )

    ivtu = os.path.join(a.out, os.path.basename(vtu).replace("solution_", "interfaces_").replace(".0.vtu", ".vtu"))
    if os.path.exists(ivtu):
        p, c, idata = read_vtu(ivtu)
        jt = np.round(idata["joint_type_bed0_head1_collar2_splitting3"]).astype(int)
        q = p[c]
        normal = np.argmin(q.max(1) - q.min(1), axis=1)
        for t, name in ((0, "bed"), (1, "head"), (2, "collar"), (3, "splitting")):
            for n in (range(3) if t == 3 else (None,)):
                m = (jt == t) if n is None else (jt == t) & (normal == n)
                if not m.any():
                    continue
                label = name if n is None else "%s (normal %s)" % (name, "xyz"[n])
                print(
                    "  %-22s %4d faces: largest opening %.2e m, largest slip %.2e m"
                    % (label, m.sum(), idata["normal_opening"][m].max(), idata["slip"][m].max())
                )

    if a.section is not None and a.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.collections import PatchCollection
        from matplotlib.patches import Rectangle

        s = (lo[:, 0] <= a.section) & (hi[:, 0] >= a.section)
        fig, axes = plt.subplots(1, 2, figsize=(3 + 4 * thickness / 0.215, 5.5), sharey=True)
        for ax, (key, label, sign, cmap) in zip(
            axes, (("stress_zz", "vertical compression -σ_zz, MPa", -1, "viridis"),
                   ("stress_yy", "lateral σ_yy (thickness direction), MPa", 1, "coolwarm"))
        ):
            rects = [Rectangle((lo[i, 1] * 1e3, lo[i, 2] * 1e3), size[i, 1] * 1e3, size[i, 2] * 1e3) for i in np.where(s)[0]]
            v = sign * cell[key][s] / 1e6
            pc = PatchCollection(rects, cmap=cmap, edgecolor="k", linewidth=0.2)
            pc.set_array(v)
            if key == "stress_yy":
                m = max(abs(v).max(), 1e-9)
                pc.set_clim(-m, m)
            else:
                pc.set_clim(0, max(v.max(), 1e-9))
            ax.add_collection(pc)
            ax.set_xlim(0, thickness * 1e3)
            ax.set_ylim(0, summary["height"] * 1e3)
            ax.set_aspect("equal")
            ax.set_xlabel("y, mm")
            ax.set_title(label, fontsize=8)
            fig.colorbar(pc, ax=ax, shrink=0.8)
            for y0, y1 in collars:
                ax.axvspan(y0 * 1e3, y1 * 1e3, color="none", ec="r", lw=0.5)
        axes[0].set_ylabel("z, mm")
        fig.suptitle("%s: x = %.0f mm, strain %.5f, %.2f MPa" % (os.path.basename(os.path.normpath(a.out)), a.section * 1e3, strain, float(row["stress_Pa"]) / 1e6), fontsize=9)
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
