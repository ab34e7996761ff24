#!/usr/bin/python3
"""failure.png of a wallette run (masonry runs this at the end of the run
when the postprocessor `failure plot' is listed).

Usage: wallette_failure.py OUTPUT_DIRECTORY

Reads failure.json (written by the postprocessor) and draws failure.png of
the size it names, in two views of the deformed wallette (displacements
times the stated factor):
  left:  the front face (x-z), seen from y = -infinity: each cell's face of
         lower y, the nearer cells drawn over the farther ones;
  right: a vertical section across the thickness (y-z) at 45 % of the
         length (the cells and joints the plane cuts), where collar joints
         between the leaves of double and triple walls show.
Cells are coloured by their damage (0 to 1); deleted cells are left out and
marked with a black cross at their undeformed centre; every open joint face
in failure.json (normal opening above the stated threshold) is drawn as a
line coloured by its type: in the front view the bed, head and splitting
faces, in the section the bed, collar and splitting faces the plane cuts.
Lengths in mm.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa
from matplotlib import cm, colors  # noqa: E402

TYPES = {0: ("bed", "tab:blue"), 1: ("head", "tab:orange"),
         2: ("collar", "magenta"), 3: ("splitting", "red")}
# front face of a cell (vertex v = i + 2 j + 4 k, i along x, j along y, k
# along z): j = 0, in order around the face
FRONT = (0, 1, 5, 4)


def main(d):
    data = json.load(open(os.path.join(d, "failure.json")))
    w, h = int(data["width"]), int(data["height"])
    f = float(data["magnification"])
    cells = []
    for c in data["cells"]:
        v = [c[2 + 6 * i: 8 + 6 * i] for i in range(8)]
        x0 = [p[:3] for p in v]
        x = [[1e3 * (p[k] + f * p[3 + k]) for k in range(3)] for p in v]
        cells.append({"deleted": c[0] != 0, "damage": c[1], "x0": x0,
                      "x": x})
    joints = []
    for j in data["joints"]:
        v = [j[3 + 6 * i: 9 + 6 * i] for i in range(4)]
        joints.append({"type": int(j[0]), "axis": int(j[1]),
                       "x0": [p[:3] for p in v],
                       "x": [[1e3 * (p[k] + f * p[3 + k]) for k in range(3)]
                             for p in v]})
    xs = [p[0] for c in cells for p in c["x0"]]
    x_cut = min(xs) + 0.45 * (max(xs) - min(xs))

    # text scaled with the picture (the layout is made for 1600 pixels)
    plt.rcParams["font.size"] = 10 * max(0.55, min(1.0, w / 1600))
    fs = plt.rcParams["font.size"]
    fig = plt.figure(figsize=(w / 100, h / 100), dpi=100)
    axf = fig.add_axes([0.05, 0.1, 0.52, 0.78])
    axs = fig.add_axes([0.62, 0.1, 0.26, 0.78])
    axc = fig.add_axes([0.91, 0.1, 0.015, 0.78])
    cmap = plt.get_cmap("YlOrRd")
    norm = colors.Normalize(0, 1)

    # front view: far cells first
    live = [c for c in cells if not c["deleted"]]
    live.sort(key=lambda c: -sum(p[1] for p in c["x"]))
    polys = [[(c["x"][i][0], c["x"][i][2]) for i in FRONT] for c in live]
    axf.add_collection(PolyCollection(
        polys, facecolors=[cmap(norm(c["damage"])) for c in live],
        edgecolors="0.35", linewidths=0.3))
    gone = [c for c in cells if c["deleted"]]
    if gone:
        axf.plot([1e3 * sum(p[0] for p in c["x0"]) / 8 for c in gone],
                 [1e3 * sum(p[2] for p in c["x0"]) / 8 for c in gone],
                 "kx", ms=5, mew=1, label=f"deleted cells ({len(gone)})")
    drawn = {t: sum(j["type"] == t for j in joints) for t in TYPES}
    for t, (name, colour) in TYPES.items():
        segs = []
        for j in joints:
            if j["type"] != t or j["axis"] == 1:
                continue
            # a face normal to x or z: its projection on x-z is a segment;
            # draw its outline (degenerate polygon)
            p = [(q[0], q[2]) for q in j["x"]]
            segs.append([p[0], p[1], p[3], p[2], p[0]])
        if segs:
            axf.add_collection(LineCollection(segs, colors=colour,
                                              linewidths=1.6))
    axf.set_title("front face (x-z)", fontsize=fs)

    # section at x_cut
    def cut_cell(c):
        x0, x = c["x0"], c["x"]
        lo, hi = x0[0][0], x0[1][0]
        if not lo <= x_cut <= hi:
            return None
        t = (x_cut - lo) / (hi - lo)
        pts = []
        for a, b in ((0, 1), (2, 3), (6, 7), (4, 5)):  # y-z corners
            pts.append(((1 - t) * x[a][1] + t * x[b][1],
                        (1 - t) * x[a][2] + t * x[b][2]))
        return pts

    secs, sec_damage, sec_gone = [], [], []
    for c in cells:
        p = cut_cell(c)
        if p is None:
            continue
        if c["deleted"]:
            sec_gone.append(c)
        else:
            secs.append(p)
            sec_damage.append(c["damage"])
    axs.add_collection(PolyCollection(
        secs, facecolors=[cmap(norm(v)) for v in sec_damage],
        edgecolors="0.35", linewidths=0.3))
    if sec_gone:
        axs.plot([1e3 * sum(p[1] for p in c["x0"]) / 8 for c in sec_gone],
                 [1e3 * sum(p[2] for p in c["x0"]) / 8 for c in sec_gone],
                 "kx", ms=5, mew=1)
    for t, (name, colour) in TYPES.items():
        segs = []
        for j in joints:
            if j["type"] != t or j["axis"] == 0:
                continue
            x0 = [q[0] for q in j["x0"]]
            if not min(x0) <= x_cut <= max(x0):
                continue
            # face vertices in face-lexicographic order: (0, 1) and (2, 3)
            # differ along the face's first tangent (x for bed and collar
            # faces); the segment where the plane cuts the face
            lo, hi = j["x0"][0][0], j["x0"][1][0]
            s = (x_cut - lo) / (hi - lo) if hi != lo else 0.5
            a = [(1 - s) * j["x"][0][k] + s * j["x"][1][k] for k in (1, 2)]
            b = [(1 - s) * j["x"][2][k] + s * j["x"][3][k] for k in (1, 2)]
            segs.append([a, b])
        if segs:
            axs.add_collection(LineCollection(segs, colors=colour,
                                              linewidths=1.6))
    axs.set_title(f"section at x = {1e3 * x_cut:.0f} mm (y-z)", fontsize=fs)

    for ax, (i, j) in ((axf, (0, 2)), (axs, (1, 2))):
        pts = [(p[i], p[j]) for c in cells for p in c["x"]] or [(0, 0)]
        lo_x, hi_x = min(p[0] for p in pts), max(p[0] for p in pts)
        lo_y, hi_y = min(p[1] for p in pts), max(p[1] for p in pts)
        m = 0.05 * max(hi_x - lo_x, hi_y - lo_y, 1e-9)
        ax.set_xlim(lo_x - m, hi_x + m)
        ax.set_ylim(lo_y - m, hi_y + m)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("xyz"[i] + " (mm)")
        ax.set_ylabel("z (mm)")
        ax.tick_params(labelsize=0.8 * fs)
    handles = [plt.Line2D([], [], color=colour, lw=2,
                          label=f"open {name} ({drawn[t]})")
               for t, (name, colour) in TYPES.items()]
    if gone:
        handles.append(plt.Line2D([], [], color="k", marker="x", ls="",
                                  label=f"deleted cell ({len(gone)})"))
    axf.legend(handles=handles, fontsize=0.7 * fs, loc="upper right",
               framealpha=0.8)
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), cax=axc,
                 label=f"damage ({data['damage']})")
    fig.suptitle(
        f"strain {data['strain']:.5f}, stress "
        f"{round(data['stress'] / 1e6, 2) + 0.0:.2f} MPa;"
        f" displacements x {f:.3g}; open joints: normal opening > "
        f"{1e3 * data['opening_threshold']:.3g} mm "
        f"({len(joints)} faces)", fontsize=fs)
    fig.savefig(os.path.join(d, "failure.png"), dpi=100)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1])
