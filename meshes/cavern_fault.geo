// The paper's example 3: a cavern 30 m wide and 60 m high, its centre at
// 400 m depth, cut by a fault dipping 30 degrees that enters the left wall
// 10 m above the floor and leaves through the floor (plane strain).
//   cavern:  -15 <= x <= 15, -30 <= y <= 30 (centre at the origin);
//   model:   -165 <= x <= 165, -180 <= y <= 180: 150 m (5 cavern widths)
//            beyond each wall, 150 m above the crown and below the floor;
//   fault:   y = -20 - (x + 15) tan 30, from the left side (y = 66.6) to
//            the right side (y = -123.9).
// Material ids: 1 rock above the fault (hanging wall), 2 rock below it
// (footwall), 9 the cavern (excavated). Boundary ids (physical curves):
// 10 left side, 11 right side, 12 base, 13 top.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 cavern_fault.geo -o cavern_fault.msh
// h is the element size at the cavern before subdivision (each element
// is split in four).
If (!Exists(h))
  h = 4;
EndIf
// yw: where the fault enters the left wall (y, cavern centre at the
// origin); -20 is 10 m above the floor. It leaves through the floor while
// -30 < yw < -30 + 30 tan 30 = -12.7 (scripts/cavern_fault_position.sh
// varies it: gmsh -setnumber yw -25 ...).
If (!Exists(yw))
  yw = -20;
EndIf
H = 40;   // far field
t = Tan(30*Pi/180);

Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;

Point(1) = {-165, -180, 0, H};          // A
Point(2) = { 165, -180, 0, H};          // B
Point(3) = { 165,  180, 0, H};          // C
Point(4) = {-165,  180, 0, H};          // D
Point(5) = {-165, yw + 150*t, 0, H/2}; // FL, fault on the left side
Point(6) = { 165, yw - 180*t, 0, H/2}; // FR, fault on the right side
Point(7) = {-15, -30, 0, h};            // P1 floor left
Point(8) = { 15, -30, 0, h};            // P2 floor right
Point(9) = { 15,  30, 0, h};            // P3 crown right
Point(10) = {-15, 30, 0, h};            // P4 crown left
Point(11) = {-15, yw, 0, h};           // FW fault in the left wall
Point(12) = {-15 + (yw + 30)/t, -30, 0, h}; // FF fault in the floor

Line(1) = {1, 2};    // base
Line(2) = {2, 6};    // right side, below the fault
Line(3) = {6, 3};    // right side, above
Line(4) = {3, 4};    // top
Line(5) = {4, 5};    // left side, above
Line(6) = {5, 1};    // left side, below
Line(7) = {5, 11};   // fault, left of the cavern
Line(8) = {12, 6};   // fault, right of the cavern
Line(9) = {11, 12};  // fault across the cavern
Line(10) = {11, 10}; // left wall above the fault
Line(11) = {10, 9};  // crown
Line(12) = {9, 8};   // right wall
Line(13) = {8, 12};  // floor right of the fault
Line(14) = {12, 7};  // floor left of the fault
Line(15) = {7, 11};  // left wall below the fault

Curve Loop(1) = {5, 7, 10, 11, 12, 13, 8, 3, 4};       // hanging wall
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, -8, 14, 15, -7, 6};             // footwall
Plane Surface(2) = {2};
Curve Loop(3) = {9, -13, -12, -11, -10};               // cavern, above the fault
Plane Surface(3) = {3};
Curve Loop(4) = {14, 15, 9};                           // cavern, below
Plane Surface(4) = {4};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Surface(9) = {3, 4};
Physical Curve(10) = {5, 6};
Physical Curve(11) = {2, 3};
Physical Curve(12) = {1};
Physical Curve(13) = {4};
