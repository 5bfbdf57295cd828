// Heads exported by Blender itself (tests/usd/blender_gltf_head.py, run by bpy in build/bpy-venv,
// made by `bash scripts/setup.sh test`): a .gltf + .bin + texture and a .gltf with everything
// embedded, written into a fresh temporary folder at test time, with what Blender held as the
// reference (triangles, bounds in metres with Y up).
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const BLENDER = 'build/bpy-venv/bin/python';
const SCRIPT = 'tests/usd/blender_gltf_head.py';

export interface BlenderHeads {
  /** Blender's version string. */
  blender: string;
  dir: string;
  /** The files of each export, by name (in `dir`). */
  files: { separate: string[]; embedded: string[] };
  /** Triangles of the mesh Blender exported, and its bounds in glTF axes (metres). */
  triangles: number;
  min: [number, number, number];
  max: [number, number, number];
  /** Milliseconds the script took (Blender's start-up and both exports). */
  ms: number;
  /** A written file's bytes. */
  read(name: string): Buffer;
}

/** Runs Blender's export; rejects with Blender's own message when it fails. */
export function blenderHeads(): Promise<BlenderHeads> {
  if (!existsSync(BLENDER))
    return Promise.reject(
      new Error(
        `${BLENDER} is missing: Blender's Python module (bpy) lives in a virtual environment made by the test setup. Run \`bash scripts/setup.sh test\`.`,
      ),
    );
  const dir = mkdtempSync(join(tmpdir(), 'hs-blender-gltf-'));
  const t0 = performance.now();
  return new Promise((resolve, reject) => {
    const child = spawn(BLENDER, [SCRIPT, dir], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    let err = '';
    child.stdout.on('data', (d) => {
      out += d;
    });
    child.stderr.on('data', (d) => {
      err += d;
    });
    child.on('error', reject);
    child.on('close', (code) => {
      if (code !== 0) {
        reject(new Error(`${SCRIPT} failed (exit ${code}): ${err.trim().slice(-2000)}`));
        return;
      }
      // Blender prints its own lines too; the report is the last one
      const report = JSON.parse(out.trim().split('\n').at(-1) as string);
      resolve({
        ...report,
        dir,
        ms: performance.now() - t0,
        read: (name: string) => readFileSync(join(dir, name)),
      });
    });
  });
}
