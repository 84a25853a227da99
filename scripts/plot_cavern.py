#!/usr/bin/python3
"""Pictures of the faulted cavern (the paper's example 3) from an mbfem run
of parameters/cavern_fault.prm: first principal stress (tension positive)
with the tensile zone outlined, displacement vectors, and the slip and gap
along the fault.

  /usr/bin/python3 scripts/plot_cavern.py RESULTS/BASE INCREMENT OUT_PREFIX [TITLE]

e.g. results/cavern 10 doc/figures/cavern_elastic; reads
RESULTS/BASE-block0{1,2}-NNNN.vtu and RESULTS/BASE-pairs-NNNN.csv and
writes OUT_PREFIX_stress.png and OUT_PREFIX_fault.png. Needs Debian's
python3-vtk9 and python3-matplotlib.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

T = math.tan(math.radians(30))


def read_block(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    data = grid.GetPointData()
    s1 = vtk_to_numpy(data.GetArray("sigma_1"))
    u = vtk_to_numpy(data.GetArray("displacement"))[:, :2]
    # DataOut writes cell data as values at the cells' points.
    # The plastic zone: cells with plastic strain (at some time), not only
    # those yielding in the last increment.
    yielded_array = data.GetArray("plastic_strain") or data.GetArray("yielded")
    centres = []
    if yielded_array is not None:
        centres = list(points[vtk_to_numpy(yielded_array) > 0])
    read_block.yielded = getattr(read_block, "yielded", []) + centres
    # Triangulate each cell's corner points (the first four of a Lagrange
    # quadrilateral) for contouring.
    triangles = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        a, b, cc, d = (ids.GetId(i) for i in range(4))
        triangles += [[a, b, cc], [a, cc, d]]
    return points, s1, u, np.array(triangles)


def main():
    base, increment, prefix = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    title = sys.argv[4] if len(sys.argv) > 4 else "Faulted cavern after excavation (elastic rock)"
    blocks = [read_block("%s-block%02d-%04d.vtu" % (base, b, increment)) for b in (1, 2)]

    fig, ax = plt.subplots(figsize=(8, 7.5))
    for points, s1, u, tri in blocks:
        near = (np.abs(points[:, 0]) < 75) & (np.abs(points[:, 1]) < 75)
        print("block: largest sigma_1 within 75 m of the cavern centre %.2f MPa at (%.1f, %.1f)"
              % (s1[near].max() / 1e6, *points[near][np.argmax(s1[near])]))
    levels = np.linspace(-30, 6, 37)
    for points, s1, u, tri in blocks:
        t = mtri.Triangulation(points[:, 0], points[:, 1], tri)
        cs = ax.tricontourf(t, np.clip(s1 / 1e6, -30, 6), levels=levels, cmap="RdBu_r",
                            norm=matplotlib.colors.TwoSlopeNorm(vmin=-30, vcenter=0, vmax=6))
        ax.tricontour(t, s1 / 1e6, levels=[0.0], colors="k", linewidths=1.2)
    fig.colorbar(cs, ax=ax, label="first principal stress sigma_1 (MPa), tension > 0; black line: sigma_1 = 0")
    for points, s1, u, tri in blocks:
        keep = (np.abs(points[:, 0]) < 75) & (np.abs(points[:, 1]) < 75)
        sel = np.where(keep)[0][::23]
        ax.quiver(points[sel, 0], points[sel, 1], u[sel, 0], u[sel, 1], scale=0.6, width=0.002, color="k")
    yielded = np.array(getattr(read_block, "yielded", []))
    if len(yielded):
        ax.plot(yielded[:, 0], yielded[:, 1], "x", color="darkgreen", ms=3,
                label="plastic zone (cells with plastic strain)")
    ax.plot([-15, 15, 15, -15, -15], [-30, -30, 30, 30, -30], "k-", lw=1.5)
    x = np.array([-80, 80])
    ax.plot(x, -20 - (x + 15) * T, "m-", lw=1.5, label="fault")
    ax.set_xlim(-75, 75)
    ax.set_ylim(-75, 75)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m), cavern centre at 400 m depth")
    ax.set_title(title + ": sigma_1 and displacement\n"
                 "(arrows: 0.1 m displacement = about 17 m on the plot)", fontsize=10)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_stress.png", dpi=110)

    with open("%s-pairs-%04d.csv" % (base, increment)) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    rows = [r for r in rows if abs(abs(float(r["x"])) - 165) > 1e-6]
    rows.sort(key=lambda r: float(r["x"]))
    x = np.array([float(r["x"]) for r in rows])
    slip = np.array([1e3 * float(r["slip_1"]) for r in rows])
    gap = np.array([1e3 * float(r["gap"]) for r in rows])
    state = [r["state"] for r in rows]
    # No line across the cavern, where the fault is excavated.
    cut = np.searchsorted(x, -15 + 5 / T)
    x_line = np.insert(x, cut, np.nan)
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(x_line, np.insert(np.abs(slip), cut, np.nan), "-", label="|slip| (tangential relative displacement)")
    ax.plot(x_line, np.insert(gap, cut, np.nan), "-", label="normal gap")
    for s, m in (("stick", "s"), ("slip", "^"), ("open", "o")):
        sel = [i for i, si in enumerate(state) if si == s]
        ax.plot(x[sel], np.abs(slip[sel]), m, ms=3, label=s)
    ax.axvspan(-15, -15 + 10 / T, color="grey", alpha=0.2, label="cavern (fault removed)")
    ax.axhline(40.45, color="grey", ls=":", lw=1)
    ax.text(-160, 41.5, "paper: left wall slides 40.45 mm", fontsize=8, color="grey")
    ax.set_xlim(-165, 165)
    ax.set_xlabel("x along the fault (m)")
    ax.set_ylabel("mm")
    ax.set_title("Slip and gap along the fault: " + title, fontsize=10)
    ax.legend(fontsize=7, ncol=1, loc="center right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_fault.png", dpi=110)


if __name__ == "__main__":
    main()
