#!/usr/bin/env bash
# riemesh render: PNG and SVG pictures of planar, surface and volume meshes; bad requests.
set -u
. "$(dirname "$0")/cli_lib.sh"

# expect_png NAME PATH WIDTH: the PNG signature, the IHDR width, a non-trivial size.
expect_png() {
  if /usr/bin/python3 - "$2" "$3" <<'PY'
import struct, sys
b = open(sys.argv[1], "rb").read()
w, h = struct.unpack(">II", b[16:24])
sys.exit(0 if b[:8] == b"\x89PNG\r\n\x1a\n" and w == int(sys.argv[2]) and h >= 100 and len(b) > 1000 else 1)
PY
  then ok "$1"; else ko "$1: $2"; fi
}

# run NAME ARGS...: riemesh must succeed (a failure is reported, not skipped).
run() { local name=$1; shift; "$R" "$@" || ko "$name: exit $?"; }

naca=$SHARED/data/2d/naca0012.mesh
run render-quality-png render "$naca" -o "$TMP/q.png" --width 500
expect_png render-quality-png "$TMP/q.png" 500
run render-size-png render "$naca" -o "$TMP/s.png" --color size
expect_png render-size-png "$TMP/s.png" 800
run render-ref-svg render "$naca" -o "$TMP/r.svg" --color ref
grep -q "</svg>" "$TMP/r.svg" && ok render-ref-svg || ko render-ref-svg
lshape=$SHARED/data/formats/lshape
run render-metric-svg render "$lshape.mesh" --metric "${lshape}_metric.sol" -o "$TMP/m.svg"
grep -q "<svg" "$TMP/m.svg" && ok render-metric-svg || ko render-metric-svg
run render-metric-size render "$lshape.mesh" --metric "${lshape}_metric.sol" --color size -o "$TMP/ms.png" --width 300
expect_png render-metric-size "$TMP/ms.png" 300
run render-surface-iso render "$SHARED/data/surf/bunny.mesh" --view iso -o "$TMP/b.png" --width 400
expect_png render-surface-iso "$TMP/b.png" 400
run render-volume-boundary render "$SHARED/data/vol/bunny_vol.mesh" --view y --color ref -o "$TMP/v.png" --width 400
expect_png render-volume-boundary "$TMP/v.png" 400

# Bad requests: exit 2, one line, no picture.
write_two_triangles "$TMP/two.mesh"
# Sizes, one per vertex, draw as their metric I/h² (they were refused: "no symmetric tensor field").
printf 'MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 1\n0.5\n0.5\n0.25\n0.5\nEnd\n' >"$TMP/sizes.sol"
write_metric "$TMP/sizes_as_tensors.sol" 4 "4 0 4" "4 0 4" "16 0 16" "4 0 4"
run render-metric-sizes render "$TMP/two.mesh" --metric "$TMP/sizes.sol" --color size -o "$TMP/sz.svg"
"$R" render "$TMP/two.mesh" --metric "$TMP/sizes_as_tensors.sol" --color size -o "$TMP/st.svg" &&
  cmp -s "$TMP/sz.svg" "$TMP/st.svg" && ok render-metric-sizes-as-tensors || ko render-metric-sizes-as-tensors
write_metric "$TMP/short.sol" 2 "1 0 1" "1 0 1"
write_metric "$TMP/nan.sol" 4 "1 0 1" "nan 0 1" "1 0 1" "1 0 1"
expect_error render-missing render "$TMP/none.mesh" -o "$TMP/x1.png"
expect_no_file render-missing-no-file "$TMP/x1.png"
expect_error render-extension render "$TMP/two.mesh" -o "$TMP/x2.jpg"
expect_no_file render-extension-no-file "$TMP/x2.jpg"
expect_error render-metric-count render "$TMP/two.mesh" --metric "$TMP/short.sol" -o "$TMP/x3.png"
expect_no_file render-metric-count-no-file "$TMP/x3.png"
expect_error render-metric-nan render "$TMP/two.mesh" --metric "$TMP/nan.sol" -o "$TMP/x4.png"
expect_no_file render-metric-nan-no-file "$TMP/x4.png"
expect_error render-ref-with-metric render "$TMP/two.mesh" --color ref --metric "$TMP/short.sol" -o "$TMP/x5.png"
expect_no_file render-ref-with-metric-no-file "$TMP/x5.png"
expect_error render-view-on-planar render "$TMP/two.mesh" --view iso -o "$TMP/x6.png"
expect_no_file render-view-on-planar-no-file "$TMP/x6.png"
expect_error render-bad-color render "$TMP/two.mesh" --color speed -o "$TMP/x7.png"
expect_error render-bad-width render "$TMP/two.mesh" --width 5 -o "$TMP/x8.png"
expect_error render-no-output render "$TMP/two.mesh"
expect_no_file render-bad-no-file "$TMP/x8.png"

# Without cairo (dlopen of libcairo.so.2 refused by a preloaded shim): a picture (PNG or SVG: both
# are drawn by cairo) fails with one line naming the package, exit 2, and leaves no file.
cat >"$TMP/no_cairo.c" <<'C'
#define _GNU_SOURCE
#include <dlfcn.h>
#include <string.h>
void* dlopen(const char* name, int flags) {
  static void* (*real)(const char*, int);
  if (name && strstr(name, "libcairo")) return NULL;
  if (!real) real = (void* (*)(const char*, int))dlsym(RTLD_NEXT, "dlopen");
  return real(name, flags);
}
C
if cc -shared -fPIC -o "$TMP/no_cairo.so" "$TMP/no_cairo.c" -ldl 2>"$TMP/cc.err"; then
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
  for ext in png svg; do
    out=$(LD_PRELOAD="$TMP/no_cairo.so" "$R" render "$TMP/two.mesh" -o "$TMP/nc.$ext" 2>"$TMP/nc.err")
    code=$?
    err=$(cat "$TMP/nc.err")
    if [ "$code" -eq 2 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] &&
       [[ "$err" == "riemesh: error: "*"libcairo2"* ]]; then
      ok "render-$ext-without-cairo ($err)"
    else
      ko "render-$ext-without-cairo: exit $code, stderr '$err'"
    fi
    expect_no_file "render-$ext-without-cairo-no-file" "$TMP/nc.$ext"
  done
else
  ko "render-without-cairo: cannot build the dlopen shim: $(head -1 "$TMP/cc.err")"
fi

exit $fail
