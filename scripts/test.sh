#!/usr/bin/env bash
# npm test: set up what is missing, then format + lint + types, native build and tests, wasm
# build, unit tests (with the real wasm under Node, and the bundled command line) and browser
# tests against Debian's Chromium.
# After the Debian packages three lanes run at once, since none keeps both cores busy all the
# time: the app lane builds the wasm module (while npm's packages install), checks types, builds
# the app and the CLI and runs the browser tests; the native lane builds and runs the native
# tests; the checks lane installs npm's and Python's packages, runs format and lint, and then
# (once the app lane's browser tests are done) the unit tests. The browser tests keep both cores
# busy on their own (96 % of the machine), and the two suites side by side cost the machine
# 11 % more time than one after the other (busy 1284 s of a 644 s run; 1123 s of 573 s).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each phase's wall time and CPU time (of the processes it ran, user + system: on a shared machine
# the CPU figure moves less than the wall time) go into a table printed at the end (also when a
# phase fails), so it is plain where the run's time goes. Phases of the two lanes overlap: the
# table gives when each started.
now_ms() { local t=${EPOCHREALTIME/[.,]/}; echo $(( t / 1000 )); }
cpu_now() {  # cpu=CPU ms of this (sub)shell's finished children (cutime + cstime in /proc)
  local f
  read -r -a f < "/proc/$BASHPID/stat"
  cpu=$(( (f[15] + f[16]) * 1000 / ticks ))
}
ticks=$(getconf CLK_TCK 2>/dev/null || echo 100)
secs() { printf '%d.%d' $(( $1 / 1000 )) $(( ($1 % 1000) / 100 )); }
start=$(now_ms)
# The whole machine's busy CPU time (all processes, /proc/stat's first line, in clock ticks):
# the browsers' renderer processes are not children the phases wait for, so only this counts them.
machine_busy() {
  local cpu user nice system idle iowait irq softirq steal
  read -r cpu user nice system idle iowait irq softirq steal _ < /proc/stat
  echo $(( user + nice + system + irq + softirq + steal ))
}
busy0=$(machine_busy)
mkdir -p build
table=build/test-phases.txt
: > "$table"

phase() {  # name command...: runs the command as one phase of the table
  local name="$1"
  shift
  local s c cpu rc=0
  s=$(now_ms)
  cpu_now
  c=$cpu
  echo ""
  echo "== $name ($(( (s - start) / 1000 )) s)"
  # In a subshell of its own so that set -e holds within it (a `cmd || …` would switch it off)
  set +e
  (
    set -e
    "$@"
  )
  rc=$?
  set -e
  cpu_now
  printf '%s\t%s\t%s\t%s\t%s\n' "$(( s - start ))" "$(( $(now_ms) - s ))" "$(( cpu - c ))" \
    "$name" "$([ "$rc" = 0 ] || echo failed)" >> "$table"
  return "$rc"
}

timing_table() {
  local cpu
  cpu_now
  echo ""
  echo "npm test, time per phase (lanes overlap: see where each starts):"
  printf '  %8s %10s %10s  %s\n' start wall cpu phase
  sort -n "$table" | while IFS=$'\t' read -r s w c name failed; do
    printf '  %6s s %8s s %8s s  %s%s\n' "$(( s / 1000 ))" "$(secs "$w")" "$(secs "$c")" "$name" \
      "${failed:+  (failed)}"
  done
  local wall=$(( $(now_ms) - start )) busy=$(( ($(machine_busy) - busy0) * 1000 / ticks ))
  printf '  %6s   %8s s %8s s  total\n' "" "$(secs "$wall")" "$(secs "$cpu")"
  printf '  the machine was busy %s s of %s s (%d cores, every process on it counted)\n' \
    "$(secs "$busy")" "$(secs $(( wall * $(nproc) )))" "$(nproc)"
}
trap 'status=$?; timing_table; if [ "$status" != 0 ]; then echo "npm test: failed"; fi' EXIT

