#!/usr/bin/python3
"""Write report.html for a wallette run from its output files.

The page (the template and scripts of share/masonry/scripts/report/, with
Debian's plotly.js inside, gzip-compressed) shows the wallette in 3D at a
chosen output step (a slider): the cells coloured by damage, deleted cells
hidden, the joints that open drawn by their opening; the stress-strain
curve with its cycles, the cycle and envelope tables, and the key numbers
of summary.json.

It reads only the run's files: summary.json (or --summary, the summary of
a run still being written), curve.csv, cycles.csv, envelope.csv, the
fields (solution.pvd with its VTU files, or solution.xdmf with its HDF5
files) and the joint fields (interfaces.pvd), so it runs after masonry or
on an old output directory.

Usage: wallette_report.py OUTPUT_DIR [--summary FILE] [--output FILE]
(--output: default OUTPUT_DIR/report.html, written under a temporary name
and renamed when complete)
"""
import argparse
import base64
import csv
import json
import os
import xml.etree.ElementTree as ET

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# a joint counts as open from this normal opening on (m): a crack of 0.01 mm
OPEN_JOINT = 1e-5
# largest number of output steps on the page (evenly picked, the last kept)
MAX_STEPS = 24


def read_csv(path):
    """Rows of a CSV file as dicts of floats (text kept where not a number),
    or [] if the file is missing."""
    if not os.path.exists(path):
        return []
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            parsed = {}
            for k, v in row.items():
                try:
                    parsed[k] = float(v)
                except (TypeError, ValueError):
                    parsed[k] = v
            rows.append(parsed)
    return rows


def collection(path):
    """(timestep, file) of a ParaView collection (.pvd)."""
    if not os.path.exists(path):
        return []
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), os.path.join(os.path.dirname(path), d.get("file")))
            for d in root.iter("DataSet")]


def read_vtu_pieces(path):
    """Points, hexahedra and point data of a .vtu or of the pieces of a
    .pvtu (deal.II writes every cell with its own vertices, and cell values
    as equal values at its vertices)."""
    import meshio
    files = [path]
    if path.endswith(".pvtu"):
        root = ET.parse(path).getroot()
        files = [os.path.join(os.path.dirname(path), p.get("Source")) for p in root.iter("Piece")]
    points, cells, data = [], [], {}
    offset = 0
    for f in files:
        m = meshio.read(f)
        hexes = [c.data for c in m.cells if c.type == "hexahedron"]
        if not hexes:
            continue
        points.append(m.points)
        cells.append(np.concatenate(hexes) + offset)
        for k, v in m.point_data.items():
            data.setdefault(k, []).append(np.asarray(v))
        offset += len(m.points)
    return (np.concatenate(points), np.concatenate(cells),
            {k: np.concatenate(v) for k, v in data.items()})


def xdmf_grids(path):
    """(timestep, grid element) of every grid of an XDMF time series."""
    for grid in ET.parse(path).getroot().iter("Grid"):
        if grid.get("GridType") == "Collection":
            continue
        time = grid.find("Time")
        yield (float(time.get("Value")) if time is not None else 0.0), grid


def xdmf_files(path):
    """(timestep, HDF5 file) of every grid of an XDMF time series (masonry's
    interfaces.xdmf); [] without the file."""
    if not os.path.exists(path):
        return []
    return [(t, os.path.join(os.path.dirname(path),
                             grid.find("Geometry").find("DataItem").text.strip().split(":")[0]))
            for t, grid in xdmf_grids(path)]


def read_xdmf_steps(path):
    """(timestep, reader) of every grid of deal.II's solution.xdmf; the
    reader gives points, hexahedra and point data from its HDF5 file."""
    steps = []
    directory = os.path.dirname(path)

    def item(element):
        text = element.find("DataItem").text.strip()
        name, dataset = text.split(":")
        return os.path.join(directory, name), dataset

    for t, grid in xdmf_grids(path):

        def reader(grid=grid):
            import h5py
            topology, geometry = item(grid.find("Topology")), item(grid.find("Geometry"))
            with h5py.File(geometry[0], "r") as h:
                points = np.array(h[geometry[1]])
            with h5py.File(topology[0], "r") as h:
                cells = np.array(h[topology[1]]).reshape(-1, 8)
            data = {}
            for attribute in grid.iter("Attribute"):
                f, d = item(attribute)
                with h5py.File(f, "r") as h:
                    data[attribute.get("Name")] = np.array(h[d])
            if points.shape[1] == 2:
                points = np.column_stack([points, np.zeros(len(points))])
            return points, cells, data
        steps.append((t, reader))
    return steps


