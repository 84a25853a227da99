// Timoshenko's cantilever (0 <= x <= 10, -1 <= y <= 1) cut by the inclined
// plane from (4, -1) to (6, 1) into two blocks meshed on their own: 2 cells
// along the cut on the left, 3 on the right (separate curves, so the
// meshes do not share nodes there; a mortar interface joins them).
//   gmsh -2 timoshenko_inclined_cut.geo -format msh22 -o timoshenko_inclined_cut.msh
// Physical groups: surfaces 1 (left block, supported) and 2 (right block,
// loaded, held only by the cut); curves 1 the support x = 0, 2 the loaded
// end x = 10, 3 the top and bottom faces, 4 and 5 the cut of blocks 1 and 2.
Point(1) = {0, -1, 0};
Point(2) = {4, -1, 0};
Point(3) = {6, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Transfinite Curve{1} = 5;
Line(2) = {2, 3}; Transfinite Curve{2} = 3;
Line(3) = {3, 4}; Transfinite Curve{3} = 5;
Line(4) = {4, 1}; Transfinite Curve{4} = 3;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {4, -1, 0};
Point(6) = {10, -1, 0};
Point(7) = {10, 1, 0};
Point(8) = {6, 1, 0};
Line(5) = {5, 6}; Transfinite Curve{5} = 5;
Line(6) = {6, 7}; Transfinite Curve{6} = 4;
Line(7) = {7, 8}; Transfinite Curve{7} = 5;
Line(8) = {8, 5}; Transfinite Curve{8} = 4;
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(1) = {4};
Physical Curve(2) = {6};
Physical Curve(3) = {1, 3, 5, 7};
Physical Curve(4) = {2};
Physical Curve(5) = {8};
