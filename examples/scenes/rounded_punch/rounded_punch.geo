// A flat punch with rounded corners (examples/scenes/rounded_punch): a base [0, 4] x [-1, 0]
// (40 x 8 quadrilaterals) and a punch [1, 3] x [0, 1] whose bottom corners are rounded with
// radius 0.3 (arcs centred at (1.3, 0.3) and (2.7, 0.3), so the flat bottom is [1.3, 2.7] at
// y = 0 and the sides start at y = 0.3), 21 x 8 quadrilaterals, physical groups named as
// rounded_punch.toml uses them. Mesh with:
//   gmsh rounded_punch.geo -2 -format msh41 -o rounded_punch.msh
// rounded_punch.msh in this folder was written by lab/tests/data/make_msh.py (so that the
// repository does not need Gmsh): the same geometry and groups, but its bottom nodes are evenly
// spaced in x (21 intervals over [1, 3]) where this file puts 4 on each arc and 13 on the flat.
SetFactory("Built-in");
r = 0.3;
// base
Point(1) = {0, -1, 0}; Point(2) = {4, -1, 0}; Point(3) = {4, 0, 0}; Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
// punch: bottom = arc (1, r) -> (1 + r, 0), flat to (3 - r, 0), arc -> (3, r)
Point(5) = {1, r, 0}; Point(6) = {1 + r, r, 0}; Point(7) = {1 + r, 0, 0};
Point(8) = {3 - r, 0, 0}; Point(9) = {3 - r, r, 0}; Point(10) = {3, r, 0};
Point(11) = {3, 1, 0}; Point(12) = {1, 1, 0};
Circle(5) = {5, 6, 7};
Line(6) = {7, 8};
Circle(7) = {8, 9, 10};
Line(8) = {10, 11}; Line(9) = {11, 12}; Line(10) = {12, 5};
Curve Loop(2) = {5, 6, 7, 8, 9, 10}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 41; Transfinite Curve{2, 4} = 9;
Transfinite Curve{5, 7} = 5; Transfinite Curve{6} = 14; Transfinite Curve{9} = 22;
Transfinite Curve{8, 10} = 9;
Transfinite Surface{1};
Transfinite Surface{2} = {5, 10, 11, 12};   // corners: the bottom side is three curves
Recombine Surface{1, 2};   // quadrilaterals: hycon takes no triangles
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 4.1;
Physical Surface("base") = {1};
Physical Surface("punch") = {2};
Physical Curve("base_top") = {3};
Physical Curve("base_bottom") = {1};
Physical Curve("punch_bottom") = {5, 6, 7};
Physical Curve("punch_top") = {9};
