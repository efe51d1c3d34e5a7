// Unit test mesh: the unit cube [0,1]^3, coarse, with a physical group of each dimension.
// Regenerate: gmsh -3 -format msh41 cube.geo -o cube41.msh; gmsh -3 -format msh22 cube.geo -o cube22.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("body") = {1};
Physical Surface("bottom") = Surface In BoundingBox{-0.1, -0.1, -0.1, 1.1, 1.1, 0.1};
Physical Surface("top") = Surface In BoundingBox{-0.1, -0.1, 0.9, 1.1, 1.1, 1.1};
Physical Curve("top edge x=0") = Curve In BoundingBox{-0.1, -0.1, 0.9, 0.1, 1.1, 1.1};
Physical Point(7) = Point In BoundingBox{0.9, 0.9, 0.9, 1.1, 1.1, 1.1};
Mesh.MeshSizeMin = 0.6;
Mesh.MeshSizeMax = 0.6;
