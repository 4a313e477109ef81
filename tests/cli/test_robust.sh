#!/usr/bin/env bash
# Damaged input and impossible outputs (bench/robust_cli.py audits them at length): exit 2 with
# one line naming the file, never an internal error, a signal or a hang, and no output left.
set -u
source "$(dirname "$0")/cli_lib.sh"
D=$SHARED/data
AILE=$D/2d/aile.mesh LSHAPE=$D/formats/lshape.mesh MET=$D/formats/lshape_metric.sol

# Outputs that cannot be written: a missing folder, a folder below a regular file, a folder of the
# output's name.
touch "$TMP/file"
mkdir -p "$TMP/taken.mesh" "$TMP/taken.sol" "$TMP/taken.svg"
for out in /nonexistent/o.mesh "$TMP/file/o.mesh" "$TMP/taken.mesh"; do
  expect_error "convert-unwritable-$out" convert "$AILE" "$out"
  expect_error "adapt-unwritable-$out" adapt "$AILE" --hsiz 0.2 -o "$out" -q
done
expect_no_file convert-unwritable-no-temporary "$TMP/file/o.mesh"
expect_error render-unwritable render "$AILE" -o "$TMP/taken.svg"
expect_error hessian-unwritable metric hessian "$LSHAPE" "$D/formats/lshape.sol" --complexity 100 \
  -o "$TMP/taken.sol"
# The commands that found out after the work (14 s of meshing the rotor's volume), with a message
# about a temporary file: now before it, naming the output.
expect_error_matching mesh-unwritable "^riemesh: error: $TMP/taken.mesh: is a folder, not a file name" \
  mesh "$D/surf/rotor.mesh" -o "$TMP/taken.mesh"
expect_error_matching mesh-missing-folder \
  "^riemesh: error: /nonexistent/o.mesh: cannot write the output there (No such file or directory)$" \
  mesh "$D/surf/rotor.mesh" -o /nonexistent/o.mesh
expect_error_matching geometric-unwritable "taken.sol: is a folder" \
  metric geometric "$D/surf/rotor.mesh" -o "$TMP/taken.sol"
expect_error_matching combine-unwritable "taken.sol: is a folder" \
  metric combine "$LSHAPE" "$MET" "$MET" -o "$TMP/taken.sol"
expect_error_matching transfer-unwritable "taken.sol: is a folder" \
  transfer "$LSHAPE" "$D/formats/lshape.sol" "$LSHAPE" -o "$TMP/taken.sol"

# A metric asking for more vertices than ids hold: one tensor of 1e308 crashed adapt (SIGSEGV), a
# complexity of 1e12 ran for hours. Now refused at once.
write_metric_rows() {  # PATH ROW: lshape_metric.sol with its sixth tensor replaced by ROW
  awk -v row="$2" 'done == 0 && seen >= 1 { n++; if (n == 6) { print row; done = 1; next } }
    /^1 3$/ { seen = 1 } { print }' "$MET" >"$1"
}
write_metric_rows "$TMP/huge.sol" "1e308 0 1e308"
expect_error adapt-huge-tensor adapt "$LSHAPE" --metric "$TMP/huge.sol" -o "$TMP/h.mesh" -q
expect_no_file adapt-huge-tensor-no-file "$TMP/h.mesh"
expect_error adapt-complexity-1e12 adapt "$LSHAPE" --field "$D/formats/lshape.sol" --complexity 1e12 \
  -o "$TMP/c.mesh" -q

# Several outputs: all checked before the run, so that a bad second one cannot fail after the
# first is written.
expect_error adapt-out-metric-unwritable adapt "$LSHAPE" --metric "$MET" -o "$TMP/m1.mesh" \
  --out-metric /nonexistent/m.sol -q
expect_no_file adapt-out-metric-unwritable-no-mesh "$TMP/m1.mesh"
expect_error adapt-out-fields-is-output adapt "$LSHAPE" --metric "$MET" --fields "$D/formats/lshape.sol" \
  -o "$TMP/m2.mesh" --out-fields "$TMP/m2.mesh" -q
expect_no_file adapt-out-fields-is-output-no-mesh "$TMP/m2.mesh"
expect_error adapt-out-fields-not-sol adapt "$LSHAPE" --field "$D/formats/lshape.sol" --complexity 200 \
  -o "$TMP/m3.mesh" --out-fields "$TMP/m3.txt" -q
expect_no_file adapt-out-fields-not-sol-no-mesh "$TMP/m3.mesh"
# metric combine --mode lp: one output per sub-interval, the second unwritable.
SOL=$MET  # SPD tensors, as Hessian samples
expect_error combine-lp-second-unwritable metric combine "$SOL" "$SOL" --mode lp --complexity 300 \
  --intervals 2 --mesh "$LSHAPE" -o "$TMP/lp1.sol,/nonexistent/lp2.sol"
