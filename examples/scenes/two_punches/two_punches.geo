// Three bodies, two contact pairs (examples/scenes/two_punches): a base [0, 6] x [-1, 0]
// (24 x 4 quadrilaterals), a left punch [0.5, 2.5] x [0, 1] (9 x 4) and a right punch
// [3.5, 5.5] x [0, 0.5] (7 x 2), structured, physical groups named as two_punches.toml uses
// them. Mesh with: gmsh two_punches.geo -2 -format msh41 -o two_punches.msh
// (two_punches.msh in this folder was written by lab/tests/data/make_msh.py, which writes the
// same mesh, so that the repository does not need Gmsh.)
SetFactory("Built-in");
// base
Point(1) = {0, -1, 0}; Point(2) = {6, -1, 0}; Point(3) = {6, 0, 0}; Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
// left punch (its own nodes: the punches touch the base only through contact)
Point(5) = {0.5, 0, 0}; Point(6) = {2.5, 0, 0}; Point(7) = {2.5, 1, 0}; Point(8) = {0.5, 1, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
// right punch
Point(9) = {3.5, 0, 0}; Point(10) = {5.5, 0, 0}; Point(11) = {5.5, 0.5, 0}; Point(12) = {3.5, 0.5, 0};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 9};
Curve Loop(3) = {9, 10, 11, 12}; Plane Surface(3) = {3};
Transfinite Curve{1, 3} = 25; Transfinite Curve{2, 4} = 5;
Transfinite Curve{5, 7} = 10; Transfinite Curve{6, 8} = 5;
Transfinite Curve{9, 11} = 8; Transfinite Curve{10, 12} = 3;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};   // quadrilaterals: hycon takes no triangles
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 4.1;
Physical Surface("base") = {1};
Physical Surface("left_punch") = {2};
Physical Surface("right_punch") = {3};
Physical Curve("base_top") = {3};
Physical Curve("base_bottom") = {1};
Physical Curve("left_bottom") = {5};
Physical Curve("left_top") = {7};
Physical Curve("right_bottom") = {9};
Physical Curve("right_top") = {11};
