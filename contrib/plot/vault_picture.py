#!/usr/bin/python3
"""Render the result of a rigid-block analysis (blocks.vtu and interfaces.vtu,
ASCII, as written by masonry) to a PNG so that the crack pattern is visible
without ParaView: the blocks in neutral grey in the deformed configuration
(displacements amplified as in the VTU), and every interface that opens (a
hinge, a crack, or a block lifting off a support) drawn on top, coloured by
its opening in mm, with a colour bar. Closed joints are thin dark lines.

Usage: vault_picture.py blocks.vtu vault.png [title] [--interfaces FILE]
                        [--amplification A]
(interfaces.vtu defaults to the file of that name next to blocks.vtu; A is
the displacement factor of the VTU files, used to find which block faces are
exposed so that hidden edges are not drawn)
"""
import argparse
import os
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

# an interface is open if its opening exceeds this fraction of the largest
# opening (the LP's round-off is many orders of magnitude below)
OPEN_FRACTION = 1e-6


def read_vtu(path, nodes_per_cell):
    """Points, connectivity and the cell and point data arrays of an ASCII
    VTU (point data reshaped to one row per point)."""
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    points = np.fromstring(piece.find("Points/DataArray").text, sep=" ").reshape(-1, 3)
    cells = piece.find("Cells")
    conn = np.fromstring(
        cells.find("DataArray[@Name='connectivity']").text, dtype=np.int64, sep=" "
    ).reshape(-1, nodes_per_cell)
    data = {}
    cell_data = piece.find("CellData")
    if cell_data is not None:
        for a in cell_data.iter("DataArray"):
            data[a.get("Name")] = np.fromstring(a.text or "", sep=" ")
    point_data = piece.find("PointData")
    if point_data is not None:
        for a in point_data.iter("DataArray"):
            data[a.get("Name")] = np.fromstring(a.text or "", sep=" ").reshape(len(points), -1)
    return points, conn, data


