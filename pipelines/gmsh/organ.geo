// A closed organ-like body: two fused ellipsoidal lobes 0.15 m long, flattened where it rests
// (z = -0.02, physical surface "base") and where it is lifted (z = 0.022, physical surface
// "top"). Mesh size from the command line: gmsh -3 -clmax 0.005 organ.geo.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {0.075, 0.045, 0.035}} { Volume{1}; }
Sphere(2) = {0.03, 0.03, 0, 1};
Dilate {{0.03, 0.03, 0}, {0.045, 0.035, 0.03}} { Volume{2}; }
BooleanUnion(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(4) = {-0.1, -0.1, -0.02, 0.2, 0.2, 0.042};
BooleanIntersection(5) = { Volume{3}; Delete; }{ Volume{4}; Delete; };
Physical Volume("organ") = {5};
Physical Surface("base") = Surface In BoundingBox{-1, -1, -0.0201, 1, 1, -0.0199};
Physical Surface("top") = Surface In BoundingBox{-1, -1, 0.0219, 1, 1, 0.0221};
