// A block on a base (tests/joint_groups): the one joint between them is two
// physical surfaces, "rough" (x < 1) and "smooth" (x > 1), of different
// friction: one interface whose pairs take two joint sets' laws. The face
// x = 1 inside the top block is in a group too ("inside"), which is no
// joint: mbfem says so. gmsh -3 -format msh22 joint_groups_3d.geo
SetFactory("OpenCASCADE");
Box(1) = {0, 0, -0.5, 1, 2, 0.5};
Box(4) = {1, 0, -0.5, 1, 2, 0.5};
Box(2) = {0, 0, 0, 1, 2, 1};
Box(3) = {1, 0, 0, 1, 2, 1};
BooleanFragments{ Volume{1, 2, 3, 4}; Delete; }{}
e = 1e-6;
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Transfinite Volume{:};
Mesh.RecombineAll = 1;
Physical Volume("base", 1) = {1, 4};
Physical Volume("top", 2) = {2, 3};
Physical Surface("bottom", 1) = Surface In BoundingBox{-e, -e, -0.5 - e, 2 + e, 2 + e, -0.5 + e};
Physical Surface("rough", 11) = Surface In BoundingBox{-e, -e, -e, 1 + e, 2 + e, e};
Physical Surface("smooth", 12) = Surface In BoundingBox{1 - e, -e, -e, 2 + e, 2 + e, e};
Physical Surface("inside", 13) = Surface In BoundingBox{1 - e, -e, -e, 1 + e, 2 + e, 1 + e};
