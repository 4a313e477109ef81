SetFactory("OpenCASCADE");
Box(1) = {-1,-1,-1,2,2,2}; Cylinder(2) = {0,0,-0.5,0,0,1,0.4};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.2;
