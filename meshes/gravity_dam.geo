// A 30 m gravity dam with a vertical upstream face on a fixed foundation
// block (issue 20): the dam is the triangle heel (0,0), toe (24,0),
// crest (0,30); the foundation the rectangle -24 <= x <= 48, -24 <= y <= 0.
// The dam is cut into three quadrilaterals at its centroid (8,10) so that
// it meshes with structured quads; the base joint (0 <= x <= 24) has
// elements of size h, its nodes shared with the foundation's top.
// Material ids: 1 foundation, 2 dam. Boundary ids: 1 foundation bottom,
// 2 the upstream face (x = 0, 0 <= y <= 30) that the water loads.
//
// Regenerate (gmsh 4.8.4, Debian 12), joint elements of 1, 0.5, 0.25 m:
//   gmsh -2 -format msh22 -setnumber h 1 gravity_dam.geo -o gravity_dam_h1.msh
If (!Exists(h))
  h = 1;
EndIf
k = Round(12 / h);           // elements on each half of the base
nd = Round(12 / h) > 24 ? 24 : Round(12 / h); // foundation, vertical
ns = nd;                    // foundation sides, horizontal

Point(1) = {0, 0, 0};   // heel
Point(2) = {12, 0, 0};  // mid base
Point(3) = {24, 0, 0};  // toe
Point(4) = {12, 15, 0}; // mid downstream face
Point(5) = {0, 30, 0};  // crest
Point(6) = {0, 15, 0};  // mid upstream face
Point(7) = {8, 10, 0};  // centroid
Point(8) = {-24, 0, 0};
Point(9) = {48, 0, 0};
Point(10) = {-24, -24, 0};
Point(11) = {0, -24, 0};
Point(12) = {12, -24, 0};
Point(13) = {24, -24, 0};
Point(14) = {48, -24, 0};

// dam
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 7}; Line(8) = {7, 6};
Line(9) = {7, 4};
Curve Loop(1) = {1, 7, 8, 6};  Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, -9, -7}; Plane Surface(2) = {2};
Curve Loop(3) = {-8, 9, 4, 5}; Plane Surface(3) = {3};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8, 9} = k + 1;

// foundation
Line(10) = {8, 1}; Line(11) = {3, 9};
Line(12) = {10, 11}; Line(13) = {11, 12}; Line(14) = {12, 13}; Line(15) = {13, 14};
Line(16) = {10, 8}; Line(17) = {11, 1}; Line(18) = {12, 2}; Line(19) = {13, 3};
Line(20) = {14, 9};
Curve Loop(4) = {12, 17, -10, -16}; Plane Surface(4) = {4};
Curve Loop(5) = {13, 18, -1, -17};  Plane Surface(5) = {5};
Curve Loop(6) = {14, 19, -2, -18};  Plane Surface(6) = {6};
Curve Loop(7) = {15, 20, -11, -19}; Plane Surface(7) = {7};
Transfinite Curve{13, 14} = k + 1;
Transfinite Curve{10, 11, 12, 15} = ns + 1;
Transfinite Curve{16, 17, 18, 19, 20} = nd + 1;

Transfinite Surface{1, 2, 3, 4, 5, 6, 7};
Recombine Surface{1, 2, 3, 4, 5, 6, 7};

Physical Surface(1) = {4, 5, 6, 7};
Physical Surface(2) = {1, 2, 3};
Physical Curve(1) = {12, 13, 14, 15};
Physical Curve(2) = {5, 6};
