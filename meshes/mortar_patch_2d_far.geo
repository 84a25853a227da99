// mortar_patch_2d.geo moved by (1000, 1000) (tests/mortar_interfaces.cc):
// the projections must settle at the round-off of coordinates far from the
// origin. Mortar patch test: two blocks with 4 and 5 elements along their common
// face y = 1 (separate curves, so the meshes do not share nodes there).
// gmsh -2 mortar_patch_2d_far.geo -format msh22 -o mortar_patch_2d_far.msh
// Physical groups: surfaces 1 (lower block) and 2 (upper); curves 1 the
// base, 2 the sides, 3 the top, 4 and 5 the lower and upper faces at y = 1.
Point(1) = {0 + 1000, 0 + 1000, 0};
Point(2) = {1 + 1000, 0 + 1000, 0};
Point(3) = {1 + 1000, 1 + 1000, 0};
Point(4) = {0 + 1000, 1 + 1000, 0};
Line(1) = {1, 2}; Transfinite Curve{1} = 5;
Line(2) = {2, 3}; Transfinite Curve{2} = 3;
Line(3) = {3, 4}; Transfinite Curve{3} = 5;
Line(4) = {4, 1}; Transfinite Curve{4} = 3;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {0 + 1000, 1 + 1000, 0};
Point(6) = {1 + 1000, 1 + 1000, 0};
Point(7) = {1 + 1000, 2 + 1000, 0};
Point(8) = {0 + 1000, 2 + 1000, 0};
Line(5) = {5, 6}; Transfinite Curve{5} = 6;
Line(6) = {6, 7}; Transfinite Curve{6} = 4;
Line(7) = {7, 8}; Transfinite Curve{7} = 6;
Line(8) = {8, 5}; Transfinite Curve{8} = 4;
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(1) = {1};
Physical Curve(2) = {2, 4, 6, 8};
Physical Curve(3) = {7};
Physical Curve(4) = {3};
Physical Curve(5) = {5};
