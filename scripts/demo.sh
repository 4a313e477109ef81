#!/usr/bin/env bash
# Sets up a fresh machine, builds Riemesh and runs a demo on embedded inputs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
exec build/riemesh demo
