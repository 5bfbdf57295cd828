#!/usr/bin/env bash
# npm start: set up what is missing, build, serve the app and print its URL.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
port="${PORT:-5173}"
echo ""
echo "hairsketch is served at  http://127.0.0.1:${port}/   (Ctrl+C stops it)"
echo "  options: ?preset=default|empty|bob|long|fig6|fig7|fig8|fig1|curly|braid|bun|pigtail-braids  ?grid=25k|50k|100k|250k  ?solver=fast|exact|auto|cg  ?strands=N"
echo ""
exec npx vite preview --port "$port" --strictPort
