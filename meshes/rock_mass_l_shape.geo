// Issue 61: the domain of tests/rock_mass_file_2d (Mesh/Rock mass/Domain =
// file): an L-shaped rock mass, its physical group dropped by mbfem.
SetFactory("OpenCASCADE");
// an L-shaped rock mass (12 x 8 with a 4 x 4 notch at its top right)
Point(1) = {0, 0, 0}; Point(2) = {12, 0, 0}; Point(3) = {12, 4, 0};
Point(4) = {8, 4, 0}; Point(5) = {8, 8, 0}; Point(6) = {0, 8, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6}; Plane Surface(1) = {1};
Physical Surface(7) = {1};
