// Two-block toppling on a base dipping 20 deg (issue 20): a 2 x 2 m toe
// block and a 2 x 8 m column beside it, upslope, 0.01 m apart, both on a
// fixed base slab 1 m deep. Built in the frame of the base (x' down-dip,
// y' normal to the base) and rotated by -20 deg, so the base dips towards
// +x. Toe block: 0 <= x' <= 2, 0 <= y' <= 2; column: -2.01 <= x' <= -0.01,
// 0 <= y' <= 8; base: -3.01 <= x' <= 3, -1 <= y' <= 0. Elements of 2/n m
// in the blocks; the column's lower 2 m facing the toe block has the same
// nodes (in y') as the toe block's face, so they pair across the gap.
// Material ids: 1 base, 2 toe block, 3 column. Boundary ids: 1 base
// bottom, 3 the column's face towards the toe block (lower 2 m), 4 the toe
// block's face towards the column.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 toppling_pair.geo -o toppling_pair.msh
If (!Exists(n))
  n = 8; // elements per 2 m
EndIf
If (!Exists(dip))
  dip = 20;
EndIf
g = 0.01;

// base: five rectangles under the column, the gap, the toe block and
// the margins, so that it meshes with structured quads
xs = {-3.01, -2 - g, -g, 0, 2, 3};
nx = {n / 2, n, 1, n, n / 2};
For i In {0 : 5}
  Point(1 + i) = {xs(i), -1, 0};
  Point(7 + i) = {xs(i), 0, 0};
  Line(1 + i) = {1 + i, 7 + i};       // verticals
EndFor
For i In {0 : 4}
  Line(10 + i) = {1 + i, 2 + i};      // bottom
  Line(20 + i) = {7 + i, 8 + i};      // top
  Curve Loop(1 + i) = {10 + i, 2 + i, -(20 + i), -(1 + i)};
  Plane Surface(1 + i) = {1 + i};
  Transfinite Curve{10 + i, 20 + i} = nx(i) + 1;
EndFor
Transfinite Curve{1 : 6} = n / 2 + 1;
// toe block on top line 23 (x' = 0..2)
Point(30) = {2, 2, 0};
Point(31) = {0, 2, 0};
Line(30) = {11, 30}; Line(31) = {30, 31}; Line(32) = {31, 10};
Curve Loop(10) = {23, 30, 31, 32}; Plane Surface(10) = {10};
// column on top line 21 (x' = -2.01..-0.01), its right face split at y' = 2
Point(40) = {-g, 2, 0};
Point(41) = {-g, 8, 0};
Point(42) = {-2 - g, 8, 0};
Point(43) = {-2 - g, 2, 0};
Line(40) = {9, 40}; Line(41) = {40, 43}; Line(42) = {43, 8};
Line(43) = {40, 41}; Line(44) = {41, 42}; Line(45) = {42, 43};
Curve Loop(11) = {21, 40, 41, 42};  Plane Surface(11) = {11};
Curve Loop(12) = {-41, 43, 44, 45}; Plane Surface(12) = {12};
Transfinite Curve{30, 31, 32, 40, 41, 42, 44} = n + 1;
Transfinite Curve{43, 45} = 3 * n + 1;

Transfinite Surface{1 : 5, 10, 11, 12};
Recombine Surface{1 : 5, 10, 11, 12};

Rotate {{0, 0, 1}, {0, 0, 0}, -dip * Pi / 180} { Surface{1 : 5, 10, 11, 12}; }

Physical Surface(1) = {1 : 5};
Physical Surface(2) = {10};
Physical Surface(3) = {11, 12};
Physical Curve(1) = {10 : 14};
Physical Curve(3) = {40};
Physical Curve(4) = {32};
