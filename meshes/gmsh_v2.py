# A 2D mesh in gmsh's MSH 2.2 format, for the small generators in meshes/
# (square_2x2_shifted.py, u_block.py): nodes as (x, y), elements as
# (gmsh type, physical tag, [node numbers from 1]); type 3 is a quadrangle
# (its tag the block's material id), type 1 a line (its tag the boundary id).
def write(out, nodes, elems):
    with open(out, 'w') as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes):
            f.write("%d %.17g %.17g 0\n" % (k + 1, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elems))
        for k, (t, tag, ns) in enumerate(elems):
            f.write("%d %d 2 %d %d %s\n" % (k + 1, t, tag, tag, " ".join(map(str, ns))))
        f.write("$EndElements\n")
