#!/usr/bin/python3
"""Render the result of a rigid-block analysis (blocks.vtu and interfaces.vtu,
ASCII, as written by masonry) as a figure for a paper: the deformed vault
(displacements amplified as in the VTU) shaded by the displacement
magnitude (mm, colour bar), every joint that opens drawn as a red line
whose width grows with its opening, the fixed supports in grey and the
settling ones in orange with arrows for their prescribed motion, a scale
bar, and the thrust line of a limit-load or minimum-thickness run. The
camera looks from the side that moves most (--view), faces turned away from
it are not drawn.

Usage: vault_picture.py blocks.vtu vault.png [title] [--interfaces FILE]
                        [--amplification A] [--view DX,DY]
(interfaces.vtu defaults to the file of that name next to blocks.vtu; A is
the displacement factor of the VTU files; DX,DY the horizontal direction,
from the vault's centre, of the side to look from)
"""
import argparse
import math
import os

import matplotlib
import meshio

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

# an interface is a crack if its opening exceeds this fraction of the
# largest opening (the LP's round-off is many orders of magnitude below)
OPEN_FRACTION = 1e-4


def read_vtu(path, nodes_per_cell):
    """Points, connectivity and the cell and point data arrays of a VTU file
    (read by meshio; point data with one row per point)."""
    mesh = meshio.read(path)
    kind = {8: "hexahedron", 4: "quad"}[nodes_per_cell]
    conn = np.concatenate([b.data for b in mesh.cells if b.type == kind]).astype(np.int64)
    data = {}
    for name, blocks in mesh.cell_data.items():
        data[name] = np.concatenate([np.asarray(b, dtype=float) for b in blocks])
    for name, values in mesh.point_data.items():
        data[name] = np.asarray(values, dtype=float).reshape(len(mesh.points), -1)
    return np.asarray(mesh.points, dtype=float), conn, data


# the six faces of a VTK hexahedron (0-3 intrados side, 4-7 extrados side)
HEX_FACES = np.array(
    [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
)


def block_surface(conn, points, block_of_cell):
    """The faces of the sub-cells on a block's boundary (every block has its
    own points, so a face seen once is on the boundary), oriented outwards
    (from the block's centre), and their block."""
    faces = conn[:, HEX_FACES].reshape(-1, 4)
    owner = np.repeat(block_of_cell, 6)
    keys = np.sort(faces, axis=1)
    _, index, counts = np.unique(keys, axis=0, return_index=True, return_counts=True)
    keep = index[counts == 1]
    faces, owner = faces[keep], owner[keep]
    centres = np.zeros((owner.max() + 1, 3))
    np.add.at(centres, block_of_cell, points[conn].mean(axis=1))
    centres /= np.maximum(np.bincount(block_of_cell), 1)[:, None]
    p = points[faces]
    normals = np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 1])
    inward = np.einsum("ij,ij->i", normals, p.mean(axis=1) - centres[owner]) < 0
    faces[inward] = faces[inward][:, ::-1]
    normals[inward] *= -1
    length = np.linalg.norm(normals, axis=1)
    length[length == 0] = 1
    return faces, normals / length[:, None], owner, centres


def crease_edges(faces, normals, visible, angle=40):
    """Edges of the blocks: sides shared by two boundary faces of a block
    whose normals differ by more than `angle` degrees, where at least one
    of the two faces is visible."""
    a = faces.reshape(-1)
    b = np.roll(faces, -1, axis=1).reshape(-1)
    face = np.repeat(np.arange(len(faces)), 4)
    key = np.minimum(a, b) * (faces.max() + 1) + np.maximum(a, b)
    order = np.argsort(key, kind="stable")
    key, face, a, b = key[order], face[order], a[order], b[order]
    pair = np.nonzero(key[1:] == key[:-1])[0]
    f, g = face[pair], face[pair + 1]
    cosine = np.einsum("ij,ij->i", normals[f], normals[g])
    keep = (cosine < math.cos(math.radians(angle))) & (visible[f] | visible[g])
    return np.column_stack([a[pair][keep], b[pair][keep]])


