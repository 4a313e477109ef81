// gmsh 4.8.4: gmsh -2 two_boxes_gmsh.geo -format mesh -o two_boxes_gmsh.mesh
SetFactory("OpenCASCADE");
Box(1) = {0,0,0,1,1,1}; Box(2) = {1,0,0,1,1,1};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.2;
