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
exit $fail
