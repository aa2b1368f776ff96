// A half model meshed with triangles (no Mesh.RecombineAll): penny must refuse it.
DefineConstant[ c = 1, R = 10, H = 10 ];
Point(1) = {0, 0, 0}; Point(2) = {c, 0, 0}; Point(3) = {R, 0, 0};
Point(4) = {R, H, 0}; Point(5) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Curve(1) = {5}; Physical Curve(2) = {1}; Physical Curve(3) = {2}; Physical Curve(4) = {3, 4};
Physical Surface(1) = {1};
Mesh.MeshSizeMax = 2;
