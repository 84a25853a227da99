// Timoshenko's cantilever, 0 <= x <= 10, -1 <= y <= 1, as a structured quad
// mesh of 20 x 4 cells (the same cells as the built-in generator's level 2).
// Physical groups give deal.II's ids: surface 1 -> material id 1 (block 1),
// lines 1..4 -> boundary ids.
//
// Regenerate the .msh (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 timoshenko_beam.geo -o timoshenko_beam.msh

Point(1) = {0, -1, 0};
Point(2) = {10, -1, 0};
Point(3) = {10, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = 21;
Transfinite Curve{2, 4} = 5;
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve("support", 1) = {4};     // x = 0
Physical Curve("loaded end", 2) = {2};  // x = 10
Physical Curve("bottom", 3) = {1};      // y = -1
Physical Curve("top", 4) = {3};         // y = 1
Physical Surface("block", 1) = {1};
