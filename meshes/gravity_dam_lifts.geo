// The 30 m gravity dam of gravity_dam.geo built in three lifts (issue 28,
// part 3): the triangle heel (0,0), toe (24,0), crest (0,30) cut at
// y = 10 and y = 20 into lift 1 (0 <= y <= 10), lift 2 and lift 3, on the
// foundation -24 <= x <= 48, -24 <= y <= 0. Unstructured quads, h / 2
// (1 m) in the dam and on the joints, up to 3 h in the foundation; the lift joints
// and the base are shared lines, so the pairs across them are node to
// node. Material ids: 1 foundation, 2, 3, 4 the lifts from the bottom.
// Boundary ids: 1 foundation bottom, 2 the upstream face (x = 0,
// 0 <= y <= 30) that the water loads.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 gravity_dam_lifts.geo -o gravity_dam_lifts.msh
If (!Exists(h))
  h = 2;
EndIf

Point(1) = {0, 0, 0, h};    // heel
Point(2) = {24, 0, 0, h};   // toe
Point(3) = {16, 10, 0, h};  // downstream face at y = 10
Point(4) = {0, 10, 0, h};
Point(5) = {8, 20, 0, h};   // downstream face at y = 20
Point(6) = {0, 20, 0, h};
Point(7) = {0, 30, 0, h};   // crest
Point(8) = {-24, 0, 0, 3 * h};
Point(9) = {48, 0, 0, 3 * h};
Point(10) = {-24, -24, 0, 3 * h};
Point(11) = {48, -24, 0, 3 * h};

Line(1) = {1, 2};  // base joint
Line(2) = {2, 3};
Line(3) = {3, 4};  // lift joint 1
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};  // lift joint 2
Line(7) = {6, 4};
Line(8) = {5, 7};
Line(9) = {7, 6};
Line(10) = {8, 1};
Line(11) = {2, 9};
Line(12) = {9, 11};
Line(13) = {11, 10};
Line(14) = {10, 8};

Curve Loop(1) = {1, 2, 3, 4};        Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};       Plane Surface(2) = {2};
Curve Loop(3) = {-6, 8, 9};          Plane Surface(3) = {3};
Curve Loop(4) = {10, 1, 11, 12, 13, 14}; Plane Surface(4) = {4};

Recombine Surface{1, 2, 3, 4};
Mesh.Algorithm = 6;            // frontal-Delaunay
Mesh.RecombinationAlgorithm = 0;
Mesh.SubdivisionAlgorithm = 1; // all quads

Physical Surface(1) = {4};
Physical Surface(2) = {1};
Physical Surface(3) = {2};
Physical Surface(4) = {3};
Physical Curve(1) = {13};
Physical Curve(2) = {4, 7, 9};
