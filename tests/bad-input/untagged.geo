// A valid half model without physical tags: penny must refuse it.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {10, 0, 0};
Point(4) = {10, 10, 0}; Point(5) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SubdivisionAlgorithm = 1;
