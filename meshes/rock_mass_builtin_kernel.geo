// Issue 61: tests/failures/rock_mass_geometry_builtin_kernel. A rectangle
// of the built-in kernel, which OpenCASCADE cannot cut.
Point(1) = {0, 0, 0}; Point(2) = {12, 0, 0}; Point(3) = {12, 8, 0}; Point(4) = {0, 8, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
