// Variant of cavern_fault.geo: the 30-degree fault enters the left wall
// 10 m above the cavern's mid-height and leaves through the right wall,
// 7.3 m below it, so it cuts both walls and neither the crown nor the floor.
//   cavern:  -15 <= x <= 15, -30 <= y <= 30 (centre at the origin);
//   model:   -165 <= x <= 165, -180 <= y <= 180;
//   fault:   y = 10 - (x + 15) tan 30.
// Material ids: 1 above the fault, 2 below, 9 the cavern (excavated).
// Boundary ids: 10 left side, 11 right side, 12 base, 13 top.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 cavern_fault_walls.geo -o cavern_fault_walls.msh
If (!Exists(h))
  h = 4;
EndIf
H = 40;
t = Tan(30*Pi/180);

Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;

Point(1) = {-165, -180, 0, H};         // A
Point(2) = { 165, -180, 0, H};         // B
Point(3) = { 165,  180, 0, H};         // C
Point(4) = {-165,  180, 0, H};         // D
Point(5) = {-165, 10 + 150*t, 0, H/2}; // FL
Point(6) = { 165, 10 - 180*t, 0, H/2}; // FR
Point(7) = {-15, -30, 0, h};           // P1
Point(8) = { 15, -30, 0, h};           // P2
Point(9) = { 15,  30, 0, h};           // P3
Point(10) = {-15, 30, 0, h};           // P4
Point(11) = {-15, 10, 0, h};           // FW, fault in the left wall
Point(12) = { 15, 10 - 30*t, 0, h};    // FE, fault in the right wall

Line(1) = {1, 2};
Line(2) = {2, 6};
Line(3) = {6, 3};
Line(4) = {3, 4};
Line(5) = {4, 5};
Line(6) = {5, 1};
Line(7) = {5, 11};   // fault, left of the cavern
Line(8) = {12, 6};   // fault, right of the cavern
Line(9) = {11, 12};  // fault across the cavern
Line(10) = {11, 10}; // left wall above the fault
Line(11) = {10, 9};  // crown
Line(12) = {9, 12};  // right wall above the fault
Line(13) = {12, 8};  // right wall below
Line(14) = {8, 7};   // floor
Line(15) = {7, 11};  // left wall below

Curve Loop(1) = {5, 7, 10, 11, 12, 8, 3, 4};   // above the fault
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, -8, 13, 14, 15, -7, 6}; // below
Plane Surface(2) = {2};
Curve Loop(3) = {9, -12, -11, -10};            // cavern above the fault
Plane Surface(3) = {3};
Curve Loop(4) = {-9, -15, -14, -13};           // cavern below
Plane Surface(4) = {4};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Surface(9) = {3, 4};
Physical Curve(10) = {5, 6};
Physical Curve(11) = {2, 3};
Physical Curve(12) = {1};
Physical Curve(13) = {4};