# the faces of a VTK hexahedron, outward for a positively oriented cell
HEX_FACES = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])


def surface(points, cells, keep, scale):
    """The faces of the kept cells that no other kept cell shares (matched
    by their vertices' coordinates, since every cell has its own
    vertices), and the cell of each."""
    keys = np.round(points / scale).astype(np.int64)
    _, vertex = np.unique(keys, axis=0, return_inverse=True)
    vertex = vertex.reshape(-1)
    kept = np.nonzero(keep)[0]
    faces = cells[kept][:, HEX_FACES].reshape(-1, 4)
    owner = np.repeat(kept, 6)
    ids = np.sort(vertex[faces], axis=1)
    _, index, counts = np.unique(ids, axis=0, return_index=True, return_counts=True)
    outer = index[counts == 1]
    return faces[outer], owner[outer]


def damage_fields(data):
    """The point-data names that are damages (between 0 and 1)."""
    return [k for k in data if "damage" in k]


class Positions:
    """The undeformed positions of all steps, shared (rounded to SCALE m):
    a step refers to them by index."""

    def __init__(self, scale):
        self.scale = scale
        self.index = {}
        self.list = []

    def ids(self, points):
        out = []
        for key in map(tuple, np.round(points / self.scale).astype(np.int64)):
            k = self.index.get(key)
            if k is None:
                k = self.index[key] = len(self.list)
                self.list.append(key)
            out.append(k)
        return out

    def flat(self):
        return [round(c * self.scale, 9) for key in self.list for c in key]


# displacements on the page, in units of this length (m)
DISPLACEMENT_UNIT = 1e-7


def step_data(points, cells, data, positions):
    """What the page draws of one output step: the surface of the cells
    left, its vertices (a position and a displacement: the two sides of an
    open joint stay apart), the damages of each face."""
    first = cells[:, 0]
    deleted = data.get("deleted", np.zeros(len(points))).reshape(-1)[first] > 0.5
    faces, owner = surface(points, cells, ~deleted, positions.scale)
    u = data.get("displacement", np.zeros((len(points), 3))).reshape(len(points), -1)[:, :3]
    corners = faces.reshape(-1)
    where = np.array(positions.ids(points[corners]), dtype=np.int64)
    moved = np.round(u[corners] / DISPLACEMENT_UNIT).astype(np.int64)
    key = np.column_stack([where, moved])
    unique, inverse = np.unique(key, axis=0, return_inverse=True)
    values = {}
    for name in damage_fields(data):
        values[name] = np.round(data[name].reshape(-1)[first][owner], 3).tolist()
    return {
        "v": unique[:, 0].tolist(),
        "u": unique[:, 1:].reshape(-1).tolist(),
        "quads": inverse.reshape(-1).tolist(),
        "values": values,
        "deleted": int(deleted.sum()),
        "cells": int(len(cells)),
    }


def joints_data(path, points, data, positions):
    """The joint faces of interfaces_NNNN.vtu (or .h5) that open more than
    OPEN_JOINT, with the displacement of the cells' vertices there (the
    mean of the two sides)."""
    if path.endswith(".h5"):
        import h5py
        with h5py.File(path, "r") as h:
            joint_points = np.array(h["nodes"])
            quads = np.array(h["cells"]).reshape(-1, 4)
            opening = np.array(h["normal_opening"]).reshape(-1)
    else:
        import meshio
        m = meshio.read(path)
        joint_points = m.points
        quads = np.concatenate([c.data for c in m.cells if c.type == "quad"]) if m.cells else np.zeros((0, 4), int)
        opening = np.asarray(m.cell_data.get("normal_opening", [np.zeros(len(quads))])[0]).reshape(-1)
    open_ = np.nonzero(opening > OPEN_JOINT)[0]
    u = data.get("displacement", np.zeros((len(points), 3))).reshape(len(points), -1)[:, :3]
    keys = np.round(points / positions.scale).astype(np.int64)
    _, vertex = np.unique(keys, axis=0, return_inverse=True)
    vertex = vertex.reshape(-1)
    mean = np.zeros((vertex.max() + 1, 3))
    np.add.at(mean, vertex, u)
    mean /= np.bincount(vertex)[:, None]
    lookup = {tuple(k): vertex[i] for i, k in enumerate(keys)}
    corners = quads[open_].reshape(-1)
    where = positions.ids(joint_points[corners])
    d = [mean[lookup[tuple(k)]] if tuple(k) in lookup else np.zeros(3)
         for k in np.round(joint_points[corners] / positions.scale).astype(np.int64)]
    d = np.round(np.array(d).reshape(-1, 3) / DISPLACEMENT_UNIT).astype(np.int64)
    return {"v": where, "u": d.reshape(-1).tolist(), "opening": np.round(opening[open_], 9).tolist(),
            "n_joints": int(len(quads))}


