#!/usr/bin/env bash
# The adaptation loop of a real solver client: FreeFem++ (Debian freefem++) solves the
# convection-diffusion problem with boundary layers on the L-shape of ../shared/clients, then LOOPS
# times: `riemesh adapt MESH --field U.sol --complexity N` (Hessian of the solution, Lp-optimal
# metric, remesh) and FreeFem reads the new mesh back and solves again. Prints one line per solve
# and a summary against the reference of ../shared/clients/README.md (uniform 136k-vertex P1 mesh:
# max u = 0.7533, integral of u = 0.2059).
#   scripts/freefem_loop.sh [-n N] [-k LOOPS] [-o OUTDIR] [--check PERCENT] [-- ADAPT-OPTIONS...]
# Defaults: N 1000, 5 loops, OUTDIR /tmp/riemesh-freefem, riemesh adapt options --hmin 1e-3
# --hmax 0.2 (the client's bounds). --check P: exit 1 unless both final figures are within P % of
# the reference. Environment: RIEMESH (binary, default build/riemesh), SHARED (default ../shared).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
R=${RIEMESH:-$top/build/riemesh}
C=${SHARED:-$top/../shared}/clients
n=1000 loops=5 out=/tmp/riemesh-freefem check=""
while [ $# -gt 0 ]; do
  case $1 in
    -n) n=$2; shift 2 ;;
    -k) loops=$2; shift 2 ;;
    -o) out=$2; shift 2 ;;
    --check) check=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "freefem_loop.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] || set -- --hmin 1e-3 --hmax 0.2
ref_umax=0.7533 ref_int=0.2059
mkdir -p "$out"
out=$(cd "$out" && pwd)

# solve K MESH: FreeFem re-solves on MESH and writes u_K.sol; prints "nv umax int_u".
solve() {
  FreeFem++ -nw -v 0 "$C/freefem/resolve.edp" -in "$2" -sol "$out/u_$1.sol" |
    awk '/^resolve:/ { for (i = 1; i < NF; ++i) { if ($i == "nv") nv = $(i + 1);
           if ($i == "umax") um = $(i + 1); if ($i == "int_u") iu = $(i + 1) } print nv, um, iu }'
}

# Loop 0: the client meshes the L-shape (372 vertices) and solves; its mesh (FreeFem's dialect,
# with BAMG's extra sections) is read by riemesh as it is, and u is P1: value i at vertex i.
(cd "$out" && FreeFem++ -nw -v 0 "$C/freefem/lshape_init.edp" -out . > init.log)
cp "$out/lshape.mesh" "$out/m_0.mesh"
read -r nv umax int_u < <(solve 0 "$out/m_0.mesh")
echo "loop 0: nv $nv umax $umax int_u $int_u"
total=0 cpu=0
TIMEFORMAT='%3R %3U %3S'
for ((k = 1; k <= loops; ++k)); do
  # --out-fields: the transferred u is not used by the solver, which solves again on the new mesh.
  # bash's `time` (ms): wall, user and system seconds of the process, to OUT/time.
  { time "$R" adapt "$out/m_$((k - 1)).mesh" --field "$out/u_$((k - 1)).sol" --complexity "$n" \
      -o "$out/m_$k.mesh" --out-fields "$out/t_$k.sol" -q "$@" 2>&3; } 3>&2 2>"$out/time"
  read -r t tcpu < <(awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$out/time")
  total=$(awk -v a="$total" -v b="$t" 'BEGIN { printf "%.3f", a + b }')
  cpu=$(awk -v a="$cpu" -v b="$tcpu" 'BEGIN { printf "%.3f", a + b }')
  read -r nv umax int_u < <(solve "$k" "$out/m_$k.mesh")
  echo "loop $k: nv $nv umax $umax int_u $int_u adapt ${t} s (cpu ${tcpu} s)"
done
awk -v um="$umax" -v iu="$int_u" -v ru="$ref_umax" -v ri="$ref_int" -v nv="$nv" -v n="$n" \
    -v t="$total" -v c="$cpu" -v tol="$check" 'BEGIN {
  eu = 100 * (um - ru) / ru; ei = 100 * (iu - ri) / ri
  printf "final: N %s nv %s umax %s (%+.3f%% vs %s) int_u %s (%+.3f%% vs %s) adapt total %s s cpu %s s\n",
         n, nv, um, eu, ru, iu, ei, ri, t, c
  if (tol != "") {
    ok = (eu <= tol && -eu <= tol && ei <= tol && -ei <= tol)
    printf "check: both within %s%%: %s\n", tol, ok ? "yes" : "NO"
    exit ok ? 0 : 1
  }
}'
