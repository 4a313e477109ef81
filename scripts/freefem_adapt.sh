#!/bin/sh
# Riemesh as the external remesher of ../shared/clients/roundtrip.sh (FreeFem++ client):
#   ADAPT="sh $PWD/scripts/freefem_adapt.sh" sh ../shared/clients/roundtrip.sh OUT
# called as: freefem_adapt.sh IN.mesh METRIC.sol OUT.mesh
set -eu
R=$(cd "$(dirname "$0")/.." && pwd)/build/riemesh
exec "$R" adapt "$1" --metric "$2" -o "$3" -q
