// The head an export carries: the head's triangles, and the bust's after them when the session
// shows one (its vertices numbered after the head's), as one mesh.
import type { ExportHead } from './types';

/** `head` with `body` appended (null: the head alone). Normals are kept when both have them. */
export function exportHeadWithBody(head: ExportHead, body: ExportHead | null): ExportHead {
  if (!body) return head;
  const nv = head.positions.length / 3;
  const positions = new Float32Array(head.positions.length + body.positions.length);
  positions.set(head.positions);
  positions.set(body.positions, head.positions.length);
  const indices = new Uint32Array(head.indices.length + body.indices.length);
  indices.set(head.indices);
  for (let i = 0; i < body.indices.length; i++)
    indices[head.indices.length + i] = body.indices[i] + nv;
  let normals: Float32Array | undefined;
  if (head.normals && body.normals) {
    normals = new Float32Array(positions.length);
    normals.set(head.normals);
    normals.set(body.normals, head.normals.length);
  }
  return normals ? { positions, indices, normals } : { positions, indices };
}
