# Writes meshes/u_block.msh (tests/same_block_pair): a fixed base
# [0,2]x[0,0.5] (material 1, boundary 10 its bottom, 41 its top) and on it
# a floating U-shaped block (material 2) whose two arms face each other
# across a gap of 0.02 at x = 0.99 and 1.01 (boundary ids 60 and 61), so
# that the interface 'boundaries 60:61' pairs a block with itself; 42 the
# U's bottom, 11 and 12 its outer sides.
#
#   python3 meshes/u_block.py meshes/u_block.msh
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh_v2

out = sys.argv[1]
xs = [0., .5, .99, 1.01, 1.5, 2.]
nodes, elems = [], []
def grid(ys, cells, mat, faceid):
    base = len(nodes)
    for y in ys:
        for x in xs:
            nodes.append((x, y))
    nid = lambda i, j: base + j * len(xs) + i + 1
    present = set(cells)
    for (i, j) in cells:
        elems.append((3, mat, [nid(i, j), nid(i+1, j), nid(i+1, j+1), nid(i, j+1)]))
    for (i, j) in cells:
        # bottom, right, top, left; boundary if neighbour absent
        if (i, j-1) not in present:
            elems.append((1, faceid('b', i, j), [nid(i, j), nid(i+1, j)]))
        if (i+1, j) not in present:
            elems.append((1, faceid('r', i, j), [nid(i+1, j), nid(i+1, j+1)]))
        if (i, j+1) not in present:
            elems.append((1, faceid('t', i, j), [nid(i+1, j+1), nid(i, j+1)]))
        if (i-1, j) not in present:
            elems.append((1, faceid('l', i, j), [nid(i, j+1), nid(i, j)]))
def base_id(s, i, j):
    return {'b': 10, 't': 41}.get(s, 20)
grid([0., .5], [(i, 0) for i in range(5)], 1, base_id)
def u_id(s, i, j):
    if s == 'b' and j == 0: return 42
    if s == 'l' and i == 0 and j >= 1: return 11
    if s == 'r' and i == 4 and j >= 1: return 12
    if s == 'r' and i == 1 and j >= 1: return 60
    if s == 'l' and i == 3 and j >= 1: return 61
    return 20
cells = [(i, 0) for i in range(5)] + [(i, j) for j in (1, 2) for i in (0, 1, 3, 4)]
grid([.5, 1., 1.5, 2.], cells, 2, u_id)
gmsh_v2.write(out, nodes, elems)