# the six faces of a VTK hexahedron (0-3 intrados side, 4-7 extrados side)
HEX_FACES = np.array(
    [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
)


def block_faces(conn):
    """The faces of the sub-cells that lie on a block's boundary: every block
    has its own points, so a face shared by two sub-cells of a block is
    interior and a face seen once is on the boundary."""
    faces = conn[:, HEX_FACES].reshape(-1, 4)
    keys = np.sort(faces, axis=1)
    _, index, counts = np.unique(keys, axis=0, return_index=True, return_counts=True)
    return faces[index[counts == 1]]


def block_edges(conn, n_blocks, undeformed=None):
    """Edges of the blocks, as segments between the sample points (blocks.vtu
    has (k+1)^2 points per block face, intrados then extrados, numbered block
    by block): the extrados outline of every block, and the intrados and
    across-thickness edges of its face v = 0 (towards the viewer) where that
    face is exposed, i.e. not shared with the next block (decided on the
    undeformed points, if given; else drawn for every block). Hidden edges
    are left out because matplotlib draws lines on top of the faces."""
    k = int(round(np.sqrt(len(conn) / n_blocks)))
    n = k + 1
    r = np.arange(n)
    per_block = 2 * n * n
    first = per_block * np.arange(n_blocks)

    def replicate(line, blocks):
        segments = np.column_stack([line[:-1], line[1:]])
        return (segments[None, :, :] + first[blocks][:, None, None]).reshape(-1, 2)

    every = np.arange(n_blocks)
    edges = []
    for fixed in (0, k):
        edges.append(replicate(n * n + fixed * n + r, every))  # along i at j = fixed
        edges.append(replicate(n * n + r * n + fixed, every))  # along j at i = fixed
    exposed = every
    if undeformed is not None:
        corners = np.array([0, k, n * n, n * n + k])  # face v = 0 (j = 0)
        front = undeformed[first[:, None] + corners].mean(axis=1)
        back = undeformed[first[:, None] + corners + k * n].mean(axis=1)
        size = np.ptp(undeformed, axis=0).max()
        tolerance = 1e-6 * size
        shared = {tuple(v) for v in np.round(back / tolerance).astype(np.int64)}
        keys = np.round(front / tolerance).astype(np.int64)
        exposed = np.array([b for b in every if tuple(keys[b]) not in shared], dtype=int)
    if len(exposed):
        edges.append(replicate(r, exposed))  # intrados along i at j = 0
        for i in (0, k):
            edges.append(replicate(np.array([i, n * n + i]), exposed))  # across
    return np.concatenate(edges)


def shade(points, faces, base):
    """Grey faces lit from above (Lambert, two-sided)."""
    p = points[faces]
    normals = np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 1])
    norm = np.linalg.norm(normals, axis=1)
    norm[norm == 0] = 1
    light = np.abs(normals @ np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8]) / norm)
    grey = base * (0.55 + 0.45 * light)
    return np.column_stack([grey, grey, grey, np.ones_like(grey)])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("blocks_vtu")
    parser.add_argument("png")
    parser.add_argument("title", nargs="?", default="")
    parser.add_argument("--interfaces", help="interfaces.vtu (default: next to blocks.vtu)")
    parser.add_argument("--amplification", type=float,
                        help="the displacement factor of the VTU files (to find the exposed block faces)")
    args = parser.parse_args()
    vtu, png, title = args.blocks_vtu, args.png, args.title
    interfaces_vtu = args.interfaces or os.path.join(os.path.dirname(vtu), "interfaces.vtu")
    points, conn, data = read_vtu(vtu, 8)
    faces = block_faces(conn)

    fig = plt.figure(figsize=(9, 6), dpi=110)
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # the open interfaces stay on top
    ax.add_collection3d(
        Poly3DCollection(points[faces], facecolors=shade(points, faces, 0.8), edgecolors="none", zorder=1)
    )
    n_blocks = len(np.unique(data["block_id"])) if "block_id" in data else len(conn)
    undeformed = None
    if args.amplification is not None and "displacement" in data:
        undeformed = points - args.amplification * data["displacement"]
    edges = block_edges(conn, n_blocks, undeformed)
    ax.add_collection3d(Line3DCollection(points[edges], colors="0.2", linewidths=0.4, zorder=2))

    subtitle = "no interface data"
    if os.path.exists(interfaces_vtu):
        ipoints, quads, idata = read_vtu(interfaces_vtu, 4)
        opening = np.clip(idata.get("opening", np.zeros(len(quads))), 0, None) * 1e3  # mm
        largest = opening.max() if len(opening) else 0.0
        is_open = opening > OPEN_FRACTION * largest if largest > 0 else np.zeros(len(quads), bool)
        if is_open.any():
            order = np.argsort(opening[is_open])  # the largest openings on top
            q = ipoints[quads[is_open][order]]
            o = opening[is_open][order]
            cmap = plt.get_cmap("plasma")
            norm = matplotlib.colors.Normalize(vmin=0, vmax=largest)
            colours = cmap(norm(o))
            ax.add_collection3d(Poly3DCollection(q, facecolors=colours, edgecolors="none", zorder=3))
            edges = np.concatenate([q[:, [a, (a + 1) % 4]] for a in range(4)])
            ax.add_collection3d(
                Line3DCollection(edges, colors=np.tile(colours, (4, 1)), linewidths=2.5, zorder=4)
            )
            mappable = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
            fig.colorbar(mappable, ax=ax, shrink=0.6, pad=0.02, label="opening [mm]")
            subtitle = f"{int(is_open.sum())} of {len(quads)} interface faces open (coloured), largest {largest:.3g} mm"
        else:
            subtitle = "no interface opens"

    # the line of thrust (limit load, minimum thickness): the centres of
    # pressure of the joints, in the undeformed geometry
    thrust_csv = os.path.join(os.path.dirname(vtu), "thrust_line.csv")
    if os.path.exists(thrust_csv):
        rows = [line.split(",") for line in open(thrust_csv) if line[0].isdigit()]
        if rows:
            xyz = np.array([[float(r[3]), float(r[4]), float(r[5])] for r in rows])
            extent = points.max(axis=0) - points.min(axis=0)
            if extent[1] < 0.5 * max(extent[0], extent[2]):
                # a strip (arch): one point per joint across the depth, joined
                # along the span
                xyz = xyz[np.argsort(xyz[:, 0])]
                ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], "k.-", lw=1.2, ms=4, zorder=5,
                        label="line of thrust (undeformed)")
            else:
                ax.scatter(xyz[:, 0], xyz[:, 1], xyz[:, 2], c="k", s=6, zorder=5,
                           label="centres of pressure (undeformed)")
            ax.legend(loc="lower left", fontsize=8)

    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    extent = hi - lo
    if extent[1] < 0.5 * max(extent[0], extent[2]):
        ax.view_init(elev=12, azim=-80)  # a strip (arch): look at its face
    else:
        ax.view_init(elev=25, azim=-60)
    heading = f"{title}: deformed blocks (displacements amplified)" if title else "deformed blocks"
    ax.set_title(f"{heading}\n{subtitle}", fontsize=10)
    fig.tight_layout()
    fig.savefig(png)


if __name__ == "__main__":
    main()
