// A concrete gravity dam on a jointed rock foundation (issue 28, part 4):
// the dam is the triangle heel (0,0), toe (80,0), crest (0,100) (vertical
// upstream face, 100 m high, base 80 m). It stands on a rock wedge cut off
// the foundation by a joint dipping upstream, from (-10,-12) below the
// heel to (110,-4), where it daylights in a 4 m step of the river bed
// downstream; upstream the wedge ends at a vertical crack 0.5 m wide
// (x = -10.5 ... -10, water-filled, no contact). The rest of the
// foundation is one block, -60 <= x <= 160, -60 <= y <= 0 (-4 downstream
// of the step). The dam is built in three lifts, cut at y = 30 and y = 60
// (lift joints 56 m and 32 m long). Unstructured quads of size h (2 m
// along the joints). Material ids: 1 foundation, 2 wedge, 3, 4, 5 the
// dam's lifts from the bottom. Boundary ids: 1 the foundation's bottom, 2
// the dam's upstream face and the wedge's face in the crack (water), 3 the
// foundation's sides.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 dam_foundation.geo -o dam_foundation.msh
If (!Exists(h))
  h = 4;
EndIf
hj = h / 2;

// dam
Point(1) = {0, 0, 0, hj};
Point(2) = {80, 0, 0, hj};
Point(3) = {0, 100, 0, h};
Point(14) = {0, 30, 0, hj};   // lift joints: upstream and downstream ends
Point(15) = {56, 30, 0, hj};
Point(16) = {0, 60, 0, hj};
Point(17) = {32, 60, 0, hj};
// wedge
Point(4) = {-10, 0, 0, hj};
Point(5) = {110, 0, 0, hj};
Point(6) = {110, -4, 0, hj};
Point(7) = {-10, -12, 0, hj};
// foundation
Point(8) = {-10.5, -12.0333333333, 0, hj};
Point(9) = {-10.5, 0, 0, hj};
Point(10) = {-60, 0, 0, 2 * h};
Point(11) = {-60, -60, 0, 2 * h};
Point(12) = {160, -60, 0, 2 * h};
Point(13) = {160, -4, 0, 2 * h};

Line(1) = {1, 2};   // construction joint (dam base = wedge top)
Line(2) = {2, 15};  // downstream face, lift 1
Line(16) = {15, 17}; // downstream face, lift 2
Line(17) = {17, 3};  // downstream face, lift 3
Line(3) = {3, 16};  // upstream face, lift 3
Line(18) = {16, 14}; // upstream face, lift 2
Line(19) = {14, 1};  // upstream face, lift 1
Line(20) = {14, 15}; // lift joint 1 (y = 30)
Line(21) = {16, 17}; // lift joint 2 (y = 60)
Line(4) = {4, 1};   // wedge top upstream of the heel
Line(5) = {2, 5};   // wedge top downstream of the toe
Line(6) = {5, 6};   // step face
Line(7) = {6, 7};   // rock joint (shared with the foundation)
Line(8) = {7, 4};   // crack face of the wedge
Line(9) = {7, 8};   // crack bottom
Line(10) = {8, 9};  // crack face of the foundation
Line(11) = {9, 10};
Line(12) = {10, 11};
Line(13) = {11, 12};
Line(14) = {12, 13};
Line(15) = {13, 6};

Curve Loop(1) = {1, 2, -20, 19};       Plane Surface(1) = {1};
Curve Loop(4) = {20, 16, -21, 18};     Plane Surface(4) = {4};
Curve Loop(5) = {21, 17, 3};           Plane Surface(5) = {5};
Curve Loop(2) = {4, 1, 5, 6, 7, 8};     Plane Surface(2) = {2};
Curve Loop(3) = {-7, -15, -14, -13, -12, -11, -10, -9};
Plane Surface(3) = {3};

Recombine Surface{1, 2, 3, 4, 5};
Mesh.Algorithm = 6;            // frontal-Delaunay
Mesh.RecombinationAlgorithm = 0;
Mesh.SubdivisionAlgorithm = 1; // all quads

Physical Surface(1) = {3};
Physical Surface(2) = {2};
Physical Surface(3) = {1};
Physical Surface(4) = {4};
Physical Surface(5) = {5};
Physical Curve(1) = {13};
Physical Curve(2) = {3, 18, 19, 8};
Physical Curve(3) = {12, 14};