def page_data(directory, summary):
    curve = read_csv(os.path.join(directory, "curve.csv"))
    data = {"summary": summary, "curve": {}, "cycles": read_csv(os.path.join(directory, "cycles.csv")),
            "envelope": read_csv(os.path.join(directory, "envelope.csv")), "steps": [],
            "open_joint": OPEN_JOINT}
    for key in ("strain", "stress_Pa", "cycle", "step", "deleted_cells", "max_damage"):
        data["curve"][key] = [r.get(key) for r in curve]

    fields = []
    if os.path.exists(os.path.join(directory, "solution.pvd")):
        fields = [(t, (lambda f=f: read_vtu_pieces(f))) for t, f in collection(os.path.join(directory, "solution.pvd"))]
    elif os.path.exists(os.path.join(directory, "solution.xdmf")):
        fields = read_xdmf_steps(os.path.join(directory, "solution.xdmf"))
    if os.path.exists(os.path.join(directory, "interfaces.pvd")):
        joint_files = collection(os.path.join(directory, "interfaces.pvd"))
    else:
        joint_files = xdmf_files(os.path.join(directory, "interfaces.xdmf"))
    joints = dict(joint_files)
    if len(fields) > MAX_STEPS:
        pick = sorted(set(np.linspace(0, len(fields) - 1, MAX_STEPS).round().astype(int)))
        fields = [fields[k] for k in pick]
    largest, size = 0.0, 0.0
    positions = None
    for number, (t, reader) in enumerate(fields):
        points, cells, d = reader()
        size = max(size, float(np.ptp(points, axis=0).max()))
        if positions is None:
            positions = Positions(1e-6 * size)
        step = step_data(points, cells, d, positions)
        step["strain"] = t
        largest = max(largest, DISPLACEMENT_UNIT * max((abs(x) for x in step["u"]), default=0))
        # the joint file written at the same output step
        jf = joints.get(t)
        if jf is None and number < len(joint_files):
            jf = joint_files[number][1]
        step["joints"] = joints_data(jf, points, d, positions) if jf and os.path.exists(jf) else None
        data["steps"].append(step)
    data["positions"] = positions.flat() if positions else []
    data["displacement_unit"] = DISPLACEMENT_UNIT
    data["amplification"] = 0.05 * size / largest if largest > 0 else 1.0
    data["size"] = size
    return data


def fill(template, parts):
    """The template with every marker replaced, in one pass."""
    out, at = [], 0
    while True:
        found = [(template.find(m, at), m) for m in parts if template.find(m, at) >= 0]
        if not found:
            out.append(template[at:])
            return "".join(out)
        position, marker = min(found)
        out.append(template[at:position])
        out.append(parts[marker])
        at = position + len(marker)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory")
    parser.add_argument("--summary", help="summary JSON (default: DIRECTORY/summary.json)")
    parser.add_argument("--output", help="the page (default: DIRECTORY/report.html)")
    args = parser.parse_args()
    with open(args.summary or os.path.join(args.directory, "summary.json")) as f:
        summary = json.load(f)
    data = page_data(args.directory, summary)
    part = os.path.join(HERE, "report")
    read = lambda name: open(os.path.join(part, name), encoding="utf-8").read()  # noqa: E731
    plotly = os.path.join(part, "plotly.js.gz")
    if not os.path.exists(plotly):
        raise FileNotFoundError(2, "report/plotly.js.gz not found (install python3-plotly and re-run "
                                   "contrib/setup: the build compresses its plotly.js)", plotly)
    with open(plotly, "rb") as f:
        plotly_b64 = base64.b64encode(f.read()).decode("ascii")
    text = json.dumps(data, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    title = f"masonry: wallette — {summary.get('parameter_file', args.directory)}"
    html = fill(read("page.html"), {
        "{{TITLE}}": title.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;"),
        "{{STYLE}}": read("report.css"),
        "{{DATA}}": text,
        "{{PLOTLY}}": plotly_b64,
        "{{SCRIPT}}": read("common.js") + "\n" + read("wallette.js"),
    })
    output = args.output or os.path.join(args.directory, "report.html")
    partial = os.path.join(os.path.dirname(output) or ".", f".{os.path.basename(output)}.{os.getpid()}.part")
    try:
        with open(partial, "w", encoding="utf-8") as f:
            f.write(html)
        os.replace(partial, output)
    finally:
        if os.path.exists(partial):
            os.remove(partial)


if __name__ == "__main__":
    main()
