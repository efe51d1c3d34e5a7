// The paper's beam (section 5) as a gmsh model: [0,0.03] x [0,0.06] x [0,0.2] m, with the
// physical groups problem-box.json uses: "fixed" (the face z = 0) and "pulled edge" (the edge
// x = 0, z = 0.2). Mesh size from the command line: gmsh -3 -clmax 0.006 box.geo.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.03, 0.06, 0.2};
Physical Volume("beam") = {1};
Physical Surface("fixed") = Surface In BoundingBox{-1e-6, -1e-6, -1e-6, 0.030001, 0.060001, 1e-6};
Physical Curve("pulled edge") = Curve In BoundingBox{-1e-6, -1e-6, 0.199999, 1e-6, 0.060001, 0.200001};
