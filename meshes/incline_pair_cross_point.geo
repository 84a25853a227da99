// Issue 65's first case: a column 1.716 x 11.369 m (block 3, down-slope)
// and a block 5.594 x 2.949 m (block 2) side by side on a fixed base
// inclined at 15.51 deg, sharing the corner at the foot of their common
// face (a point of three blocks). Written by scripts/random_incline_pairs.py's
// write_geo with 9 + 28 elements along the base joint:
//   gmsh -2 -format msh22 incline_pair_cross_point.geo -o incline_pair_cross_point.msh
Point(1) = {0, 0, 0};
Point(2) = {1.71588, 0, 0};
Point(3) = {1.71588, 2.94887, 0};
Point(4) = {0, 2.94887, 0};
Line(1) = {1, 2}; Transfinite Curve{1} = 10;
Line(2) = {2, 3}; Transfinite Curve{2} = 7;
Line(3) = {3, 4}; Transfinite Curve{3} = 10;
Line(4) = {4, 1}; Transfinite Curve{4} = 7;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {1.71588, 11.36879, 0};
Point(6) = {0, 11.36879, 0};
Line(5) = {3, 5}; Transfinite Curve{5} = 13;
Line(6) = {5, 6}; Transfinite Curve{6} = 10;
Line(7) = {6, 4}; Transfinite Curve{7} = 13;
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Point(7) = {7.31011, 0, 0};
Point(8) = {7.31011, 2.94887, 0};
Line(8) = {2, 7}; Transfinite Curve{8} = 29;
Line(9) = {7, 8}; Transfinite Curve{9} = 7;
Line(10) = {8, 3}; Transfinite Curve{10} = 29;
Curve Loop(3) = {8, 9, 10, -2}; Plane Surface(3) = {3};
Point(9) = {-1, -1, 0};
Point(10) = {0, -1, 0};
Point(11) = {-1, 0, 0};
Line(11) = {9, 10}; Transfinite Curve{11} = 3;
Line(12) = {10, 1}; Transfinite Curve{12} = 3;
Line(13) = {1, 11}; Transfinite Curve{13} = 3;
Line(14) = {11, 9}; Transfinite Curve{14} = 3;
Curve Loop(4) = {11, 12, 13, 14}; Plane Surface(4) = {4};
Point(12) = {1.71588, -1, 0};
Line(15) = {10, 12}; Transfinite Curve{15} = 10;
Line(16) = {12, 2}; Transfinite Curve{16} = 3;
Curve Loop(5) = {15, 16, -1, -12}; Plane Surface(5) = {5};
Point(13) = {7.31011, -1, 0};
Line(17) = {12, 13}; Transfinite Curve{17} = 29;
Line(18) = {13, 7}; Transfinite Curve{18} = 3;
Curve Loop(6) = {17, 18, -8, -16}; Plane Surface(6) = {6};
Point(14) = {8.31011, -1, 0};
Point(15) = {8.31011, 0, 0};
Line(19) = {13, 14}; Transfinite Curve{19} = 3;
Line(20) = {14, 15}; Transfinite Curve{20} = 3;
Line(21) = {15, 7}; Transfinite Curve{21} = 3;
Curve Loop(7) = {19, 20, 21, -18}; Plane Surface(7) = {7};
Transfinite Surface{4, 5, 6, 7, 3, 1, 2};
Recombine Surface{4, 5, 6, 7, 3, 1, 2};
Rotate {{0, 0, 1}, {0, 0, 0}, 15.50952 * Pi / 180} { Surface{4, 5, 6, 7, 3, 1, 2}; }
Physical Surface(1) = {4, 5, 6, 7};
Physical Surface(2) = {3};
Physical Surface(3) = {1, 2};
Physical Curve(1) = {11, 15, 17, 19};
Physical Curve(2) = {9};
