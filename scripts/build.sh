#!/usr/bin/env bash
# Builds the wasm solver, the web app into dist/ and the command line into build/cli/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh runtime
bash wasm-build/build.sh
npx vite build --logLevel warn
npx vite build -c vite.cli.config.ts
