#!/usr/bin/python3
"""Pictures of a 2D jointed rock model from an mbfem run, e.g.
parameters/jointed_slope.prm: the state of every contact pair (stick, slip,
open) over the blocks, and the displacement magnitude.

  /usr/bin/python3 scripts/plot_slope.py RESULTS/BASE INCREMENT OUT_PREFIX [TITLE]

e.g. results/jointed_slope 1 doc/figures/jointed_slope. Reads every
RESULTS/BASE-blockNN-IIII.vtu (deal.II's XML VTU, zlib-compressed binary,
decoded here with numpy and zlib: no VTK module needed) and
RESULTS/BASE-pairs-IIII.csv, writes OUT_PREFIX_states.png and
OUT_PREFIX_displacement.png. Needs python3-numpy and python3-matplotlib.
"""
import base64
import csv
import glob
import re
import struct
import sys
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np
from matplotlib.collections import LineCollection

TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
         "Int64": np.int64, "UInt8": np.uint8, "UInt32": np.uint32}


def decode(text, dtype):
    """A binary DataArray of vtkZLibDataCompressor with UInt32 headers:
    base64(header) base64(compressed blocks)."""
    text = text.strip()
    n_blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_chars = 4 * ((4 * (3 + n_blocks) + 2) // 3)
    header = struct.unpack("<%dI" % (3 + n_blocks), base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    raw, at = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[at : at + size])
        at += size
    return np.frombuffer(raw, dtype=dtype)


def read_vtu(path):
    with open(path) as f:
        text = f.read()
    arrays = {}
    for attributes, body in re.findall(r"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        name = re.search(r'Name="(\w+)"', attributes)
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        values = decode(body, TYPES[kind])
        if components:
            values = values.reshape(-1, int(components.group(1)))
        arrays[name.group(1) if name else "points"] = values
    return arrays


def block_triangles(arrays):
    """Two triangles per cell from its four corners (the first four points
    of a VTK Lagrange quadrilateral, or a linear quadrilateral)."""
    offsets = arrays["offsets"]
    starts = np.concatenate(([0], offsets[:-1]))
    corners = np.array([arrays["connectivity"][s : s + 4] for s in starts])
    return np.vstack((corners[:, [0, 1, 2]], corners[:, [0, 2, 3]])), corners


def read_blocks(base, increment):
    blocks = []
    for path in sorted(glob.glob("%s-block*-%04d.vtu" % (base, increment))):
        arrays = read_vtu(path)
        triangles, corners = block_triangles(arrays)
        blocks.append((arrays["points"][:, :2], arrays["displacement"][:, :2], triangles, corners))
    return blocks


def outlines(ax, blocks, colour, width):
    segments = []
    for points, _, _, corners in blocks:
        for cell in corners:
            p = points[cell]
            segments += [[p[k], p[(k + 1) % 4]] for k in range(4)]
    ax.add_collection(LineCollection(segments, colors=colour, linewidths=width))


def read_pairs(base, increment):
    with open("%s-pairs-%04d.csv" % (base, increment)) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return rows


def plot_states(blocks, pairs, path, title):
    fig, ax = plt.subplots(figsize=(11, 7))
    outlines(ax, blocks, "0.8", 0.3)
    colours = {"stick": "tab:blue", "slip": "tab:red", "open": "tab:green"}
    for state, colour in colours.items():
        xy = np.array([[float(r["x"]), float(r["y"])] for r in pairs if r["state"] == state])
        if len(xy):
            ax.plot(xy[:, 0], xy[:, 1], "o", ms=2.5, color=colour,
                    label="%s (%d pairs)" % (state, len(xy)))
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(title + ": state of every contact pair")
    ax.legend(loc="lower left", markerscale=3)
    fig.tight_layout()
    fig.savefig(path, dpi=150)


def plot_displacement(blocks, path, title):
    fig, ax = plt.subplots(figsize=(11, 7))
    top = max(np.linalg.norm(u, axis=1).max() for _, u, _, _ in blocks)
    for points, u, triangles, _ in blocks:
        grid = mtri.Triangulation(points[:, 0], points[:, 1], triangles)
        image = ax.tripcolor(grid, np.linalg.norm(u, axis=1), shading="gouraud",
                             cmap="viridis", vmin=0., vmax=top)
    outlines(ax, blocks, "k", 0.1)
    fig.colorbar(image, ax=ax, label="|u| (m)", shrink=0.8)
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(title + ": displacement magnitude")
    fig.tight_layout()
    fig.savefig(path, dpi=150)


def main():
    base, increment, prefix = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    title = sys.argv[4] if len(sys.argv) > 4 else "Jointed rock slope under gravity"
    blocks = read_blocks(base, increment)
    if not blocks:
        sys.exit("no %s-block*-%04d.vtu: run mbfem with Output/Write VTU = true" % (base, increment))
    plot_states(blocks, read_pairs(base, increment), prefix + "_states.png", title)
    plot_displacement(blocks, prefix + "_displacement.png", title)
    print("wrote %s_states.png and %s_displacement.png" % (prefix, prefix))


if __name__ == "__main__":
    main()
