// Unit test cut: the square [0,1]^2 at z = 0.5, triangles only.
// Regenerate: gmsh -2 -format msh41 square.geo -o square41.msh
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0.5, 1, 1};
Physical Surface("cut") = {1};
Mesh.MeshSizeMin = 0.6;
Mesh.MeshSizeMax = 0.6;
