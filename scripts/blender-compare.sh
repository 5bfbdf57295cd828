#!/usr/bin/env bash
# The app's look beside Blender Cycles' Principled Hair BSDF (melanin parametrisation) for the
# `long` preset, from the app's front view: writes docs/screenshots/look/app-long.png (the app's
# High quality, `hairsketch render`'s renderer) and docs/screenshots/look/blender-long.png
# (scripts/blender-compare.py on the same session's USD export), and blender-long-represented.png
# with each strand as wide as the app draws it. Slow (minutes): not in npm test.
#   bash scripts/blender-compare.sh [SIZE] [SAMPLES]     (defaults 400 and 16)
# Needs the built app and command line (npm run build) and build/bpy-venv (npm test's setup).
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-400}
samples=${2:-16}
out=docs/screenshots/look
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
npx tsx -e "
import { writeFileSync } from 'node:fs';
import { presetSession } from './web/cli/presetSession';
import { Head } from './web/head/head';
import { writeSessionFile } from './web/model/sessionFile';
const s = presetSession('long', Head.builtin());
writeSessionFile(s).then((text) => {
  writeFileSync('$tmp/long.hairsketch.json', text);
  console.log(JSON.stringify(s.hairLook));
});
" > "$tmp/look.json"
node scripts/hairsketch.mjs grow "$tmp/long.hairsketch.json" --out "$tmp/long.usda" >/dev/null 2>&1
build/bpy-venv/bin/python scripts/blender-compare.py "$tmp/long.usda" "$out/blender-long.png" \
  "$size" "$samples" "$(cat "$tmp/look.json")"
build/bpy-venv/bin/python scripts/blender-compare.py "$tmp/long.usda" \
  "$out/blender-long-represented.png" "$size" "$samples" "$(cat "$tmp/look.json")" represented
SHOT_SIZE="${size}x${size}" SHOT_QUALITY=high SHOT_OUT="$tmp" npx tsx scripts/screenshots.ts long >/dev/null
cp "$tmp/long-front.png" "$out/app-long.png"
echo "$out/app-long.png $out/blender-long.png $out/blender-long-represented.png"
