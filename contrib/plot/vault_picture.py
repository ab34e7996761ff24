#!/usr/bin/python3
"""Render the deformed blocks of a rigid-block analysis (blocks.vtu, ASCII,
as written by masonry) to a PNG: extrados faces coloured by block, block
outlines in black, so the crack pattern is visible without ParaView.

Usage: vault_picture.py blocks.vtu vault.png [title]
"""
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402


def read_vtu(path):
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    points = np.array(piece.find("Points/DataArray").text.split(), float).reshape(-1, 3)
    arrays = {a.get("Name"): a.text.split() for a in piece.iter("DataArray") if a.get("Name")}
    conn = np.array(arrays["connectivity"], int).reshape(-1, 8)
    block = np.array(arrays["block_id"], int)
    return points, conn, block


def main():
    vtu, png = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else ""
    points, conn, block = read_vtu(vtu)
    top = points[conn[:, 4:8]]  # extrados faces
    normals = np.cross(top[:, 1] - top[:, 0], top[:, 3] - top[:, 0])
    norm = np.linalg.norm(normals, axis=1)
    norm[norm == 0] = 1
    light = np.abs(normals @ np.array([0.3, -0.5, 0.8]) / norm)
    cmap = plt.get_cmap("tab20")
    colours = np.array([cmap(b % 20) for b in block])
    colours[:, :3] *= (0.55 + 0.45 * light)[:, None]

    fig = plt.figure(figsize=(9, 6), dpi=110)
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(top, facecolors=colours, edgecolors="none"))
    # block outlines: edges of sub-faces that lie on a block boundary
    edges = {}
    for cell, b in enumerate(block):
        q = conn[cell, 4:8]
        for a, c in ((0, 1), (1, 2), (2, 3), (3, 0)):
            key = tuple(sorted((q[a], q[c])))
            edges.setdefault(key, []).append(b)
    lines = [points[list(k)] for k, bs in edges.items() if len(bs) == 1]
    ax.add_collection3d(Line3DCollection(lines, colors="k", linewidths=0.8))
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.view_init(elev=25, azim=-60)
    ax.set_title(f"{title}: deformed blocks (displacements amplified)" if title else "deformed blocks")
    fig.tight_layout()
    fig.savefig(png)


if __name__ == "__main__":
    main()
