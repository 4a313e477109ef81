SetFactory("OpenCASCADE");
Box(1) = {-1,-1,-1,2,2,2}; Sphere(2) = {0,0,0,0.5};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.2;
