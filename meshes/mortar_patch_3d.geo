// Mortar patch test in 3D: two boxes with 4 x 4 and 5 x 5 hexahedra on
// their common face z = 1 (separate surfaces: the meshes share no nodes).
// gmsh -3 mortar_patch_3d.geo -format msh22 -o mortar_patch_3d.msh
// Physical groups: volumes 1 (lower block) and 2 (upper); surfaces 1 the
// base, 2 and 6 the sides, 3 the top, 4 and 5 the lower and upper faces at
// z = 1.
Geometry.AutoCoherence = 0;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Transfinite Curve{1, 2, 3, 4} = 5;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Surface{1}; Recombine Surface{1};
lower[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };
Point(101) = {0, 0, 1}; Point(102) = {1, 0, 1}; Point(103) = {1, 1, 1}; Point(104) = {0, 1, 1};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Transfinite Curve{101, 102, 103, 104} = 6;
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Transfinite Surface{101}; Recombine Surface{101};
upper[] = Extrude {0, 0, 1} { Surface{101}; Layers{3}; Recombine; };
Physical Volume(1) = {lower[1]};
Physical Volume(2) = {upper[1]};
Physical Surface(1) = {1};
Physical Surface(2) = {lower[2], lower[4], upper[2], upper[4]};
Physical Surface(6) = {lower[3], lower[5], upper[3], upper[5]};
Physical Surface(3) = {upper[0]};
Physical Surface(4) = {lower[0]};
Physical Surface(5) = {101};
