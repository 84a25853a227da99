#!/usr/bin/python3
"""Checks a 2D block mesh written by gmsh (format 2.2, ASCII), such as
meshes/jointed_slope.msh: element types, the number of blocks (physical
surfaces), the smallest block area and the shortest cell edge, the total
area of the blocks other than block 1 (the base) and the number of cells.

  /usr/bin/python3 scripts/slope_mesh_report.py MESH.msh

mbfem needs quadrilaterals only (gmsh type 3); a block with an area far
below the others (a sliver the joints cut off at the outline) makes a
stiff, badly shaped block, so the offsets of the joint sets in the .geo are
chosen to avoid them.
"""
import sys
from collections import defaultdict


def read_msh(path):
    with open(path) as f:
        lines = [line.strip() for line in f]
    nodes, elements = {}, []
    i = lines.index("$Nodes")
    for line in lines[i + 2 : i + 2 + int(lines[i + 1])]:
        fields = line.split()
        nodes[int(fields[0])] = (float(fields[1]), float(fields[2]))
    i = lines.index("$Elements")
    for line in lines[i + 2 : i + 2 + int(lines[i + 1])]:
        fields = [int(v) for v in line.split()]
        kind, n_tags = fields[1], fields[2]
        elements.append((kind, fields[3], fields[3 + n_tags :]))
    return nodes, elements


def polygon_area(points):
    return 0.5 * sum(
        points[k][0] * points[k - 1][1] - points[k - 1][0] * points[k][1]
        for k in range(len(points))
    )


def main():
    nodes, elements = read_msh(sys.argv[1])
    kinds = defaultdict(int)
    area = defaultdict(float)
    shortest = float("inf")
    n_cells = 0
    for kind, physical, vertices in elements:
        kinds[kind] += 1
        if kind in (2, 3):
            n_cells += 1
            points = [nodes[v] for v in vertices]
            area[physical] += abs(polygon_area(points))
            for k in range(len(points)):
                dx = points[k][0] - points[k - 1][0]
                dy = points[k][1] - points[k - 1][1]
                shortest = min(shortest, (dx * dx + dy * dy) ** 0.5)
    blocks = sorted(area)
    slope = [area[p] for p in blocks if p != 1]
    print("element types (gmsh numbers: 1 line, 2 triangle, 3 quad):", dict(kinds))
    print("blocks: %d (base 1 and %d others), cells: %d" % (len(blocks), len(slope), n_cells))
    print("block areas: smallest %.4f (block %d), largest %.4f; base %.4f"
          % (min(slope), min((area[p], p) for p in blocks if p != 1)[1], max(slope), area.get(1, 0.)))
    print("total area of the blocks other than the base: %.10f" % sum(slope))
    print("shortest cell edge: %.4f" % shortest)


if __name__ == "__main__":
    main()
