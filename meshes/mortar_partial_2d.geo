// A short block on a longer base, meshed on their own: the base's top
// (0 <= x <= 1, 4 elements) is covered only over 0.1 <= x <= 0.9 by the
// upper block's bottom (5 elements), so the base's end faces are covered in
// part. tests/mortar_interfaces.cc checks the mortar weights there.
// gmsh -2 mortar_partial_2d.geo -format msh22 -o mortar_partial_2d.msh
// Physical groups: surfaces 1 (base) and 2 (upper block); curves 1 the
// base's bottom, 2 the sides, 3 the top, 4 the base's top, 5 the upper
// block's bottom.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Transfinite Curve{1} = 5;
Line(2) = {2, 3}; Transfinite Curve{2} = 3;
Line(3) = {3, 4}; Transfinite Curve{3} = 5;
Line(4) = {4, 1}; Transfinite Curve{4} = 3;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {0.1, 1, 0};
Point(6) = {0.9, 1, 0};
Point(7) = {0.9, 2, 0};
Point(8) = {0.1, 2, 0};
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
