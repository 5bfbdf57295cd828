#!/usr/bin/env bash
# Builds the C++ core + binding with Debian's emcc into two modules in web/generated/:
#   hairsolver.{mjs,wasm}                   single-threaded (any page, Node)
#   hairsolver-mt.{mjs,wasm,worker.js}      threaded: -pthread, shared memory, a pthread pool of
#                                           Module.hsPoolSize workers (the loader sets it); only
#                                           for cross-origin isolated pages (SharedArrayBuffer)
# Both are built at once (in parallel). Skips the build when every input is older than every
# output (FORCE=1 rebuilds anyway).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
out="$root/web/generated"
mjs="$out/hairsolver.mjs"
wasm="$out/hairsolver.wasm"
mtMjs="$out/hairsolver-mt.mjs"
mtWasm="$out/hairsolver-mt.wasm"
mtWorker="$out/hairsolver-mt.worker.js"
outputs=("$mjs" "$wasm" "$mtMjs" "$mtWasm" "$mtWorker")

if ! command -v emcc >/dev/null 2>&1; then
  echo "wasm-build: emcc not found. Install Debian's emscripten: apt-get install -y emscripten libeigen3-dev" >&2
  exit 1
fi
eigen="${EIGEN_INCLUDE:-/usr/include/eigen3}"
if [ ! -f "$eigen/Eigen/Core" ]; then
  echo "wasm-build: Eigen headers not found in $eigen (apt-get install -y libeigen3-dev)" >&2
  exit 1
fi

# The module's TypeScript declaration always goes next to it (cheap, keeps tsc happy).
mkdir -p "$out"
cp "$here/hairsolver.d.mts" "$out/hairsolver.d.mts"

inputs=("$root"/solver-cpp/src/*.cpp "$root"/solver-cpp/src/*.hpp "$here/binding.cpp" "$here/build.sh")
have=1
for o in "${outputs[@]}"; do [ -f "$o" ] || have=0; done
if [ "${FORCE:-0}" != 1 ] && [ "$have" = 1 ]; then
  stale=0
  for f in "${inputs[@]}"; do
    for o in "${outputs[@]}"; do
      if [ "$f" -nt "$o" ]; then stale=1; fi
    done
  done
  if [ "$stale" = 0 ]; then
    echo "wasm-build: up to date ($mjs)"
    exit 0
  fi
fi

mkdir -p "$out"
# Debian's emcc runs its JS optimiser with the system node, which needs Debian's node modules.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

exports='_malloc,_free'
for f in $(grep -o 'EMSCRIPTEN_KEEPALIVE [^(]*(' "$here/binding.cpp" | grep -o 'hs_[a-z_]*'); do
  exports="$exports,_$f"
done

echo "wasm-build: emcc $(emcc --version | head -1 | grep -o '[0-9]\+\.[0-9]\+\.[0-9]\+' | head -1) -> $mjs, $mtMjs"
start=$(date +%s)
# ENVIRONMENT=web,worker: the loader then never touches node's require (emcc 3.1.6 + EXPORT_ES6
# breaks there); under Node the caller passes wasmBinary and the loader does not fetch (and, for
# the threaded module, a Worker over node:worker_threads: web/solver/nodeWorkerShim.ts).
common=(-std=c++17 -O3 -msimd128 -DNDEBUG -DEIGEN_NO_DEBUG -fno-exceptions
  -I"$root/solver-cpp/src" -I"$eigen"
  "$root"/solver-cpp/src/*.cpp "$here/binding.cpp"
  -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createHairSolver
  -sENVIRONMENT=web,worker
  -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=33554432 -sMAXIMUM_MEMORY=2GB
  -sEXPORTED_FUNCTIONS="$exports"
  -sEXPORTED_RUNTIME_METHODS=UTF8ToString
  -sFILESYSTEM=0 -sASSERTIONS=0)
emcc "${common[@]}" -o "$mjs" &
single=$!
# Threaded: the pool is created with the module (PTHREAD_POOL_SIZE evaluated at load time), so
# std::thread never waits for a worker to start (that needs the event loop the caller blocks).
# Growth of shared memory is allowed; JS reads the heap through views refreshed on growth
# (wasmEngine.ts). -Wno-pthreads-mem-growth: the warning is about JS heap access, see there.
emcc "${common[@]}" -pthread -sPTHREAD_POOL_SIZE='Module.hsPoolSize||1' \
  -Wno-pthreads-mem-growth -o "$mtMjs" &
threaded=$!
status=0
wait "$single" || status=$?
wait "$threaded" || status=$?
if [ "$status" != 0 ]; then
  echo "wasm-build: emcc failed ($status)" >&2
  exit "$status"
fi
touch "${outputs[@]}"
echo "wasm-build: done in $(( $(date +%s) - start )) s ($(du -k "$wasm" | cut -f1) KB wasm, threaded $(du -k "$mtWasm" | cut -f1) KB)"
