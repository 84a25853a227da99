// A rock slope cut by two joint sets (issue 13; doc/jointed_rock.md), on a
// fixed base block. Plane strain in the x-y plane, y up, the slope face
// towards +x.
//   slope: 0 <= y <= H, from the back x = 0 to the crest x = W, the face
//          dipping psi degrees down to the toe (W + H / tan(psi), 0);
//   base:  an L-shaped block under the slope (y from -D to 0, x from -B to
//          toe + F) and behind it (x from -B to 0, up to y = H): the rock
//          mass the slope was cut from. Clamped at y = -D. Without the back
//          part the pieces the joints cut off along x = 0 hang on the cross
//          joints (the statics certificate found them as a mechanism);
//   joints: bedding dipping beta degrees towards +x (out of the slope,
//          daylighting in the face), spacing h; a cross set at right angles
//          to it (dipping 90 - beta towards -x, into the slope), spacing b;
//          persistent lines, shifted by (ob, oc), clipped to the slope.
// OpenCASCADE's BooleanFragments cuts the slope polygon by the joint lines;
// every piece is a block (physical surface 2, 3, ...), the base is physical
// surface 1, its bottom physical curve 1. Every joint curve is one segment;
// the triangles are recombined into quadrilaterals and all cells subdivided
// (Mesh.SubdivisionAlgorithm = 1), so every block edge has two cells and
// every cell is a quadrilateral that shares its nodes with the neighbour.
// The outline cuts pieces of every size off the joint pattern; the offsets
// (ob, oc) = (0.9, 1.0) were chosen among 56 pairs for the largest smallest
// piece: 0.0124 m^2 (a full block is 3.75 m^2), shortest cell edge 0.041 m
// (scripts/slope_mesh_report.py prints both). Default: 210 blocks on the
// base; H = 6, W = 4: 21.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   gmsh -2 -format msh22 jointed_slope.geo -o jointed_slope.msh
//   gmsh -2 -format msh22 -setnumber H 6 -setnumber W 4 jointed_slope.geo \
//        -o jointed_slope_small.msh
SetFactory("OpenCASCADE");
If (!Exists(H)) H = 20; EndIf      // slope height
If (!Exists(W)) W = 24; EndIf      // crest distance from the back
If (!Exists(psi)) psi = 50; EndIf  // slope face dip, degrees
If (!Exists(beta)) beta = 25; EndIf // bedding dip, degrees
If (!Exists(h)) h = 1.5; EndIf     // bedding spacing
If (!Exists(b)) b = 2.5; EndIf     // cross-joint spacing
If (!Exists(ob)) ob = 0.9; EndIf   // offsets of the two sets
If (!Exists(oc)) oc = 1.0; EndIf
B = 4; D = 4; F = 6;   // base: behind, below, in front
toe = W + H / Tan(psi * Pi / 180);

// the slope polygon, and the base: under the slope and behind it (the rock
// mass the slope was cut from), an L-shaped block
Point(1) = {0, 0, 0}; Point(2) = {toe, 0, 0}; Point(3) = {W, H, 0};
Point(4) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {-B, -D, 0}; Point(6) = {toe + F, -D, 0}; Point(7) = {toe + F, 0, 0};
Point(8) = {-B, H, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 1}; Line(8) = {4, 8};
Line(9) = {8, 5};
Curve Loop(2) = {5, 6, 7, -4, 8, 9}; Plane Surface(2) = {2};

// joint lines n . p = offset + k spacing, n the unit normal of the set,
// clipped to 0 <= y <= H and x >= 0 (they end on the base)
sb = Sin(beta * Pi / 180); cb = Cos(beta * Pi / 180);
// bedding: normal (sb, cb); along it (cb, -sb)
// cross:   normal (cb, -sb); along it (sb, cb)
R = Sqrt(toe * toe + H * H);
joints[] = {};
p = 100;
For k In {-Ceil(R / h) - 1 : Ceil(R / h) + 1}
  c = ob + k * h;
  // points of n . p = c at y = 0 and y = H: x = (c - cb y) / sb
  x0 = c / sb; x1 = (c - cb * H) / sb; y0 = 0; y1 = H;
  If (x1 < 0) x1 = 0; y1 = c / cb; EndIf
  If (x0 > 0 && x1 < toe && y1 > 0)
    Point(p) = {x0, y0, 0}; Point(p + 1) = {x1, y1, 0};
    Line(p) = {p, p + 1}; joints[] += {p}; p += 2;
  EndIf
EndFor
For k In {-Ceil(R / b) - 1 : Ceil(R / b) + 1}
  c = oc + k * b;
  // x = (c + sb y) / cb
  x0 = c / cb; x1 = (c + sb * H) / cb; y0 = 0; y1 = H;
  If (x0 < 0) x0 = 0; y0 = -c / sb; EndIf
  If (x1 > 0 && x0 < toe && y0 < H)
    Point(p) = {x0, y0, 0}; Point(p + 1) = {x1, y1, 0};
    Line(p) = {p, p + 1}; joints[] += {p}; p += 2;
  EndIf
EndFor

pieces[] = BooleanFragments{ Surface{1, 2}; Delete; }{ Curve{joints[]}; Delete; };
// the joints' pieces outside the slope are not part of any surface
dangling[] = Curve{:};
surfaces[] = Surface{:};
id = 2;
For i In {0 : #surfaces[] - 1}
  box[] = BoundingBox Surface{surfaces[i]};
  If (box[0] < -B / 2)
    Physical Surface(1) = {surfaces[i]};
  Else
    Physical Surface(id) = {surfaces[i]};
    id += 1;
  EndIf
EndFor
Physical Curve(1) = Curve In BoundingBox{-B - 1, -D - 1e-6, -1, toe + F + 1, -D + 1e-6, 1};

Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeMax = 4;
Transfinite Curve{:} = 2;
// the base's outer sides in segments of about 2
bottom[] = Curve In BoundingBox{-B - 1, -D - 1e-6, -1, toe + F + 1, -D + 1e-6, 1};
back[] = Curve In BoundingBox{-B - 1e-6, -D - 1, -1, -B + 1e-6, H + 1, 1};
Transfinite Curve{bottom[]} = Ceil((toe + F + B) / 2) + 1;
Transfinite Curve{back[]} = Ceil((H + D) / 2) + 1;
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SubdivisionAlgorithm = 1;
