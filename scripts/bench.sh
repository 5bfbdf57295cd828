#!/usr/bin/env bash
# npm run bench: the exact solver's benchmark (issue 3), natively and in wasm under Node, on the
# 29^3 (25K) and 37^3 (50K) boxes: analyse, factor, 3-RHS solve, edits adding then removing a
# curve's 100 / 300 / 1000 clustered points (method chosen, and both methods timed), peak memory,
# and Eigen's SimplicialLDLT refactorisation as the naive baseline, in the same run.
# Then the fast solver against the exact one through the command line (`hairsketch solve
# --solver fast|exact`, wasm) on 37^3 edit sequences of the same kind: both times and the ratio
# (issue 15: fast <= 0.15 x exact), scripts/bench-fast-vs-exact.ts, about 40 s more.
# Prints the tables; writes bench-results/exact-<time>.{jsonl,md} and bench-results/bench.json
# (machine, every measurement, the tables). Takes about 11-12 minutes on two cores.
# Extra arguments go to scripts/bench-exact.sh (e.g. --no-wasm, --sizes 29, --baseline37-wasm),
# except --fast-vs-exact: only the fast-vs-exact part (`npm run bench -- --fast-vs-exact`;
# FAST_VS_EXACT_SEEDS=K runs K sequences).
set -euo pipefail
cd "$(dirname "$0")/.."
only=0
args=()
for a in "$@"; do
  if [ "$a" = --fast-vs-exact ]; then only=1; else args+=("$a"); fi
done
bash scripts/setup.sh bench
base="bench-results/exact-$(date -u +%Y%m%dT%H%M%SZ)"
mkdir -p bench-results
if [ "$only" = 0 ]; then
  # The naive baseline at 37^3 runs natively (200-260 s); in wasm only when asked (see the note
  # printed under the table).
  bash scripts/bench-exact.sh --baseline37 --out "$base" ${args[@]+"${args[@]}"}
else
  base="bench-results/fast-vs-exact-$(date -u +%Y%m%dT%H%M%SZ)"
  : > "$base.jsonl"
fi
bash wasm-build/build.sh > /dev/null
npx tsx scripts/bench-fast-vs-exact.ts --sizes 37 --seeds "${FAST_VS_EXACT_SEEDS:-1}" \
  --json "$base.jsonl" >&2
echo "" >&2
if [ "$only" = 0 ]; then
  node scripts/bench-exact-table.mjs "$base.jsonl" --json bench-results/bench.json > "$base.md"
  sed -n '/hairsketch solve --solver fast/,$p' "$base.md"
  echo "bench: wrote bench-results/bench.json (also $base.jsonl, $base.md)"
else
  node scripts/bench-exact-table.mjs "$base.jsonl" --json "$base.json" | tee "$base.md"
  echo "bench: wrote $base.json (also $base.jsonl, $base.md)"
fi
