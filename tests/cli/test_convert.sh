#!/usr/bin/env bash
# riemesh convert: round trips through .meshb and .msh, .vtu output, and bad inputs that leave
# no output file.
set -u
. "$(dirname "$0")/cli_lib.sh"

# stats --json without the "file" key: equal meshes give equal strings. stats_of_msh also drops
# the vertex refs, which .msh files do not carry.
stats_of() { "$R" stats --json "$1" | /usr/bin/python3 -c "import json,sys; j=json.load(sys.stdin); j.pop('file'); print(json.dumps(j, sort_keys=True))"; }
stats_of_msh() { stats_of "$1" | /usr/bin/python3 -c "import json,sys; j=json.load(sys.stdin); j['refs'].pop('vertices'); print(json.dumps(j, sort_keys=True))"; }

for src in "$SHARED/data/2d/naca0012.mesh" "$SHARED/data/vol/bunny_vol.mesh"; do
  name=$(basename "$src" .mesh)
  # .mesh -> .meshb -> .mesh is byte-identical to .mesh -> .mesh (shortest round-trip reals).
  "$R" convert "$src" "$TMP/$name.meshb" >/dev/null &&
    "$R" convert "$TMP/$name.meshb" "$TMP/$name.b.mesh" >/dev/null &&
    "$R" convert "$src" "$TMP/$name.a.mesh" >/dev/null
  if cmp -s "$TMP/$name.a.mesh" "$TMP/$name.b.mesh"; then ok "meshb-round-trip-$name"; else ko "meshb-round-trip-$name"; fi
  [ "$(stats_of "$src")" = "$(stats_of "$TMP/$name.b.mesh")" ] && ok "meshb-stats-$name" || ko "meshb-stats-$name"
  # .msh (ASCII and binary) keeps counts, element and edge refs, measures and qualities.
  for flag in "" --binary; do
    "$R" convert $flag "$src" "$TMP/$name.msh" >/dev/null &&
      [ "$(stats_of_msh "$src")" = "$(stats_of_msh "$TMP/$name.msh")" ] && ok "msh$flag-$name" || ko "msh$flag-$name"
  done
  # .vtu (write only): an XML VTK file.
  "$R" convert "$src" "$TMP/$name.vtu" >/dev/null && grep -q "<VTKFile" "$TMP/$name.vtu" &&
    ok "vtu-$name" || ko "vtu-$name"
done

# Bad inputs: exit 2 with one line, no output left.
expect_error convert-unknown-out-ext convert "$SHARED/data/2d/aile.mesh" "$TMP/out.xyz"
expect_no_file convert-unknown-out-ext-no-file "$TMP/out.xyz"
expect_error convert-unknown-in-ext convert "$TMP/in.txt" "$TMP/out1.mesh"
expect_no_file convert-unknown-in-ext-no-file "$TMP/out1.mesh"
expect_error convert-missing convert "$TMP/none.mesh" "$TMP/out2.mesh"
expect_no_file convert-missing-no-file "$TMP/out2.mesh"
head -c 3000 "$SHARED/data/2d/aile.mesh" >"$TMP/broken.mesh"
expect_error convert-truncated convert "$TMP/broken.mesh" "$TMP/out3.meshb"
expect_no_file convert-truncated-no-file "$TMP/out3.meshb"
expect_error convert-vtu-input convert "$SHARED/data/formats/naca0012.vtu" "$TMP/out4.mesh"
expect_no_file convert-vtu-input-no-file "$TMP/out4.mesh"
expect_error convert-one-arg convert "$SHARED/data/2d/aile.mesh"
# A failed conversion leaves an existing output untouched.
cp "$SHARED/data/2d/aile.mesh" "$TMP/keep.mesh"
"$R" convert "$TMP/broken.mesh" "$TMP/keep.mesh" 2>/dev/null
cmp -s "$SHARED/data/2d/aile.mesh" "$TMP/keep.mesh" && ok convert-keeps-old-output || ko convert-keeps-old-output

# --hilbert renumbers: same counts, still valid, and the file differs from the plain conversion.
"$R" convert "$SHARED/data/vol/bunny_vol.mesh" "$TMP/h.mesh" --hilbert > /dev/null &&
  "$R" check "$TMP/h.mesh" > /dev/null && "$R" convert "$SHARED/data/vol/bunny_vol.mesh" "$TMP/p.mesh" > /dev/null &&
  ! cmp -s "$TMP/h.mesh" "$TMP/p.mesh" && ok hilbert || ko hilbert
# --boundary keeps an interface between subdomains that is not listed (the unit square's two
# triangles of refs 1 and 2, only the four sides listed): it was dropped, and the domain meshed
# from the boundary lost a region (QA hunt 5 F10).
printf 'MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nTriangles\n2\n1 2 3 1\n1 3 4 2\nEdges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nEnd\n' >"$TMP/two_refs.mesh"
"$R" convert --boundary "$TMP/two_refs.mesh" "$TMP/two_refs_b.mesh" >/dev/null &&
  [ "$(awk '$1 == "Edges" {getline; print $1}' "$TMP/two_refs_b.mesh")" = 5 ] &&
  "$R" mesh "$TMP/two_refs_b.mesh" -o "$TMP/two_refs_m.mesh" 2>&1 | grep -q "2 regions" &&
  ok convert-boundary-keeps-interfaces || ko convert-boundary-keeps-interfaces
exit $fail
