#!/usr/bin/env bash
# Builds the wasm solver and the web app into dist/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh runtime
bash wasm-build/build.sh
npx vite build --logLevel warn
