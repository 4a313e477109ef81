# Helpers shared by the mesh command tests (sourced; not a test itself: no test_ prefix).
R=${RIEMESH:?path to the riemesh binary}
SHARED=${SHARED:?path to ../shared}
fail=0
ok() { echo "ok   $1"; }
ko() { echo "FAIL $1"; fail=1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# expect_error NAME ARGS...: exit code 2, exactly one line on stderr starting "riemesh: error:",
# nothing on stdout.
expect_error() {
  local name=$1; shift
  local out err code
  out=$("$R" "$@" 2>"$TMP/err"); code=$?
  err=$(cat "$TMP/err")
  if [ "$code" -eq 2 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] &&
     [[ "$err" == "riemesh: error: "* ]]; then
    ok "$name ($err)"
  else
    ko "$name: exit $code, stdout '$out', stderr '$err'"
  fi
}

# expect_error_matching NAME PATTERN ARGS...: as expect_error, and the error line matches the
# grep pattern PATTERN (basic regular expression).
expect_error_matching() {
  local name=$1 pattern=$2; shift 2
  local out err code
  out=$("$R" "$@" 2>"$TMP/err"); code=$?
  err=$(cat "$TMP/err")
  if [ "$code" -eq 2 ] && [ -z "$out" ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] &&
     [[ "$err" == "riemesh: error: "* ]] && printf '%s\n' "$err" | grep -q -- "$pattern"; then
    ok "$name ($err)"
  else
    ko "$name: exit $code, stdout '$out', stderr '$err' (expected /$pattern/)"
  fi
}

# expect_no_file NAME PATH: PATH does not exist and its folder holds no temporary beside it.
expect_no_file() {
  if [ ! -e "$2" ] && ! ls "$2".tmp-* >/dev/null 2>&1; then ok "$1"; else ko "$1: $2 left behind"; fi
}

# Two right triangles of the unit square, refs 1 and 2, with the four boundary edges.
write_two_triangles() {
  cat >"$1" <<'MESH'
MeshVersionFormatted 2
Dimension 2
Vertices
4
0 0 1
1 0 1
1 1 1
0 1 1
Triangles
2
1 2 3 1
1 3 4 2
Edges
4
1 2 1
2 3 2
3 4 3
4 1 4
End
MESH
}

# write_metric PATH N "m11 m12 m22"...: a 2D .sol file with the given tensors.
write_metric() {
  local path=$1 n=$2; shift 2
  { printf 'MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n%s\n1 3\n' "$n"
    for t in "$@"; do echo "$t"; done
    echo End; } >"$path"
}
