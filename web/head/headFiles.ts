// "Open head" with several files picked at once: a .gltf with its .bin and textures. The head is
// the one head file among them; a .gltf and what it refers to become one self-contained GLB
// (gltfPack.ts), which is what the head store keeps, so sessions and links find it again (the
// same files picked again give the same bytes, hence the same SHA-256).
import { selfContainedGlb } from './gltfPack';
import { HeadFileError } from './headFileError';

export interface PickedFile {
  name: string;
  bytes: ArrayBuffer;
}

const HEAD_FILE = /\.(obj|gltf|glb|ply|stl)$/i;

/** The head file to load from files picked together (one line saying why not when there is
 *  not exactly one head among them or its .gltf cannot be made whole). */
export function headFromPicked(
  files: readonly PickedFile[],
): { ok: true; head: PickedFile } | { ok: false; error: string } {
  if (files.length === 1) return { ok: true, head: files[0] };
  const heads = files.filter((f) => HEAD_FILE.test(f.name));
  if (heads.length !== 1)
    return {
      ok: false,
      error:
        heads.length === 0
          ? 'none of the files picked is a head (OBJ, glTF/GLB, PLY or STL)'
          : 'pick one head file at a time (a .gltf may come with its .bin and textures)',
    };
  const head = heads[0];
  if (!/\.gltf$/i.test(head.name)) return { ok: true, head };
  const resources = new Map(files.filter((f) => f !== head).map((f) => [f.name, f.bytes]));
  try {
    return {
      ok: true,
      head: { name: head.name, bytes: selfContainedGlb('gltf', head.bytes, resources) },
    };
  } catch (e) {
    const why = e instanceof HeadFileError ? e.message : 'it could not be read';
    return { ok: false, error: `Cannot open ${head.name}: ${why}` };
  }
}