def nice_length(size):
    """A round length near a fifth of `size`: 1, 2 or 5 times a power of 10."""
    target = size / 5
    power = 10 ** math.floor(math.log10(target))
    for m in (5, 2, 1):
        if m * power <= target:
            return m * power
    return power


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("blocks_vtu")
    parser.add_argument("png")
    parser.add_argument("title", nargs="?", default="")
    parser.add_argument("--interfaces", help="interfaces.vtu (default: next to blocks.vtu)")
    parser.add_argument("--amplification", type=float, default=1.0,
                        help="the displacement factor of the VTU files")
    parser.add_argument("--view", default="0,0", help="DX,DY: the side to look from")
    args = parser.parse_args()
    interfaces_vtu = args.interfaces or os.path.join(os.path.dirname(args.blocks_vtu), "interfaces.vtu")
    points, conn, data = read_vtu(args.blocks_vtu, 8)
    block_of_cell = data["block_id"].astype(int) if "block_id" in data else np.arange(len(conn))
    displacement = data.get("displacement", np.zeros_like(points))
    magnitude = np.linalg.norm(displacement, axis=1) * 1e3  # mm
    lo, hi = points.min(axis=0), points.max(axis=0)
    extent = hi - lo
    strip = extent[1] < 0.5 * max(extent[0], extent[2])

    # the camera: from the side that moves most (an arch face on, turned
    # towards it), never straight along an axis of the vault
    dx, dy = (float(v) for v in args.view.split(","))
    if strip:
        elevation, azimuth = 12.0, -90.0 + (20.0 if dx > 0 else -20.0 if dx < 0 else 10.0)
    elif dx == 0 and dy == 0:
        elevation, azimuth = 25.0, -60.0
    else:
        elevation, azimuth = 25.0, math.degrees(math.atan2(dy, dx))
        off = (azimuth + 360.0) % 90.0
        if off < 25.0:
            azimuth += 25.0 - off
        elif off > 65.0:
            azimuth -= off - 65.0
    e, z = math.radians(elevation), math.radians(azimuth)
    towards_camera = np.array([math.cos(e) * math.cos(z), math.cos(e) * math.sin(z), math.sin(e)])

    faces, normals, owner, centres = block_surface(conn, points, block_of_cell)
    point_block = np.zeros(len(points), dtype=int)
    point_block[conn.reshape(-1)] = np.repeat(block_of_cell, conn.shape[1])
    visible = normals @ towards_camera > 0
    fig = plt.figure(figsize=(8, 6), dpi=150)
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False
    top = magnitude.max() if magnitude.max() > 0 else 1.0
    norm = matplotlib.colors.Normalize(vmin=0, vmax=top)
    cmap = plt.get_cmap("viridis")
    colours = cmap(norm(magnitude[faces[visible]].mean(axis=1)))
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    shade = 0.6 + 0.4 * np.abs(normals[visible] @ light)
    colours[:, :3] *= shade[:, None]
    ax.add_collection3d(Poly3DCollection(points[faces[visible]], facecolors=colours, edgecolors="none",
                                         zorder=1))
    edges = crease_edges(faces, normals, visible)
    ax.add_collection3d(Line3DCollection(points[edges], colors="0.15", linewidths=0.35, zorder=2))
    mappable = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
    fig.colorbar(mappable, ax=ax, shrink=0.55, pad=0.0, label="displacement magnitude [mm]")

    subtitle = "no interface data"
    handles = []
    if os.path.exists(interfaces_vtu):
        ipoints, quads, idata = read_vtu(interfaces_vtu, 4)
        opening = np.clip(idata.get("opening", np.zeros(len(quads))), 0, None)
        support = idata.get("support", np.zeros(len(quads))) > 0.5
        largest = opening[~support].max() if (~support).any() else 0.0
        is_open = (opening > OPEN_FRACTION * largest) & ~support if largest > 0 else np.zeros(len(quads), bool)
        # a quad is (intrados s, intrados s+1, extrados s+1, extrados s):
        # draw its intrados and extrados sides where they face the camera
        q = ipoints[quads]
        across = (q[:, 3] + q[:, 2] - q[:, 0] - q[:, 1]) / 2
        across /= np.maximum(np.linalg.norm(across, axis=1), 1e-30)[:, None]
        facing = across @ towards_camera
        segments, widths = [], []
        for k in np.nonzero(is_open)[0]:
            w = 0.8 + 2.7 * opening[k] / largest
            if facing[k] > 0:
                segments.append(q[k, [3, 2]])
                widths.append(w)
            elif facing[k] < 0:
                segments.append(q[k, [0, 1]])
                widths.append(w)
        if segments:
            ax.add_collection3d(Line3DCollection(segments, colors="#d00000", linewidths=widths, zorder=4))
            handles.append(matplotlib.lines.Line2D([], [], color="#d00000", lw=2.5,
                                                   label=f"crack (width ∝ opening, largest {largest * 1e3:.3g} mm)"))
        n_open = len({int(k) for k in np.nonzero(is_open)[0]})
        subtitle = f"{n_open} of {int((~support).sum())} joint faces open" if n_open else "no joint opens"
        # supports: the middle line of each support joint, the settling ones
        # at rest (dashed) and moved (orange) with arrows
        if support.any() and "displacement" in idata:
            rest = ipoints - args.amplification * idata["displacement"]
            ground = idata.get("support_motion", np.zeros_like(ipoints))
            drawn = set()  # kinds drawn: settling (True), fixed (False)
            for k in np.nonzero(support)[0]:
                # the support's side of its block, horizontally, across the
                # support: the wall under a springing on the far side is
                # hidden by the vault
                centre = ipoints[quads[k]].mean(axis=0)
                owner = point_block[np.argmin(np.linalg.norm(points - centre, axis=1))]
                along = ipoints[quads[k][1]] - ipoints[quads[k][0]]
                along /= max(np.linalg.norm(along), 1e-30)
                outward = centre - centres[owner]
                outward -= (outward @ along) * along
                if outward[0] * towards_camera[0] + outward[1] * towards_camera[1] < 0:
                    continue
                a, b = quads[k, [0, 3]], quads[k, [1, 2]]
                line = np.array([rest[a].mean(axis=0), rest[b].mean(axis=0)])
                motion = np.array([ground[a].mean(axis=0), ground[b].mean(axis=0)])
                drawn.add(bool(np.abs(motion).max() > 0))
                if np.abs(motion).max() > 0:
                    moved = line + args.amplification * motion
                    ax.plot(*line.T, color="0.45", lw=1.2, ls="--", zorder=3)
                    ax.plot(*moved.T, color="#ff8c00", lw=4, zorder=3, solid_capstyle="butt")
                    ax.quiver(*line.mean(axis=0), *(moved.mean(axis=0) - line.mean(axis=0)),
                              color="#ff8c00", lw=1.2, arrow_length_ratio=0.3, zorder=3)
                else:
                    ax.plot(*line.T, color="0.35", lw=4, zorder=3, solid_capstyle="butt")
            if True in drawn:
                handles.append(matplotlib.lines.Line2D([], [], color="#ff8c00", lw=4,
                                                       label="settling support, moved (arrow: its motion)"))
            if False in drawn:
                handles.append(matplotlib.lines.Line2D([], [], color="0.35", lw=4, label="fixed support"))

    # the line of thrust (limit load, minimum thickness): the centres of
    # pressure of the joints, in the undeformed geometry
    thrust_csv = os.path.join(os.path.dirname(args.blocks_vtu), "thrust_line.csv")
    if os.path.exists(thrust_csv):
        rows = [line.split(",") for line in open(thrust_csv) if line[0].isdigit()]
        if rows:
            xyz = np.array([[float(r[3]), float(r[4]), float(r[5])] for r in rows])
            if strip:
                xyz = xyz[np.argsort(xyz[:, 0])]
                ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], "k.-", lw=1.0, ms=3, zorder=5)
                handles.append(matplotlib.lines.Line2D([], [], color="k", marker=".", label="line of thrust"))
            else:
                ax.scatter(xyz[:, 0], xyz[:, 1], xyz[:, 2], c="k", s=4, zorder=5)
                handles.append(matplotlib.lines.Line2D([], [], color="k", marker=".", ls="",
                                                       label="centres of pressure"))

    # scale bar: a round length along x at the foot of the vault's near side
    # scale bar: along the vault's longer plan direction, at the foot of
    # the corner nearest to the camera
    bar = nice_length(extent.max())
    corner = np.array([lo[0] if math.cos(z) < 0 else hi[0], lo[1] if math.sin(z) < 0 else hi[1], lo[2]])
    along = 1 if extent[1] >= extent[0] else 0
    end = corner.copy()
    end[along] += bar if corner[along] == lo[along] else -bar
    ax.plot(*np.column_stack([corner, end]), color="k", lw=3, zorder=6, solid_capstyle="butt")
    ax.text(*((corner + end) / 2 - np.array([0, 0, 0.05 * extent.max()])), f"{bar:g} m", ha="center",
            va="top", fontsize=9, zorder=6)

    # equal scales on the three axes, the box fitted to the vault
    pad = 0.04 * extent.max()
    for setter, a, b in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), lo - pad, hi + pad):
        setter(a, b)
    ax.set_box_aspect(tuple(hi - lo + 2 * pad), zoom=1.05)
    ax.set_axis_off()
    ax.view_init(elev=elevation, azim=azimuth)
    heading = f"{args.title}: " if args.title else ""
    ax.set_title(f"{heading}deformed vault, displacements × {args.amplification:.3g}\n{subtitle}", fontsize=10)
    if handles:
        ax.legend(handles=handles, loc="upper left", fontsize=7.5, frameon=False)
    fig.subplots_adjust(left=0, right=0.95, bottom=0, top=0.93)
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
