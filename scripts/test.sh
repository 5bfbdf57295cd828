#!/usr/bin/env bash
# npm test: set up what is missing, then format + lint + types, native tests, wasm build,
# unit tests (with the real wasm under Node) and browser tests against Debian's Chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase's wall time and CPU time (of the processes it ran, user + system: on a shared machine
# the CPU figure moves less than the wall time) go into a table printed at the end (also when a
# phase fails), so it is plain where the run's time goes.
now_ms() { local t=${EPOCHREALTIME/[.,]/}; echo $(( t / 1000 )); }
cpu_ms() {  # CPU time of this shell's finished children (cutime + cstime in /proc, clock ticks)
  local f
  read -r -a f < /proc/$$/stat
  echo $(( (f[15] + f[16]) * 1000 / ticks ))
}
ticks=$(getconf CLK_TCK 2>/dev/null || echo 100)
secs() { printf '%d.%d' $(( $1 / 1000 )) $(( ($1 % 1000) / 100 )); }
start=$(now_ms)
phases=()
phase_name=""
phase_start=0
phase_cpu=0
end_phase() {
  if [ -n "$phase_name" ]; then
    phases+=("$(printf '%8s s %8s s  %s' "$(secs $(( $(now_ms) - phase_start )))" \
      "$(secs $(( $(cpu_ms) - phase_cpu )))" "$phase_name")")
  fi
  phase_name=""
}
step() {
  end_phase
  phase_name="$*"
  phase_start=$(now_ms)
  phase_cpu=$(cpu_ms)
  echo ""
  echo "== $* ($(( (phase_start - start) / 1000 )) s)"
}
timing_table() {  # [failed]
  local failed=""
  if [ "${1:-}" = failed ]; then failed="$phase_name"; fi
  end_phase
  echo ""
  echo "npm test, time per phase:"
  printf '  %10s %10s  %s\n' wall cpu phase
  printf '  %s\n' "${phases[@]}"
  printf '  %8s s %8s s  total\n' "$(secs $(( $(now_ms) - start )))" "$(secs "$(cpu_ms)")"
  if [ -n "$failed" ]; then echo "npm test: failed in \"$failed\""; fi
}
trap 'if [ -n "$phase_name" ]; then timing_table failed; fi' EXIT

step setup
bash scripts/setup.sh test
# Pixar's USD reader for tests/unit/usdExport.test.ts (tests/usd/check_usd.py), made by setup
build/usd-venv/bin/python -c 'from pxr import Usd; print("usd-core", ".".join(map(str, Usd.GetVersion())))'

step "wasm build (its type declarations are needed by tsc)"
bash wasm-build/build.sh

step "format and lint"
mapfile -t cxx < <(git ls-files 'solver-cpp/*.cpp' 'solver-cpp/*.hpp' 'wasm-build/*.cpp' 'tests/native/*.cpp' 2>/dev/null || true)
if [ ${#cxx[@]} -gt 0 ]; then clang-format --dry-run -Werror "${cxx[@]}"; fi
npx biome check web tests scripts vite.config.ts playwright.config.ts
npx tsc --noEmit -p tsconfig.json

step "native build and tests"
cmake -S solver-cpp -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/native
ctest --test-dir build/native --output-on-failure -j2

step "unit tests (vitest, Node, real wasm)"
npx vitest run

step "web build"
npx vite build --logLevel warn

step "browser tests (Playwright, Debian Chromium)"
npx playwright test

timing_table
echo "npm test: all passed"
