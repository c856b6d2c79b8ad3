// The two-block press (press_slide uses the mesh of ../press): a punch [1, 3] x [0, 1] on a base
// [0, 4] x [-1, 0], structured quadrilateral meshes (16 x 4 and 9 x 4), physical groups named
// as press.toml uses them. Mesh with: gmsh press.geo -2 -format msh41 -o press.msh
// (press.msh in this folder was written by lab/tests/data/make_msh.py, which writes the same
// mesh, so that the repository does not need Gmsh.)
SetFactory("Built-in");
Point(1) = {0, -1, 0}; Point(2) = {4, -1, 0}; Point(3) = {4, 0, 0}; Point(4) = {0, 0, 0};
Point(5) = {1, 0, 0}; Point(6) = {3, 0, 0}; Point(7) = {3, 1, 0}; Point(8) = {1, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 17; Transfinite Curve{2, 4} = 5;
Transfinite Curve{5, 7} = 10; Transfinite Curve{6, 8} = 5;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};   // quadrilaterals: hycon takes no triangles
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 4.1;
Physical Surface("base") = {1};
Physical Surface("punch") = {2};
Physical Curve("base_top") = {3};
Physical Curve("base_bottom") = {1};
Physical Curve("punch_bottom") = {5};
Physical Curve("punch_top") = {7};
Physical Curve("punch_left") = {8};
Physical Point("punch_corner") = {5};