expect_no_file combine-lp-second-unwritable-no-first "$TMP/lp1.sol"

# A full disk at the second output (simulated by a file size limit, SIGXFSZ ignored so that the
# write fails with EFBIG): the first output, already written, is not put in place either.
awk 'BEGIN { n = 0 } /^Vertices/ { getline; n = $1 } END {
  print "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n" n; printf "20"
  for (k = 0; k < 20; ++k) printf " 1"; print ""
  for (v = 0; v < n; ++v) { for (k = 0; k < 20; ++k) printf "%.15f ", v * 0.001 + k; print "" }
  print "End" }' "$LSHAPE" >"$TMP/f20.sol"
err=$( (trap '' XFSZ; ulimit -f 300; "$R" adapt "$LSHAPE" --hsiz 0.02 --fields "$TMP/f20.sol" \
        -o "$TMP/full.meshb" --out-fields "$TMP/full.sol" -q) 2>&1); code=$?
[ "$code" -eq 2 ] && [[ "$err" == "riemesh: error: $TMP/full.sol: "* ]] &&
  ok "disk-full-second-output ($err)" || ko "disk-full-second-output: $code $err"
expect_no_file disk-full-no-first-output "$TMP/full.meshb"
expect_no_file disk-full-no-second-output "$TMP/full.sol"
"$R" adapt "$LSHAPE" --hsiz 0.02 --fields "$TMP/f20.sol" -o "$TMP/full.meshb" --out-fields "$TMP/full.sol" -q
[ "$(stat -c %s "$TMP/full.meshb")" -lt 153600 ] && [ "$(stat -c %s "$TMP/full.sol")" -gt 153600 ] &&
  ok "disk-full-sizes-straddle-the-limit" || ko "disk-full-sizes: $(stat -c %s "$TMP/full.meshb" "$TMP/full.sol")"

# Out of memory (an address-space limit; not under the sanitizers, whose shadow memory needs
# more than the limit): a one-line error and exit 2, no output (it was "internal error:
# std::bad_alloc", exit 3).
if ldd "$R" 2>/dev/null | grep -q -e libasan -e libubsan; then
  ok "out-of-memory (skipped: sanitizer build)"
else
  err=$( (ulimit -v 600000; "$R" adapt "$LSHAPE" --hsiz 0.0005 -o "$TMP/oom.mesh" -q) 2>&1); code=$?
  [ "$code" -eq 2 ] && [[ "$err" == "riemesh: error: out of memory: "* ]] &&
    ok "out-of-memory ($err)" || ko "out-of-memory: $code $err"
  expect_no_file out-of-memory-no-output "$TMP/oom.mesh"
fi

# What the library finds inside a mesh names the file: a clockwise triangle (adapt), no elements
# (render, adapt), a degenerate tetrahedron (adapt --optim).
write_two_triangles "$TMP/cw.mesh"
sed -i 's/^1 2 3 1$/1 3 2 1/' "$TMP/cw.mesh"
sed 's/^Triangles$/Triangels/' "$AILE" >"$TMP/notri.mesh"
for args in "adapt $TMP/cw.mesh --hsiz 0.2 -o $TMP/n.mesh -q" "adapt $TMP/notri.mesh --hsiz 0.2 -o $TMP/n.mesh -q" \
            "render $TMP/notri.mesh -o $TMP/n.svg"; do
  file=$(echo "$args" | cut -d' ' -f2)
  # (the misspelt keyword is noted on a line of its own before the error)
  err=$("$R" $args 2>&1 >/dev/null | grep -v "^riemesh: note: .*unknown keyword")
  [[ "$err" == "riemesh: error: $file: "* ]] && ok "names-file ($err)" || ko "names-file: $args: $err"
done
err=$("$R" adapt "$TMP/cw.mesh" --hsiz 0.2 -o "$TMP/n.mesh" -q 2>&1)
[ "$err" = "riemesh: error: $TMP/cw.mesh: triangle 1 is clockwise or degenerate" ] &&
  ok "names-the-file's-triangle" || ko "names-the-file's-triangle: $err"
