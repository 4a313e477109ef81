// A box with a cylinder through it (two volumes; the cylinder's side is a curved interface whose
// rims lie on the box's top and bottom faces). gmsh -3 cylinder_through_box.geo -format mesh
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, -1, 2, 2, 2};
Cylinder(2) = {0, 0, -1, 0, 0, 2, 0.4};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.35;
