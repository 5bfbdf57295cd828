#!/usr/bin/env bash
# npm test: set up what is missing, then format + lint + types, native tests, wasm build,
# unit tests (with the real wasm under Node) and browser tests against Debian's Chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
step() { echo ""; echo "== $* ($(( $(date +%s) - start )) s)"; }

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

echo ""
echo "npm test: all passed in $(( $(date +%s) - start )) s"