packages() {
  bash scripts/setup.sh test packages
  # Pixar's USD reader for tests/unit/usdExport.test.ts (tests/usd/check_usd.py), made by setup
  build/usd-venv/bin/python -c 'from pxr import Usd; print("usd-core", ".".join(map(str, Usd.GetVersion())))'
  # and Blender's, bpy (tests/usd/check_blender.py)
  build/bpy-venv/bin/python -c 'import bpy; print("bpy", bpy.app.version_string)'
  echo ok > "$installed"
}
format_lint() {
  local cxx
  mapfile -t cxx < <(git ls-files 'solver-cpp/*.cpp' 'solver-cpp/*.hpp' 'wasm-build/*.cpp' 'tests/native/*.cpp' 2>/dev/null || true)
  if [ ${#cxx[@]} -gt 0 ]; then clang-format --dry-run -Werror "${cxx[@]}"; fi
  npx biome check web tests scripts vite.config.ts vite.cli.config.ts playwright.config.ts
}
native_build() {
  cmake -S solver-cpp -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release -DHAIRSKETCH_BENCH=OFF >/dev/null
  cmake --build build/native
}
web_build() {
  npx vite build --logLevel warn
  npx vite build -c vite.cli.config.ts
}
logs=build/test-logs
# Lanes tell each other what is done through files in $logs holding ok or failed.
built="$logs/app-built"            # the app lane: the wasm module, the app and the CLI bundle
installed="$logs/packages-installed"  # the checks lane: npm's and Python's packages
native_done="$logs/native-tested"  # the native lane: ctest, which writes the native fields
browser_done="$logs/browser-tested"  # the app lane: the browser tests, run or failed
wait_for() {  # file what: waits until the file says; fails unless it says ok
  until [ -s "$1" ]; do sleep 1; done
  if [ "$(cat "$1")" != ok ]; then
    echo "not run: it needs $2, which failed" >&2
    return 1
  fi
}
lane_app() {
  local rc=0
  phase "wasm build" bash wasm-build/build.sh || rc=$?
  [ "$rc" = 0 ] && { wait_for "$installed" "npm's packages" || rc=$?; }
  [ "$rc" = 0 ] && { phase "types (tsc; needs the wasm module's declarations)" npx tsc --noEmit -p tsconfig.json || rc=$?; }
  [ "$rc" = 0 ] && { phase "web build (app, CLI bundle)" web_build || rc=$?; }
  if [ "$rc" = 0 ]; then echo ok > "$built"; else echo failed > "$built"; return "$rc"; fi
  phase "browser tests (Playwright, Debian Chromium)" npx playwright test || rc=$?
  if [ "$rc" = 0 ]; then echo ok > "$browser_done"; else echo failed > "$browser_done"; fi
  return "$rc"
}
lane_native() {
  local rc=0
  phase "native build" native_build || rc=$?
  [ "$rc" = 0 ] && { phase "native tests (ctest)" ctest --test-dir build/native --output-on-failure -j2 || rc=$?; }
  if [ "$rc" = 0 ]; then echo ok > "$native_done"; else echo failed > "$native_done"; fi
  return "$rc"
}
# tests/unit/wasmNative.test.ts compares the wasm module's fields with the native build's, which
# ctest writes: it runs once the native lane is done, every other unit test once the app lane has
# built the wasm module and the CLI bundle and run the browser tests.
unit_tests() {
  wait_for "$built" "the wasm module and the CLI bundle"
  until [ -s "$browser_done" ]; do sleep 1; done
  npx vitest run --exclude tests/unit/wasmNative.test.ts
}
unit_tests_native() {
  wait_for "$built" "the wasm module"
  wait_for "$native_done" "the native build and ctest"
  npx vitest run tests/unit/wasmNative.test.ts
}
lane_checks() {
  local rc=0
  phase "setup: npm and Python packages" packages || rc=$?
  if [ "$rc" != 0 ]; then echo failed > "$installed"; return "$rc"; fi
  phase "format and lint" format_lint
  phase "unit tests (vitest, Node, real wasm; waits for the app lane's builds)" unit_tests
  phase "unit tests against the native fields (waits for ctest)" unit_tests_native
}
lanes() {  # runs the three lanes at once; prints each lane's output whole, when it is done
  local pids=() names=(checks native app) name rc=0
  mkdir -p "$logs"
  rm -f "$built" "$installed" "$native_done" "$browser_done"
  lane_checks > "$logs/checks.log" 2>&1 &
  pids+=($!)
  lane_native > "$logs/native.log" 2>&1 &
  pids+=($!)
  lane_app > "$logs/app.log" 2>&1 &
  pids+=($!)
  for i in 0 1 2; do
    name=${names[$i]}
    wait "${pids[$i]}" || rc=1
    cat "$logs/$name.log"
  done
  return "$rc"
}

phase "setup: Debian packages" bash scripts/setup.sh test system
lanes

trap - EXIT
timing_table
echo "npm test: all passed"
