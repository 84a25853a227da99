// Two half-disks R = 8 touching at the origin (the paper's example 1).
//   lower: centre (0,-8), flat face y = -8, arc on top;   material id 1
//   upper: centre (0, 8), flat face y =  8, arc below;    material id 2
// The possible contact zone |x| <= 1.75 is its own arc on each disk, with
// N elements uniform in angle, so the nodes of the two arcs face each other
// at equal x (pairs joined by vertical lines).
// Physical ids: 1 lower flat, 2 lower free arcs, 3 lower contact arc,
//               4 upper flat, 5 upper free arcs, 6 upper contact arc.
//
// Regenerate (gmsh 4.8.4, Debian 12), N = elements in the contact zone:
//   for N in 12 18 24 36 72; do
//     gmsh -2 -format msh22 -setnumber N $N hertz.geo -o hertz_$N.msh
//   done
If (!Exists(N))
  N = 36;
EndIf
R  = 8;
xc = 1.75;
yc = Sqrt(R*R - xc*xc);   // height of the zone ends above the centre
h  = 4*xc/N;              // element size in the zone, before subdivision
H  = 3.2;                 // element size far away, before subdivision

Mesh.Algorithm = 6;              // frontal-Delaunay, then recombined
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1; // blossom
Mesh.SubdivisionAlgorithm = 1; // split every element into quads: no
                                // triangle survives recombination
Mesh.ElementOrder = 1;

For side In {0:1}
  s  = (side == 0) ? -1 : 1;   // lower: centre at y = -8, arc up
  o  = newp; Point(o) = {0, s*R, 0, H};
  p1 = newp; Point(p1) = {-R, s*R, 0, H};
  p2 = newp; Point(p2) = {-xc, s*R - s*yc, 0, h};
  p3 = newp; Point(p3) = { xc, s*R - s*yc, 0, h};
  p4 = newp; Point(p4) = { R, s*R, 0, H};
  a1 = newl; Circle(a1) = {p1, o, p2};
  a2 = newl; Circle(a2) = {p2, o, p3};
  a3 = newl; Circle(a3) = {p3, o, p4};
  f  = newl; Line(f) = {p4, p1};
  Transfinite Curve{a2} = N/2 + 1; // the subdivision doubles it to N
  cl = newll; Curve Loop(cl) = {a1, a2, a3, f};
  sf = news; Plane Surface(sf) = {cl};

  // Grade from h at the zone to H away from it.
  fd = side*10 + 1;
  Field[fd] = Distance; Field[fd].CurvesList = {a2}; Field[fd].Sampling = 200;
  ft = side*10 + 2;
  Field[ft] = Threshold; Field[ft].InField = fd;
  Field[ft].SizeMin = h; Field[ft].SizeMax = H;
  Field[ft].DistMin = 1.2; Field[ft].DistMax = 7; // fine to below the
                                                 // Hertz field (depth ~ 2a)
  If (side == 0)
    Physical Curve("lower flat", 1) = {f};
    Physical Curve("lower free arc", 2) = {a1, a3};
    Physical Curve("lower contact arc", 3) = {a2};
    Physical Surface("lower disk", 1) = {sf};
    lower_field = ft;
  Else
    Physical Curve("upper flat", 4) = {f};
    Physical Curve("upper free arc", 5) = {a1, a3};
    Physical Curve("upper contact arc", 6) = {a2};
    Physical Surface("upper disk", 2) = {sf};
  EndIf
EndFor
Field[30] = Min; Field[30].FieldsList = {2, 12};
Background Field = 30;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