# --hsiz 1e-300: 1/h² overflows; the error named an infinite metric coefficient, not the option.
err=$("$R" adapt "$AILE" --hsiz 1e-300 -o "$TMP/s.mesh" 2>&1)
[[ "$err" == "riemesh: error: --hsiz "* ]] && ok "adapt-hsiz-1e-300 ($err)" || ko "adapt-hsiz-1e-300: $err"
# demo --dir on a file or an empty name: bad input at once (an internal error after the demo ran).
touch "$TMP/afile"
expect_error_matching demo-dir-file "afile: cannot make the demo's folder" demo --dir "$TMP/afile"
expect_error_matching demo-dir-empty "empty folder name" demo --dir ""
# Option values out of range name the option (they blamed the mesh or wrote unreadable files).
expect_error_matching adapt-hmin-huge "^riemesh: error: --hmin must be" adapt "$AILE" --hsiz 0.1 --hmin 1e300 -o "$TMP/s.mesh"
expect_error_matching hessian-hmax-tiny "^riemesh: error: --hmax must be" metric hessian "$SHARED/data/formats/lshape.mesh" "$SHARED/data/formats/lshape.sol" \
  --complexity 100 --hmax 1e-320 -o "$TMP/h.sol"
# Options that apply to another one were accepted and ignored, even with invalid values.
L="$SHARED/data/formats/lshape"
expect_error_matching adapt-norm-without-field "^riemesh: error: --norm applies to --field" \
  adapt "$L.mesh" --metric "${L}_metric.sol" --norm abc -o "$TMP/s.mesh"
expect_error_matching adapt-out-fields-alone "^riemesh: error: --out-fields applies to --fields" \
  adapt "$L.mesh" --hsiz 0.2 --out-fields "$TMP/f.sol" -o "$TMP/s.mesh"
expect_error_matching convert-binary-mesh "^riemesh: error: --binary applies to .msh" \
  convert --binary "$AILE" "$TMP/o.mesh"
expect_error_matching stats-width-alone "^riemesh: error: --width applies to --plot" stats "$AILE" --width 100
expect_error_matching combine-lp-option "^riemesh: error: --complexity applies to --mode lp" \
  metric combine "${L}_metric.sol" --mesh "$L.mesh" --complexity 5 -o "$TMP/c.sol"
expect_error_matching unsteady-time-intersect "^riemesh: error: --time applies to --combine lp" \
  unsteady --complexities 200 --combine intersect --time integral --no-single
expect_error_matching geometric-beta-alone "^riemesh: error: --beta applies to --aniso" \
  metric geometric "$SHARED/data/surf/fandisk.mesh" --beta 0.5 -o "$TMP/g.sol"
# The same given with their default values (taken for not given and accepted: QA hunt 5 F15).
for opt in "--norm 2" "--recovery lsq" "--field-name sol0"; do
  expect_error_matching "adapt-default-without-field $opt" "^riemesh: error: ${opt%% *} applies to --field" \
    adapt "$L.mesh" --hsiz 0.2 $opt -o "$TMP/s.mesh"
done
for opt in "--norm 2" "--time max" "--intervals 1"; do
  expect_error_matching "combine-default-lp-option $opt" "^riemesh: error: ${opt%% *} applies to --mode lp" \
    metric combine "${L}_metric.sol" --mesh "$L.mesh" $opt -o "$TMP/c.sol"
done
expect_error_matching unsteady-default-time-intersect "^riemesh: error: --time applies to --combine lp" \
  unsteady --complexities 200 --combine intersect --time max --no-single
expect_error_matching geometric-default-beta-alone "^riemesh: error: --beta applies to --aniso" \
  metric geometric "$SHARED/data/surf/fandisk.mesh" --beta 1 -o "$TMP/g.sol"
# A folder as input, and render's output checked before the drawing (its errors carried the
# input's name).
mkdir -p "$TMP/dd.msh"
expect_error_matching folder-input "dd.msh: is a folder, not a file" check "$TMP/dd.msh"
expect_error_matching render-output-extension "^riemesh: error: $TMP/o.jpg: unknown image extension" \
  render "$AILE" -o "$TMP/o.jpg"
expect_error_matching loop-plot-folder "^riemesh: error: /nonexistent-folder/x.png: cannot write the output there (No such file or directory)" \
  loop --complexities 1000 --plot /nonexistent-folder/x.png
# A 3D mesh of Edges only: named, with the real problem (it said "no size field").
printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 0 0 0\nEdges\n1\n1 2 0\nEnd\n' >"$TMP/eo.mesh"
expect_error_matching adapt-edges-only "eo.mesh: the mesh has no triangles or tetrahedra to adapt" \
  adapt "$TMP/eo.mesh" -o "$TMP/o.mesh"
# The size guard's hint names no option the user may not have given (it said "see --hmin" of an
# --hsiz).
expect_error_matching size-guard-hint "vertices, more than .*: ask for coarser sizes, or bound them with --hmin$" \
  adapt "$AILE" --hsiz 1e-6 -o "$TMP/o.mesh"
exit $fail
