// Three blocks stacked (tests/joint_groups): a base (block 1) with a middle
// block (2) and a top block (3) on it. Both joints are horizontal, so joint
// sets by orientation cannot tell them apart; they are the physical curves
// "lower" (1:2) and "upper" (2:3), whose laws 'Joint sets' gives by name.
// gmsh -2 joint_groups_2d.geo -o joint_groups_2d.msh   (format 4.1)
n = 5; // nodes along a joint
Point(1) = {-0.5, -0.5, 0}; Point(2) = {0, -0.5, 0}; Point(3) = {2, -0.5, 0};
Point(4) = {2.5, -0.5, 0}; Point(5) = {2.5, 0, 0}; Point(6) = {2, 0, 0};
Point(7) = {0, 0, 0}; Point(8) = {-0.5, 0, 0};
Point(9) = {0, 0.4, 0}; Point(10) = {2, 0.4, 0};
Point(11) = {0, 0.8, 0}; Point(12) = {2, 0.8, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 1};
Line(9) = {2, 7}; Line(10) = {3, 6};
Line(11) = {7, 9}; Line(12) = {9, 10}; Line(13) = {10, 6};
Line(14) = {9, 11}; Line(15) = {11, 12}; Line(16) = {12, 10};
Curve Loop(1) = {1, 9, 7, 8}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 10, 6, -9}; Plane Surface(2) = {2};
Curve Loop(3) = {3, 4, 5, -10}; Plane Surface(3) = {3};
Curve Loop(4) = {-6, -13, -12, -11}; Plane Surface(4) = {4};
Curve Loop(5) = {12, -16, -15, -14}; Plane Surface(5) = {5};
Transfinite Curve{2, 6, 12, 15} = n;
Transfinite Curve{1, 3, 4, 5, 7, 8, 9, 10, 11, 13, 14, 16} = 3;
Transfinite Surface{1:5}; Recombine Surface{1:5};
Physical Surface("base", 1) = {1, 2, 3};
Physical Surface("middle", 2) = {4};
Physical Surface("top", 3) = {5};
Physical Curve("bottom", 1) = {1, 2, 3};
Physical Curve("lower", 11) = {6};
Physical Curve("upper", 12) = {12};
