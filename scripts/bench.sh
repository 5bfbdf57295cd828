#!/usr/bin/env bash
# npm run bench: the exact solver's benchmark (issue 3), natively and in wasm under Node, on the
# 29^3 (25K) and 37^3 (50K) boxes: analyse, factor, 3-RHS solve, edits adding then removing a
# curve's 100 / 300 / 1000 clustered points (method chosen, and both methods timed), peak memory,
# and Eigen's SimplicialLDLT refactorisation as the naive baseline, in the same run.
# Prints the table; writes bench-results/exact-<time>.{jsonl,md} and bench-results/bench.json
# (machine, every measurement, the table). Takes about 10-11 minutes on two cores.
# Extra arguments go to scripts/bench-exact.sh (e.g. --no-wasm, --sizes 29, --baseline37-wasm).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh bench
base="bench-results/exact-$(date -u +%Y%m%dT%H%M%SZ)"
# The naive baseline at 37^3 runs natively (200-260 s); in wasm only when asked (see the note
# printed under the table).
bash scripts/bench-exact.sh --baseline37 --out "$base" "$@"
node scripts/bench-exact-table.mjs "$base.jsonl" --json bench-results/bench.json > /dev/null
echo "bench: wrote bench-results/bench.json (also $base.jsonl, $base.md)"
