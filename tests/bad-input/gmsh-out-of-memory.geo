// A structured mesh of 8e8 nodes: gmsh runs out of memory (it aborted penny).
DefineConstant[ c = 1, R = 10, H = 10 ];
Point(1) = {0, 0, 0}; Point(2) = {c, 0, 0}; Point(3) = {R, 0, 0};
Point(4) = {R, H, 0}; Point(5) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Transfinite Curve{1, 2} = 20000; Transfinite Curve{3} = 39999; Transfinite Curve{4} = 39999; Transfinite Curve{5} = 39999;
Transfinite Surface{1} = {1, 3, 4, 5};
Recombine Surface{1};
Physical Curve(1) = {5}; Physical Curve(2) = {1}; Physical Curve(3) = {2}; Physical Curve(4) = {3, 4};
Physical Surface(1) = {1};
