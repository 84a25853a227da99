// Hoek and Bray's wedge on two joint planes (issue 20): plane 1 dips
// 40 deg towards 135, plane 2 40 deg towards 225, the slope face dips
// 70 deg towards 180 and the top is flat, 20 m above the point O where the
// line of intersection daylights (x east, y north, z up, O at the origin).
// The line of intersection plunges 30.68 deg towards 180 (due south).
// The wedge is the tetrahedron O, A, B, C:
//   A = (-26.4285, 7.2794, 20) plane 1, face and top;
//   B = ( 26.4285, 7.2794, 20) plane 2, face and top;
//   C = (0, 33.7079, 20)       line of intersection and top.
// The rock below is cut by the vertical plane x = 0 through the line of
// intersection, so each joint plane is its own interface: block 2 (west)
// is the prism under triangle O A C extruded 10 m down, block 3 (east) the
// one under O B C. Their bottoms (boundary id 1) are clamped.
// Material ids: 1 wedge, 2 west rock, 3 east rock.
// Tetrahedra split into hexahedra (4 per tetrahedron): with n segments on
// O-C before the split, the line of intersection has 2 n elements.
//
// Regenerate (gmsh 4.8.4, Debian 12), 8 (n = 4) or 4 (n = 2) elements
// along the line of intersection:
//   gmsh -3 -format msh22 -setnumber n 4 wedge_3d.geo -o wedge_3d_8.msh
If (!Exists(n))
  n = 4;
EndIf
xa = 26.4285;
ya = 7.2794;
yc = 33.7079;
D = 10;              // depth of the rock blocks below the joint planes
h = 39.2 / n;        // length of O-C over n

Point(1) = {0, 0, 0, h};       // O
Point(2) = {-xa, ya, 20, h};   // A
Point(3) = { xa, ya, 20, h};   // B
Point(4) = {0, yc, 20, h};     // C
Point(5) = {0, 0, -D, h};      // O'
Point(6) = {-xa, ya, 20 - D, h};
Point(7) = { xa, ya, 20 - D, h};
Point(8) = {0, yc, 20 - D, h};

Line(1) = {1, 2}; Line(2) = {1, 3}; Line(3) = {1, 4};   // O-A, O-B, O-C
Line(4) = {2, 3}; Line(5) = {3, 4}; Line(6) = {4, 2};   // top edges
Line(7) = {5, 6}; Line(8) = {5, 7}; Line(9) = {5, 8};   // bottoms
Line(10) = {7, 8}; Line(11) = {8, 6};
Line(12) = {1, 5}; Line(13) = {2, 6}; Line(14) = {3, 7}; Line(15) = {4, 8};

Curve Loop(1) = {1, -6, -3};  Plane Surface(1) = {1};   // plane 1: O A C
Curve Loop(2) = {2, 5, -3};   Plane Surface(2) = {2};   // plane 2: O B C
Curve Loop(3) = {1, 4, -2};   Plane Surface(3) = {3};   // slope face O A B
Curve Loop(4) = {4, 5, 6};    Plane Surface(4) = {4};   // top A B C
Curve Loop(5) = {3, 15, -9, -12}; Plane Surface(5) = {5};  // x = 0
Curve Loop(6) = {1, 13, -7, -12}; Plane Surface(6) = {6};  // west, O A
Curve Loop(7) = {6, 13, -11, -15}; Plane Surface(7) = {7}; // west, C A
Curve Loop(8) = {7, -11, -9};  Plane Surface(8) = {8};  // west bottom
Curve Loop(9) = {2, 14, -8, -12}; Plane Surface(9) = {9};  // east, O B
Curve Loop(10) = {5, 15, -10, -14}; Plane Surface(10) = {10}; // east, B C
Curve Loop(11) = {8, 10, -9};  Plane Surface(11) = {11}; // east bottom

Surface Loop(1) = {1, 2, 3, 4};        Volume(1) = {1};
Surface Loop(2) = {1, 5, 6, 7, 8};     Volume(2) = {2};
Surface Loop(3) = {2, 5, 9, 10, 11};   Volume(3) = {3};

Transfinite Curve{3} = n + 1;
Mesh.SubdivisionAlgorithm = 2;   // all hexahedra

Physical Volume(1) = {1};
Physical Volume(2) = {2};
Physical Volume(3) = {3};
Physical Surface(1) = {8, 11};
