#!/usr/bin/env bash
# Builds the C++ core + binding with Debian's emcc into two modules in web/generated/:
#   hairsolver.{mjs,wasm}                   single-threaded (any page, Node)
#   hairsolver-mt.{mjs,wasm,worker.js}      threaded: -pthread, shared memory, a pthread pool of
#                                           Module.hsPoolSize workers (the loader sets it); only
#                                           for cross-origin isolated pages (SharedArrayBuffer)
# The core's sources are compiled as two unity units (build/wasm/core-{a,b}.cpp, each including
# half of them, which then share their Eigen instantiations) and the binding as a third, each to
# an object per variant (build/wasm/{st,mt}/), with the Eigen and standard headers parsed once per
# variant into a precompiled header (wasm-build/pch.hpp; the code emitted is the same without
# it), on every core at once (JOBS overrides), and only when a unit's sources or a header
# changed; then both modules are linked. As in the native build (solver-cpp/CMakeLists.txt), a
# name in one file's anonymous namespace must not clash with, or overload, another file's.
# Skips everything when every input is older
# than every output (FORCE=1 rebuilds everything anyway).
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

inputs=("$root"/solver-cpp/src/*.cpp "$root"/solver-cpp/src/*.hpp "$here/binding.cpp" "$here/pch.hpp" "$here/build.sh")
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
objs="$root/build/wasm"
if [ "${FORCE:-0}" = 1 ]; then rm -rf "$objs"; fi
# the C locale's order, as CMake's (the same files share a unit in both builds)
mapfile -t core < <(printf '%s\n' "$root"/solver-cpp/src/*.cpp | LC_ALL=C sort)
half=$(((${#core[@]} + 1) / 2))
units=(core-a core-b binding)
unit_source() {  # unit: the file compiled for it
  if [ "$1" = binding ]; then echo "$here/binding.cpp"; else echo "$objs/$1.cpp"; fi
}
unit_members() {  # unit: the sources it compiles
  case "$1" in
    core-a) printf '%s\n' "${core[@]:0:half}" ;;
    core-b) printf '%s\n' "${core[@]:half}" ;;
    binding) echo "$here/binding.cpp" ;;
  esac
}
cflags=(-std=c++17 -O3 -msimd128 -DNDEBUG -DEIGEN_NO_DEBUG -fno-exceptions
  -I"$root/solver-cpp/src" -I"$eigen")
# Every object depends on every header, the precompiled header's list and this script.
common_inputs=("$root"/solver-cpp/src/*.hpp "$here/pch.hpp" "$here/build.sh")
newer_than() {  # file inputs...: whether any input is newer than file (or file is missing)
  local f="$1" i
  shift
  [ -f "$f" ] || return 0
  for i in "$@"; do [ "$i" -nt "$f" ] && return 0; done
  return 1
}
variant_flags() {  # st|mt
  if [ "$1" = mt ]; then echo -pthread; fi
}
export -f variant_flags
# 1. the precompiled header of each variant (its flags must be the objects' own)
for v in st mt; do
  mkdir -p "$objs/$v"
  pch="$objs/$v/pch.hpp.pch"
  if newer_than "$pch" "${common_inputs[@]}"; then
    # shellcheck disable=SC2046
    em++ "${cflags[@]}" $(variant_flags "$v") -x c++-header "$here/pch.hpp" -o "$pch" &
  fi
done
status=0
for job in $(jobs -p); do wait "$job" || status=$?; done
if [ "$status" != 0 ]; then
  echo "wasm-build: emcc failed on the precompiled header ($status)" >&2
  exit "$status"
fi
# 2. the unity files, rewritten only when their list of sources changed (a rewrite rebuilds
# the unit)
for u in core-a core-b; do
  f="$objs/$u.cpp"
  unit_members "$u" | sed 's/.*/#include "&"/' > "$f.new"
  if cmp -s "$f.new" "$f"; then rm "$f.new"; else mv "$f.new" "$f"; fi
done
# 3. the objects that are missing or older than a source of theirs or a common input, on JOBS
# cores
todo=()
for v in st mt; do
  for u in "${units[@]}"; do
    src="$(unit_source "$u")"
    o="$objs/$v/$u.o"
    mapfile -t members < <(unit_members "$u")
    if newer_than "$o" "$src" "${members[@]}" "${common_inputs[@]}" "$objs/$v/pch.hpp.pch"; then
      todo+=("$v" "$src" "$o")
    fi
  done
done
if [ ${#todo[@]} -gt 0 ]; then
  printf '%s\0' "${todo[@]}" |
    xargs -0 -n 3 -P "${JOBS:-$(nproc)}" bash -c \
      'v=${*: -3:1} src=${*: -2:1} o=${*: -1}
       em++ "${@:1:$#-3}" $(variant_flags "$v") -include-pch "$(dirname "$o")/pch.hpp.pch" -c "$src" -o "$o" ||
         { echo "wasm-build: emcc failed on $src ($v)" >&2; exit 255; }' _ "${cflags[@]}" ||
    { echo "wasm-build: compiling failed" >&2; exit 1; }
fi
# 4. link. ENVIRONMENT=web,worker: the loader then never touches node's require (emcc 3.1.6 +
# EXPORT_ES6 breaks there); under Node the caller passes wasmBinary and the loader does not
# fetch (and, for the threaded module, a Worker over node:worker_threads: web/solver/nodeWorkerShim.ts).
objects() { for u in "${units[@]}"; do echo "$objs/$1/$u.o"; done; }
link=(-O3 -msimd128
  -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createHairSolver
  -sENVIRONMENT=web,worker
  -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=33554432 -sMAXIMUM_MEMORY=2GB
  -sEXPORTED_FUNCTIONS="$exports"
  -sEXPORTED_RUNTIME_METHODS=UTF8ToString
  -sFILESYSTEM=0 -sASSERTIONS=0)
mapfile -t stObjects < <(objects st)
mapfile -t mtObjects < <(objects mt)
em++ "${link[@]}" "${stObjects[@]}" -o "$mjs" &
single=$!
# Threaded: the pool is created with the module (PTHREAD_POOL_SIZE evaluated at load time), so
# std::thread never waits for a worker to start (that needs the event loop the caller blocks).
# Growth of shared memory is allowed; JS reads the heap through views refreshed on growth
# (wasmEngine.ts). -Wno-pthreads-mem-growth: the warning is about JS heap access, see there.
em++ "${link[@]}" "${mtObjects[@]}" -pthread -sPTHREAD_POOL_SIZE='Module.hsPoolSize||1' \
  -Wno-pthreads-mem-growth -o "$mtMjs" &
threaded=$!
status=0
wait "$single" || status=$?
wait "$threaded" || status=$?
if [ "$status" != 0 ]; then
  echo "wasm-build: linking failed ($status)" >&2
  exit "$status"
fi
touch "${outputs[@]}"
echo "wasm-build: done in $(( $(date +%s) - start )) s ($(du -k "$wasm" | cut -f1) KB wasm, threaded $(du -k "$mtWasm" | cut -f1) KB)"
