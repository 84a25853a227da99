// The uncut body of timoshenko_inclined_cut.geo: the same beam and the same
// two quadrilateral patches on either side of the line from (4, -1) to
// (6, 1), but sharing that line (3 cells along it on both sides) and one
// physical surface, so the mesh is conforming and the beam is one block.
// The reference of the bonded inclined cut in doc/order_study.md.
//   gmsh -2 timoshenko_inclined_uncut.geo -format msh22 -o timoshenko_inclined_uncut.msh
// Physical groups: surface 1 (the beam); curves 1 the support x = 0, 2 the
// loaded end x = 10, 3 the top and bottom faces.
Point(1) = {0, -1, 0};
Point(2) = {4, -1, 0};
Point(3) = {6, 1, 0};
Point(4) = {0, 1, 0};
Point(6) = {10, -1, 0};
Point(7) = {10, 1, 0};
Line(1) = {1, 2}; Transfinite Curve{1} = 5;
Line(2) = {2, 3}; Transfinite Curve{2} = 4;
Line(3) = {3, 4}; Transfinite Curve{3} = 5;
Line(4) = {4, 1}; Transfinite Curve{4} = 4;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Line(5) = {2, 6}; Transfinite Curve{5} = 5;
Line(6) = {6, 7}; Transfinite Curve{6} = 4;
Line(7) = {7, 3}; Transfinite Curve{7} = 5;
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1, 2};
Physical Curve(1) = {4};
Physical Curve(2) = {6};
Physical Curve(3) = {1, 3, 5, 7};
