# Writes meshes/square_2x2_shifted.msh (issue 31's test
# tests/mortar_cross_point_roundoff): the five blocks of
# tests/mortar_cross_point_matching (a base [0,2]x[0,0.5] of 4 x 1 cells and
# a 2 x 2 square of blocks of 2 x 2 cells each above it), every block's nodes
# its own, boundary ids per face (10 the base's bottom, 11 the left sides, 20
# the other outer faces, 41 to 52 the faces of the interfaces), and the block
# of material 3 ([1,2]x[0.5,1.5]) shifted by (dx, dy): a mesh whose shared
# faces match only to round-off, as gmsh writes separately meshed curves.
#
#   python3 meshes/square_2x2_shifted.py meshes/square_2x2_shifted.msh 1e-10 0
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh_v2

out, dx, dy = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
blocks = [  # material, x0, y0, nx, ny, shift
  (1, 0., 0., 4, 1, (0, 0)),
  (2, 0., .5, 2, 2, (0, 0)),
  (3, 1., .5, 2, 2, (dx, dy)),
  (4, 0., 1.5, 2, 2, (0, 0)),
  (5, 1., 1.5, 2, 2, (0, 0)),
]
h = .5
nodes, elems = [], []
def faceid(mat, side, xm, ym):
    # side: 'b','r','t','l'
    if mat == 1:
        if side == 'b': return 10
        if side == 't': return 41 if xm < 1 else 43
        return 20
    if mat == 2:
        return {'b': 42, 'r': 45, 't': 47, 'l': 11}[side]
    if mat == 3:
        return {'b': 44, 'l': 46, 't': 49, 'r': 20}[side]
    if mat == 4:
        return {'b': 48, 'r': 51, 'l': 11, 't': 20}[side]
    if mat == 5:
        return {'b': 50, 'l': 52, 'r': 20, 't': 20}[side]
for mat, x0, y0, nx, ny, (sx, sy) in blocks:
    base = len(nodes)
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((x0 + i * h + sx, y0 + j * h + sy))
    nid = lambda i, j: base + j * (nx + 1) + i + 1
    for j in range(ny):
        for i in range(nx):
            elems.append((3, mat, [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]))
    for i in range(nx):
        elems.append((1, faceid(mat, 'b', x0 + (i + .5) * h, y0), [nid(i, 0), nid(i + 1, 0)]))
        elems.append((1, faceid(mat, 't', x0 + (i + .5) * h, y0 + ny * h), [nid(i + 1, ny), nid(i, ny)]))
    for j in range(ny):
        elems.append((1, faceid(mat, 'l', x0, y0 + (j + .5) * h), [nid(0, j + 1), nid(0, j)]))
        elems.append((1, faceid(mat, 'r', x0 + nx * h, y0 + (j + .5) * h), [nid(nx, j), nid(nx, j + 1)]))
gmsh_v2.write(out, nodes, elems)
