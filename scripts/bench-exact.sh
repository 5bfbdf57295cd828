#!/usr/bin/env bash
# Benchmark of the exact solver (issue 3), natively and in wasm under Node, on the 29^3 and 37^3
# boxes. Writes bench-results/exact-<time>.jsonl (one JSON object per measurement) and
# bench-results/exact-<time>.md (the table), and prints the table.
#   scripts/bench-exact.sh [--no-wasm] [--baseline37] [--sizes "29 37"]
# The naive baseline (Eigen SimplicialLDLT refactorisation, AMD ordering) runs at 29^3 on both
# platforms; at 37^3 only natively and only with --baseline37 (about 200 s).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
wasm=1
base37=0
sizes="29 37"
while [ $# -gt 0 ]; do
  case "$1" in
    --no-wasm) wasm=0 ;;
    --baseline37) base37=1 ;;
    --sizes) sizes="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
stamp="$(date -u +%Y%m%dT%H%M%SZ)"
mkdir -p bench-results
out="bench-results/exact-$stamp.jsonl"
: > "$out"

cmake -S solver-cpp -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build/native --target exact_bench > /dev/null
if [ "$wasm" = 1 ]; then bash wasm-build/bench.sh "$root/build/wasm-bench" > /dev/null; fi

run() {  # platform N extra-args...
  local platform="$1" n="$2"
  shift 2
  local baseline=()
  if [ "$n" = 29 ]; then baseline=(--baseline); fi
  if [ "$base37" = 1 ] && [ "$platform" = native ]; then baseline=(--baseline); fi
  echo "== $platform $n^3" >&2
  if [ "$platform" = native ]; then
    ./build/native/exact_bench "$n" --force-both "${baseline[@]}" "$@" | tee -a "$out" >&2
  else
    node --no-experimental-fetch build/wasm-bench/exact_bench.js "$n" --force-both \
      "${baseline[@]}" "$@" | tee -a "$out" >&2
  fi
}
for n in $sizes; do
  run native "$n"
  if [ "$wasm" = 1 ]; then run wasm "$n"; fi
done

node scripts/bench-exact-table.mjs "$out" | tee "${out%.jsonl}.md"
echo "wrote $out and ${out%.jsonl}.md" >&2
