#!/usr/bin/env bash
# Benchmark of the exact solver, natively and in wasm under Node, on the 29^3 and 37^3 boxes.
# Writes BASE.jsonl (one JSON object per measurement; BASE defaults to build/bench/exact), prints
# the table, and writes bench-results/exact.{json,md} (scripts/bench-exact-table.mjs).
#   scripts/bench-exact.sh [--no-wasm] [--baseline37] [--baseline37-wasm] [--sizes "29 37"]
#                          [--out BASE]
# Every edit is timed with both methods (--force-both): the one the cost model chose, and the
# other one forced. The naive baseline (Eigen SimplicialLDLT refactorisation, AMD ordering) runs
# in its own process (so that its peak memory is its own) at 29^3 on both platforms; at 37^3
# natively with --baseline37 (200-260 s), in wasm with --baseline37-wasm (7-9 minutes more).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
wasm=1
base37=0
base37wasm=0
sizes="29 37"
base="build/bench/exact"
while [ $# -gt 0 ]; do
  case "$1" in
    --no-wasm) wasm=0 ;;
    --baseline37) base37=1 ;;
    --baseline37-wasm) base37wasm=1 ;;
    --sizes) sizes="$2"; shift ;;
    --out) base="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$(dirname "$base")"
out="$base.jsonl"
: > "$out"

cmake -S solver-cpp -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release -DHAIRSKETCH_BENCH=ON > /dev/null
cmake --build build/native --target exact_bench > /dev/null
if [ "$wasm" = 1 ]; then bash wasm-build/bench.sh "$root/build/wasm-bench" > /dev/null; fi

note() {  # platform N text: recorded in the JSON lines and printed under the table
  node -e 'console.log(JSON.stringify({kind: "note", platform: process.argv[1],
    N: Number(process.argv[2]), text: process.argv[3]}))' "$@" | tee -a "$out" >&2
}
bench() {  # platform args...
  local platform="$1"
  shift
  if [ "$platform" = native ]; then
    ./build/native/exact_bench "$@" | tee -a "$out" >&2
  else
    node --no-experimental-fetch build/wasm-bench/exact_bench.js "$@" | tee -a "$out" >&2
  fi
}
run() {  # platform N
  local platform="$1" n="$2"
  echo "== $platform $n^3" >&2
  bench "$platform" "$n" --force-both
  local baseline=0
  if [ "$n" != 37 ]; then baseline=1; fi
  if [ "$n" = 37 ] && [ "$platform" = native ] && [ "$base37" = 1 ]; then baseline=1; fi
  if [ "$n" = 37 ] && [ "$platform" = wasm ] && [ "$base37wasm" = 1 ]; then baseline=1; fi
  if [ "$baseline" = 1 ]; then
    echo "== $platform $n^3 naive baseline (SimplicialLDLT)" >&2
    bench "$platform" "$n" --baseline-only
  elif [ "$platform" = native ]; then
    note native "$n" "naive baseline not run (200-260 s natively at 37^3; pass --baseline37)"
  else
    note wasm "$n" "naive baseline not run in wasm at 37^3 by default: it would take about the \
native 37^3 baseline time (200-260 s here) times the wasm/native ratio of the 29^3 baseline \
rows (about 2), i.e. 7-9 minutes; pass --baseline37-wasm to run it"
  fi
}
for n in $sizes; do
  run native "$n"
  if [ "$wasm" = 1 ]; then run wasm "$n"; fi
done

node scripts/bench-exact-table.mjs "$out" --name exact
