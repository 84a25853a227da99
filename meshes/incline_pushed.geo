// A block on an inclined base, pushed on its top face (the limit cases of
// the state iteration, issue 11; doc/state_iteration.md).
// The interface dips at theta towards +x; gravity is -y (2D) or -z (3D).
// Slope coordinates (a along the dip, b normal) map to
//   x = a cos(theta) + b sin(theta),  vertical = -a sin(theta) + b cos(theta).
// Material ids: 1 base, 2 block. Boundary ids: 1 base bottom, 2 block top.
// 2D in the x-y plane; with -setnumber dim3 1 the profile lies in the x-z
// plane and is extruded along y (width W) into hexahedra.
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 -setnumber theta 35 incline_pushed.geo -o incline_pushed_35.msh
//   gmsh -3 -format msh22 -setnumber theta 20 -setnumber dim3 1 -setnumber n 4 \
//        incline_pushed.geo -o incline_pushed_20_3d.msh
If (!Exists(theta)) theta = 35; EndIf
If (!Exists(dim3)) dim3 = 0; EndIf
If (!Exists(n)) n = 8; EndIf      // elements along the dip
L = 1; H = 0.5; B = 0.5; W = 1;  // block length and height, base depth, width
t = theta*Pi/180; c = Cos(t); s = Sin(t);
a[] = {0, L, L, 0, L, 0};
b[] = {-B, -B, 0, 0, H, H};
For i In {0:5}
  If (dim3 == 0)
    Point(i+1) = {a[i]*c + b[i]*s, -a[i]*s + b[i]*c, 0};
  Else
    Point(i+1) = {a[i]*c + b[i]*s, 0, -a[i]*s + b[i]*c};
  EndIf
EndFor
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Transfinite Curve{1, 3, 6} = n + 1;
Transfinite Curve{2, 4} = n/2 + 1;
Transfinite Curve{5, 7} = n/2 + 1;
Curve Loop(1) = {1, 2, 3, 4};   Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};  Plane Surface(2) = {2};
Transfinite Surface{1, 2}; Recombine Surface{1, 2};
If (dim3 == 0)
  Physical Surface("base", 1) = {1};
  Physical Surface("block", 2) = {2};
  Physical Curve("base bottom", 1) = {1};
  Physical Curve("block top", 2) = {6};
Else
  base[] = Extrude {0, W, 0} { Surface{1}; Layers{n}; Recombine; };
  block[] = Extrude {0, W, 0} { Surface{2}; Layers{n}; Recombine; };
  // Extrude returns the top, the volume, then the sides in the order of
  // the surface's curves: the base's bottom from curve 1, the block's top
  // from curve 6.
  Physical Volume("base", 1) = {base[1]};
  Physical Volume("block", 2) = {block[1]};
  Physical Surface("base bottom", 1) = {base[2]};
  Physical Surface("block top", 2) = {block[4]};
EndIf
