#!/usr/bin/env bash
# Riemesh against FreeFem's own adaptmesh (BAMG) on the FreeFem client problem of ../shared/clients,
# at equal vertex count: for each complexity N, the 5-loop solve -> `riemesh adapt --field`
# -> solve of scripts/freefem_loop.sh, then the same 5 loops with adaptmesh
# (bench/freefem_bamg_loop.edp), its tolerance `err` searched (secant on log err vs log nv) until
# the final mesh has the vertex count of Riemesh's within 3%. Both use hmin 1e-3, hmax 0.2.
# Errors of max u and of the integral of u against the README reference of ../shared/clients
# (P1, uniform 136k vertices: 0.7533, 0.2059) and against a P2 solution on the same uniform mesh
# (bench/freefem_reference.edp, computed here). Adapt time: CPU seconds of the 5 adaptations, median
# of RUNS runs (Riemesh: user + system time of the `riemesh adapt` processes, file I/O and Hessian
# recovery included, wall time beside it; BAMG: FreeFem's clock() around adaptmesh, in-process,
# Hessian included). Prints a Markdown table.
#   bench/freefem_vs_bamg.sh [RUNS] [N ...]      (default 3 runs; N = 100 250 500 1000 2000 4000)
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
runs=${1:-3}
shift || true
ns=("$@")
[ ${#ns[@]} -gt 0 ] || ns=(100 250 500 1000 2000 4000)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

read -r p2_umax p2_int < <(FreeFem++ -nw -v 0 bench/freefem_reference.edp -n 400 |
  awk '{ for (i = 1; i < NF; ++i) { if ($i == "umax") u = $(i + 1); if ($i == "int_u") s = $(i + 1) } print u, s }')
echo "P2 reference (uniform, 136k vertices): max u $p2_umax, integral $p2_int"

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

# bamg ERR: final "nv umax int_u adapt_seconds" of the 5-loop with adaptmesh at tolerance ERR.
bamg() {
  FreeFem++ -nw -v 0 bench/freefem_bamg_loop.edp -err "$1" -loops 5 |
    awk '{ for (i = 1; i < NF; ++i) { if ($i == "nv") nv = $(i + 1); if ($i == "umax") u = $(i + 1);
           if ($i == "int_u") s = $(i + 1); if ($i == "adapt_s") t += $(i + 1) } } END { print nv, u, s, t }'
}

row() {  # row TOOL N NV UMAX INT CPU_SECONDS PARAM [WALL_SECONDS]
  awk -v tool="$1" -v n="$2" -v nv="$3" -v u="$4" -v s="$5" -v t="$6" -v p="$7" -v w="${8:-}" \
      -v pu="$p2_umax" -v ps="$p2_int" 'BEGIN {
    printf "| %s | %s | %s | %d | %.6f | %+.3f%% | %+.3f%% | %.6f | %+.3f%% | %+.3f%% | %.3f%s |\n", n, tool, p, nv,
      u, 100 * (u - 0.7533) / 0.7533, 100 * (u - pu) / pu, s, 100 * (s - 0.2059) / 0.2059, 100 * (s - ps) / ps,
      t, w == "" ? "" : sprintf(" (wall %.3f)", w) }'
}

echo
echo "| N | tool | parameter | vertices | max u | vs 0.7533 | vs P2 | ∫u | vs 0.2059 | vs P2 | adapt CPU s (5 loops) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for n in "${ns[@]}"; do
  times=() walls=()
  for ((r = 0; r < runs; ++r)); do
    line=$(scripts/freefem_loop.sh -n "$n" -o "$work/r$n" | grep '^final:')
    times+=("$(awk '{ print $(NF - 1) }' <<<"$line")")
    walls+=("$(awk '{ print $(NF - 4) }' <<<"$line")")
  done
  read -r nv umax int_u < <(awk '{ for (i = 1; i < NF; ++i) { if ($i == "nv") nv = $(i + 1);
    if ($i == "umax") u = $(i + 1); if ($i == "int_u") s = $(i + 1) } print nv, u, s }' <<<"$line")
  t=$(printf '%s\n' "${times[@]}" | median)
  w=$(printf '%s\n' "${walls[@]}" | median)
  row riemesh "$n" "$nv" "$umax" "$int_u" "$t" "--complexity $n" "$w"

  # BAMG: find err giving nv within 3% (nv ~ err^-1 to start, then secant in log-log).
  err=0.01 best="" best_gap=1e9 prev_err="" prev_nv=""
  for ((it = 0; it < 10; ++it)); do
    read -r bnv bu bs bt < <(bamg "$err")
    gap=$(awk -v a="$bnv" -v b="$nv" 'BEGIN { g = (a - b) / b; print (g < 0 ? -g : g) }')
    if awk -v g="$gap" -v b="$best_gap" 'BEGIN { exit !(g < b) }'; then best="$err"; best_gap=$gap; fi
    awk -v g="$gap" 'BEGIN { exit !(g <= 0.03) }' && break
    next_err=$(awk -v e="$err" -v v="$bnv" -v pe="$prev_err" -v pv="$prev_nv" -v t="$nv" 'BEGIN {
      s = -1; if (pe != "" && pv != v && pe != e) s = (log(v) - log(pv)) / (log(e) - log(pe))
      if (s > -0.3 || s < -3) s = -1
      printf "%.6g", e * exp((log(t) - log(v)) / s) }')
    prev_err=$err prev_nv=$bnv err=$next_err
  done
  times=()
  for ((r = 0; r < runs; ++r)); do
    read -r bnv bu bs bt < <(bamg "$best")
    times+=("$bt")
  done
  t=$(printf '%s\n' "${times[@]}" | median)
  row "FreeFem adaptmesh" "$n" "$bnv" "$bu" "$bs" "$t" "err $best"
done
