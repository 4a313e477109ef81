#!/usr/bin/env bash
# The FreeFem++ client loop (scripts/freefem_loop.sh): 5 x (FreeFem solve -> riemesh adapt --field
# U.sol --complexity N -> FreeFem reads the mesh back), final max u and integral of u within 0.5%
# of the reference of ../shared/clients/README.md; every adapted mesh valid with the 6 edge refs;
# the solution riemesh transferred to the last mesh matches FreeFem's new solution there (a
# vertex-order mix-up would differ by O(max u)). Skipped (exit 77) when FreeFem++ is not installed.
set -u
source "$(dirname "$0")/cli_lib.sh"
if ! command -v FreeFem++ >/dev/null 2>&1; then
  echo "skip: FreeFem++ is not installed (Debian freefem++, scripts/setup.sh)"
  exit 77
fi
top=$(cd "$(dirname "$0")/../.." && pwd)
RIEMESH=$R SHARED=$SHARED "$top/scripts/freefem_loop.sh" -n 500 -o "$TMP/loop" --check 0.5 >"$TMP/log" 2>&1 &&
  ok "5 loops within 0.5%: $(grep '^final:' "$TMP/log")" || ko "5 loops within 0.5%: $(cat "$TMP/log")"
[ "$(grep -c '^loop [1-5]:' "$TMP/log")" -eq 5 ] && ok "5 adaptations" || ko "5 adaptations"
for k in 1 2 3 4 5; do
  "$R" check "$TMP/loop/m_$k.mesh" >/dev/null 2>&1 || ko "mesh $k valid"
  refs=$("$R" stats "$TMP/loop/m_$k.mesh" --json 2>/dev/null | /usr/bin/python3 -c \
    'import json,sys; print(sorted(int(k) for k in json.load(sys.stdin)["refs"]["edges"]))' 2>/dev/null)
  [ "$refs" = "[1, 2, 3, 4, 5, 6]" ] || ko "mesh $k edge refs: $refs"
done
ok "meshes valid with refs 1..6"
/usr/bin/python3 - "$TMP/loop/t_5.sol" "$TMP/loop/u_5.sol" <<'PY' && ok "transferred u matches the new solve" || ko "transferred u vs new solve"
import sys
def values(path):
    t = open(path).read().split()
    i = t.index('SolAtVertices'); n = int(t[i + 1])
    return [float(v) for v in t[i + 4:i + 4 + n]]
a, b = values(sys.argv[1]), values(sys.argv[2])
d = max(abs(x - y) for x, y in zip(a, b))
print('max |transferred - solved| =', d)
sys.exit(0 if len(a) == len(b) and d < 0.02 else 1)
PY
exit $fail
