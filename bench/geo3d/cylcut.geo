SetFactory("OpenCASCADE");
Cylinder(1) = {0,0,0, 0,0,1, 0.5}; Cylinder(2) = {0,0,1, 0,0,1, 0.5};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.2;
