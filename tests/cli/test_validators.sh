#!/usr/bin/env bash
# Independent readers accept what Riemesh writes (../shared/clients/validate.py): meshio and
# FreeFem++ read an adapted 2D .mesh and its metric .sol; meshio, FreeFem++ and gmsh read 3D .mesh,
# .meshb, .msh; meshio reads .vtu. The VTK reader check runs only if python3-vtk9 is installed.
set -u
source "$(dirname "$0")/cli_lib.sh"
D=$SHARED/data
V=$SHARED/clients/validate.py
"$R" adapt "$D/formats/lshape.mesh" --metric "$D/formats/lshape_metric.sol" -o "$TMP/a2.mesh" \
  --out-metric "$TMP/a2.sol" -q || ko adapt
for ext in mesh meshb msh vtu; do
  "$R" convert "$D/vol/bunny_vol.mesh" "$TMP/v3.$ext" > /dev/null || ko "convert-$ext"
done
(cd "$TMP" && /usr/bin/python3 "$V" a2.mesh a2.sol v3.mesh v3.meshb v3.msh v3.vtu) > "$TMP/report" 2>&1
cat "$TMP/report"
for want in "meshio     a2.mesh" "freefem    a2.mesh" "sol-parser a2.sol" "meshio     v3.mesh" \
            "freefem    v3.mesh" "gmsh       v3.mesh" "meshio     v3.meshb" "freefem    v3.meshb" \
            "meshio     v3.msh" "gmsh       v3.msh" "meshio     v3.vtu"; do
  grep -q "^OK   $want" "$TMP/report" && ok "$want" || ko "$want"
done
if grep "^FAIL" "$TMP/report" | grep -v "python3-vtk9 not installed" | grep -q .; then
  ko "a validator failed"
fi
exit $fail
