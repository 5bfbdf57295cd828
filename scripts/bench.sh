#!/usr/bin/env bash
# npm run bench: the exact solver's benchmark, natively and in wasm under Node, on the
# 29^3 (25K) and 37^3 (50K) boxes: analyse, factor, 3-RHS solve, edits adding then removing a
# curve's 100 / 300 / 1000 clustered points (method chosen, and both methods timed), peak memory,
# and Eigen's SimplicialLDLT refactorisation as the naive baseline, in the same run.
# Then the fast solver against the exact one through the command line (`hairsketch solve
# --solver fast|exact`, wasm) on 37^3 edit sequences of the same kind: both times and the ratio
# (target: fast <= 0.15 x exact), scripts/bench-fast-vs-exact.ts, about 40 s more.
# Prints the tables; writes bench-results/exact.{json,md} (date, commit, machine, every
# measurement, the tables) and bench-results/fast-vs-exact.{json,md}; the raw lines stay in
# build/bench/exact.jsonl. Takes about 11-12 minutes on two cores.
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
base="build/bench/exact"
mkdir -p build/bench
if [ "$only" = 0 ]; then
  # The naive baseline at 37^3 runs natively (200-260 s); in wasm only when asked (see the note
  # printed under the table).
  bash scripts/bench-exact.sh --baseline37 --out "$base" ${args[@]+"${args[@]}"}
  bash wasm-build/build.sh > /dev/null
  npx tsx scripts/bench-fast-vs-exact.ts --sizes 37 --seeds "${FAST_VS_EXACT_SEEDS:-1}" \
    --json "$base.jsonl" >&2
  echo "" >&2
  node scripts/bench-exact-table.mjs "$base.jsonl" --name exact | sed -n '/hairsketch solve --solver fast/,$p'
else
  bash wasm-build/build.sh > /dev/null
  npx tsx scripts/bench-fast-vs-exact.ts --sizes 37 --seeds "${FAST_VS_EXACT_SEEDS:-1}" >&2
fi
