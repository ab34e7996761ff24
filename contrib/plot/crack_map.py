#!/usr/bin/python3
"""Draw the crack map of a rigid-block run (crack_map.csv, written by the
`crack map' output) as a PNG: the developed intrados with the patch edges,
every joint (thin grey), the supports (grey; settling ones orange) and the
cracks coloured by their largest opening (mm): solid where the intrados
opens (a crack visible from below), dashed where only the extrados opens,
dotted where the joint slides.

Usage: crack_map.py crack_map.csv crack_map.png [title] [--tolerance T]
(T: the jump below which a face counts as closed, m; crack_map.csv's
`opens_at' column is used when it is not given)
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("title", nargs="?", default="")
    parser.add_argument("--tolerance", type=float, default=None)
    args = parser.parse_args()
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))

    def line(r):
        # drawn with t (along the vault) across the page, s upwards
        return [(float(r[f"t{k}"]), float(r[f"s{k}"])) for k in range(3)]

    everything = [p for r in rows for p in line(r)]
    width = max(p[0] for p in everything) - min(p[0] for p in everything)
    height = max(p[1] for p in everything) - min(p[1] for p in everything)
    aspect = min(2.5, max(0.6, height / max(width, 1e-30)))
    fig, ax = plt.subplots(figsize=(9, 1.6 + 7.4 * aspect * 0.75), dpi=120)
    joints = [line(r) for r in rows if r["kind"] == "joint"]
    ax.add_collection(LineCollection(joints, colors="0.72", linewidths=0.6, zorder=1))
    edges = [line(r) for r in rows if r["kind"] == "edge"]
    ax.add_collection(LineCollection(edges, colors="k", linewidths=1.0, zorder=2))
    # supports: drawn just outside the edge they carry, so that the cracks
    # along them stay visible
    middle = [sum(p[0] for p in everything) / len(everything), sum(p[1] for p in everything) / len(everything)]
    gap = 0.015 * max(width, height)

    def outside(r):
        points = line(r)
        (x0, y0), (x1, y1) = points[0], points[-1]
        nx, ny = y0 - y1, x1 - x0
        norm = max((nx * nx + ny * ny) ** 0.5, 1e-30)
        nx, ny = nx / norm, ny / norm
        if nx * ((x0 + x1) / 2 - middle[0]) + ny * ((y0 + y1) / 2 - middle[1]) < 0:
            nx, ny = -nx, -ny
        return [(x + gap * nx, y + gap * ny) for x, y in points]

    supports = [r for r in rows if r["kind"] == "support"]
    fixed = [outside(r) for r in supports if float(r["support_motion"]) == 0]
    settling = [outside(r) for r in supports if float(r["support_motion"]) > 0]
    handles = []
    if fixed:
        ax.add_collection(LineCollection(fixed, colors="0.35", linewidths=5, zorder=2))
        handles.append(matplotlib.lines.Line2D([], [], color="0.35", lw=5, label="fixed support"))
    if settling:
        ax.add_collection(LineCollection(settling, colors="#ff8c00", linewidths=5, zorder=2))
        handles.append(matplotlib.lines.Line2D([], [], color="#ff8c00", lw=5, label="settling support"))

    cracks = [r for r in rows if r["kind"] in ("joint", "support") and r["type"] not in ("closed", "")]
    largest = max([float(r["max_opening"]) for r in cracks] + [0.0]) * 1e3
    norm = matplotlib.colors.Normalize(vmin=0, vmax=largest if largest > 0 else 1.0)
    cmap = plt.get_cmap("YlOrRd")

    def style(r):
        if r["type"] == "slip":
            return "slip", ":"
        intrados = (float(r["intrados_opening"]) > args.tolerance if args.tolerance is not None
                    else r["opens_at"] in ("intrados", "both"))
        return ("opens at the intrados", "-") if intrados else ("opens at the extrados only", "--")

    # one collection per line style, the larger openings on top
    groups = {}
    for r in sorted(cracks, key=lambda r: float(r["max_opening"])):
        groups.setdefault(style(r), []).append(r)
    for (label, dash), members in groups.items():
        colours = [cmap(0.15 + 0.85 * norm(max(0.0, float(r["max_opening"]) * 1e3))) for r in members]
        ax.add_collection(LineCollection([line(r) for r in members], colors=colours, linewidths=3.2,
                                         linestyles=dash, zorder=3, capstyle="round"))
        handles.append(matplotlib.lines.Line2D([], [], color="0.3", lw=2.5, ls=dash, label=label))
    if cracks:
        mappable = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
        fig.colorbar(mappable, ax=ax, shrink=0.8, label="largest opening [mm]")
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("t, along the vault [m]")
    ax.set_ylabel("s, across, along the intrados [m]")
    heading = f"{args.title}: " if args.title else ""
    count = f"{len(cracks)} cracks" if cracks else "no crack"
    ax.set_title(f"{heading}crack map on the developed intrados ({count})", fontsize=10)
    if handles:
        fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.subplots_adjust(left=0.08, right=0.98, top=0.93, bottom=0.2)
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
