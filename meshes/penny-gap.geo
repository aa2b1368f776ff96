// Half model of one penny gap for penny-verifier: 0 <= r <= R, 0 <= z <= H,
// the crack tip (c, 0) a vertex, quadrilaterals graded towards the tip.
// penny passes c, R and H from its parameter file (gmsh -setnumber); the
// values below are the defaults when meshing by hand: gmsh -2 penny-gap.geo
//
// Physical tags (numeric, read by penny as boundary and material ids):
//   curve 1   axis r = 0            u_r = 0
//   curve 2   gap face z = 0, r < c  loaded by p(r)
//   curve 3   ligament z = 0, r > c  u_z = 0
//   curve 4   far boundary r = R and z = H
//   surface 1 the solid

DefineConstant[ c = 1, R = 1000, H = 1000 ];
tip_size = 1e-3 * c;  // cell size at the tip
growth = 0.2;         // cell size grows by this much per unit distance from the tip
far_size = 0.1 * R;

Point(1) = {0, 0, 0};
Point(2) = {c, 0, 0};
Point(3) = {R, 0, 0};
Point(4) = {R, H, 0};
Point(5) = {0, H, 0};

Line(1) = {1, 2};  // gap face
Line(2) = {2, 3};  // ligament
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};  // axis

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Physical Curve(1) = {5};
Physical Curve(2) = {1};
Physical Curve(3) = {2};
Physical Curve(4) = {3, 4};
Physical Surface(1) = {1};

// Size proportional to the distance from the tip: a geometric grading.
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g + %g * F1, %g)", tip_size, growth, far_size);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// All quadrilaterals, as deal.II needs.
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;
