// One block resting on a fixed base inclined at theta degrees (issue 20):
// the block is L x H (along x H normal to the slope), the base a slab of
// the same inclination, L + 2 m long and D deep, both rotated by theta
// about the origin so that the slope rises towards +x and the block would
// slide towards -x. Structured quads; the interface has n elements, so its
// nodes coincide on both sides (a conforming joint).
// Material ids: 1 base, 2 block. Boundary ids: 1 the base's bottom, 2 the
// block's up-slope face (x' = L), for a lateral pressure.
//
// With -setnumber dim3 1 the block is 3D: the profile lies in the x-z
// plane (gravity -z) and is extruded along -y by the width Bw (nb layers);
// material and boundary ids as in 2D (issue 27's 3D campaign,
// scripts/random_inclines.py --dimension 3).
//
// Regenerate (gmsh 4.8.4, Debian 12), e.g. the two blocks of issue 20:
//   gmsh -2 -format msh22 incline_block.geo -o incline_24deg.msh
//   gmsh -2 -format msh22 -setnumber L 3.04 -setnumber H 1.18 \
//        -setnumber theta 6.57 -setnumber n 4 incline_block.geo -o incline_6deg.msh
If (!Exists(L))
  L = 2.26;
EndIf
If (!Exists(H))
  H = 1.69;
EndIf
If (!Exists(theta))
  theta = 24.2;
EndIf
If (!Exists(n))
  n = 8; // elements along the interface
EndIf
If (!Exists(nh))
  nh = Ceil(n * H / L); // elements across the block
EndIf
D = 1.0;    // depth of the base
m = 1.0;    // base beyond each end of the block
nm = Ceil(n * m / L) > 1 ? Ceil(n * m / L) : 1;
nd = Ceil(n * D / L) > 1 ? Ceil(n * D / L) : 1;

Point(1) = {-m, -D, 0};
Point(2) = { 0, -D, 0};
Point(3) = { L, -D, 0};
Point(4) = { L + m, -D, 0};
Point(5) = {-m, 0, 0};
Point(6) = { 0, 0, 0};
Point(7) = { L, 0, 0};
Point(8) = { L + m, 0, 0};
Point(9) = { 0, H, 0};
Point(10) = { L, H, 0};

Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};   // base bottom
Line(4) = {5, 6};  Line(5) = {6, 7};  Line(6) = {7, 8};   // base top
Line(7) = {1, 5};  Line(8) = {2, 6};  Line(9) = {3, 7};  Line(10) = {4, 8};
Line(11) = {6, 9}; Line(12) = {9, 10}; Line(13) = {10, 7};

Curve Loop(1) = {1, 8, -4, -7};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 9, -5, -8};   Plane Surface(2) = {2};
Curve Loop(3) = {3, 10, -6, -9};  Plane Surface(3) = {3};
Curve Loop(4) = {5, -13, -12, -11}; Plane Surface(4) = {4};

Transfinite Curve{2, 5, 12} = n + 1;
Transfinite Curve{1, 3, 4, 6} = nm + 1;
Transfinite Curve{7, 8, 9, 10} = nd + 1;
Transfinite Curve{11, 13} = nh + 1;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};

If (!Exists(dim3))
  dim3 = 0;
EndIf
If (dim3 == 0)
  Rotate {{0, 0, 1}, {0, 0, 0}, theta * Pi / 180} { Surface{1, 2, 3, 4}; }
  Physical Surface(1) = {1, 2, 3};
  Physical Surface(2) = {4};
  Physical Curve(1) = {1, 2, 3};
  Physical Curve(2) = {13};
Else
  // 3D: the profile in the x-z plane (gravity is -z), rotated about the y
  // axis so that the slope again rises towards +x, extruded along y by the
  // width Bw in nb layers into hexahedra.
  Rotate {{1, 0, 0}, {0, 0, 0}, Pi / 2} { Surface{1, 2, 3, 4}; }
  Rotate {{0, 1, 0}, {0, 0, 0}, -theta * Pi / 180} { Surface{1, 2, 3, 4}; }
  If (!Exists(Bw))
    Bw = 1.0;
  EndIf
  If (!Exists(nb))
    nb = Ceil(n * Bw / L) > 1 ? Ceil(n * Bw / L) : 1;
  EndIf
  // Extrude returns the top, the volume, then the sides in the order of
  // the surface's curve loop: each base part's bottom from its first
  // curve, the block's up-slope face from curve 13, its loop's second.
  b1[] = Extrude {0, -Bw, 0} { Surface{1}; Layers{nb}; Recombine; };
  b2[] = Extrude {0, -Bw, 0} { Surface{2}; Layers{nb}; Recombine; };
  b3[] = Extrude {0, -Bw, 0} { Surface{3}; Layers{nb}; Recombine; };
  bk[] = Extrude {0, -Bw, 0} { Surface{4}; Layers{nb}; Recombine; };
  Physical Volume(1) = {b1[1], b2[1], b3[1]};
  Physical Volume(2) = {bk[1]};
  Physical Surface(1) = {b1[2], b2[2], b3[2]};
  Physical Surface(2) = {bk[3]};
EndIf
