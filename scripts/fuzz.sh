#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang + ASan + UBSan) into build-fuzz/ and runs each for
# SECONDS (default 30; $FUZZ_SECONDS also works). Fails, printing the reproducer, if a target
# finds a crash, a sanitizer report, a leak, a hang (-timeout) or an input over the memory limit.
#   scripts/fuzz.sh [SECONDS] [TARGET ...]      e.g. scripts/fuzz.sh 300 meshb
# Reproduce a finding: build-fuzz/fuzz/riemesh_fuzz_<target> <reproducer file>
# New corpus entries stay in build-fuzz/corpus/<target>/ (the seeds in fuzz/corpus/ are not
# touched); keep a crasher under tests/io/crashers/<target>/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-30}"
if [[ "${1:-}" =~ ^[0-9]+$ ]]; then seconds="$1"; shift; fi

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRIEMESH_FUZZ=ON -DRIEMESH_WERROR=OFF -DRIEMESH_BUILD_TESTS=OFF -DRIEMESH_BUILD_BENCH=OFF \
  -DRIEMESH_BUILD_APPS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" >build-fuzz/build.log 2>&1 ||
  { tail -n 40 build-fuzz/build.log; echo "fuzz: build failed (build-fuzz/build.log)"; exit 1; }

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for exe in build-fuzz/fuzz/riemesh_fuzz_*; do targets+=("${exe##*/riemesh_fuzz_}"); done
fi

# Longest input per target: text formats need room for a few sections, binary ones less.
max_len() {
  case "$1" in
    meshb | sol) echo 4096 ;;
    *) echo 16384 ;;
  esac
}

failed=0
for t in "${targets[@]}"; do
  exe="build-fuzz/fuzz/riemesh_fuzz_$t"
  [ -x "$exe" ] || { echo "fuzz: no target $t (built: $(ls build-fuzz/fuzz | grep riemesh_fuzz_ | tr '\n' ' '))"; exit 2; }
  work="build-fuzz/corpus/$t" artifacts="build-fuzz/artifacts/$t" log="build-fuzz/logs/$t.log"
  mkdir -p "$work" "$artifacts" "$(dirname "$log")"
  args=(-max_total_time="$seconds" -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=2048
        -artifact_prefix="$artifacts/" -print_final_stats=1)
  [ -f "fuzz/$t.dict" ] && args+=(-dict="fuzz/$t.dict")
  seeds=()
  [ -d "fuzz/corpus/$t" ] && seeds+=("fuzz/corpus/$t")
  if "$exe" "${args[@]}" "$work" "${seeds[@]}" >"$log" 2>&1; then
    echo "fuzz: $t: ok, $(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$') runs" \
         "in ${seconds}s, corpus $(ls "$work" | wc -l) inputs"
  else
    failed=1
    echo "fuzz: $t: FAILED (log $log)"
    grep -E '^==[0-9]+==ERROR|runtime error|SUMMARY|ALARM|out-of-memory|deadly signal|terminate' "$log" | head -5 || true
    grep -o 'Test unit written to .*' "$log" | sed 's/Test unit written to /fuzz: reproducer: /' || true
    echo "fuzz: reproduce with: $exe <reproducer>"
  fi
done
exit "$failed"
