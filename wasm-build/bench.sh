#!/usr/bin/env bash
# Builds solver-cpp/bench/exact_bench.cpp as a Node program (emcc -O3 -msimd128, one thread).
# Output: build/wasm-bench/exact_bench.js (+ .wasm). Run: node --no-experimental-fetch <js> 29
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/wasm-bench}"
mkdir -p "$out"
# Debian's emcc runs its JS optimiser with the machine's Node, which needs Debian's node folder.
export NODE_PATH=/usr/share/nodejs
src="$root/solver-cpp/src"
emcc -O3 -msimd128 -std=c++17 -DNDEBUG -I"$src" -I/usr/include/eigen3 \
  "$root/solver-cpp/bench/exact_bench.cpp" \
  "$src"/grid_ordering.cpp "$src"/supernodal_symbolic.cpp "$src"/supernodal_factor.cpp \
  "$src"/factor_update.cpp "$src"/exact_solver.cpp "$src"/field_system.cpp \
  "$src"/constraints.cpp "$src"/memory_budget.cpp \
  -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=4GB -sINITIAL_MEMORY=64MB -sENVIRONMENT=node \
  -sNODERAWFS=1 -sEXIT_RUNTIME=1 -o "$out/exact_bench.js"
# The output is CommonJS; the repository's package.json says "type": "module", which Node would
# apply to build/wasm-bench/*.js (ReferenceError: __dirname is not defined in ES module scope).
echo '{"type": "commonjs"}' > "$out/package.json"
echo "$out/exact_bench.js"
