// Distance along a triangle mesh's edges from a set of source vertices, up to a cut-off:
// Dijkstra's shortest paths over the edge graph with a binary heap, stopping at the cut-off.

/** Per vertex: the shortest path along the mesh's edges to a vertex where `source` is true, or
 *  Infinity where that is `cutoff` or more. */
export function edgeDistance(
  positions: ArrayLike<number>,
  indices: ArrayLike<number>,
  source: (vertex: number) => boolean,
  cutoff: number,
): Float64Array {
  const n = positions.length / 3;
  const { start, next } = vertexNeighbours(n, indices);
  const d = new Float64Array(n).fill(Infinity);
  const heap = new VertexHeap(d);
  for (let v = 0; v < n; v++)
    if (source(v)) {
      d[v] = 0;
      heap.push(v);
    }
  const done = new Uint8Array(n);
  while (heap.size > 0) {
    const a = heap.pop();
    if (done[a]) continue;
    done[a] = 1;
    for (let k = start[a]; k < start[a + 1]; k++) {
      const b = next[k];
      if (done[b]) continue;
      const e = Math.hypot(
        positions[3 * a] - positions[3 * b],
        positions[3 * a + 1] - positions[3 * b + 1],
        positions[3 * a + 2] - positions[3 * b + 2],
      );
      const via = d[a] + e;
      if (via < d[b] && via < cutoff) {
        d[b] = via;
        heap.push(b);
      }
    }
  }
  return d;
}

/** Each vertex's neighbours along the triangles' edges (an edge shared by two triangles is
 *  listed twice: harmless for shortest paths). */
function vertexNeighbours(n: number, indices: ArrayLike<number>) {
  const start = new Uint32Array(n + 1);
  for (let i = 0; i < indices.length; i++) start[indices[i] + 1] += 2;
  for (let v = 0; v < n; v++) start[v + 1] += start[v];
  const fill = start.slice(0, n);
  const next = new Uint32Array(start[n]);
  for (let t = 0; t + 2 < indices.length; t += 3)
    for (let k = 0; k < 3; k++) {
      const a = indices[t + k];
      const b = indices[t + ((k + 1) % 3)];
      const c = indices[t + ((k + 2) % 3)];
      next[fill[a]++] = b;
      next[fill[a]++] = c;
    }
  return { start, next };
}

/** A min-heap of vertices keyed by `key[vertex]` at the time each was pushed (a vertex pushed
 *  again with a smaller key is popped first; its older entries are skipped by the caller). */
class VertexHeap {
  private items: number[] = [];
  private keys: number[] = [];
  constructor(private readonly key: Float64Array) {}
  get size(): number {
    return this.items.length;
  }
  push(v: number): void {
    const { items, keys } = this;
    let i = items.length;
    const k = this.key[v];
    items.push(v);
    keys.push(k);
    while (i > 0) {
      const p = (i - 1) >> 1;
      if (keys[p] <= k) break;
      items[i] = items[p];
      keys[i] = keys[p];
      i = p;
    }
    items[i] = v;
    keys[i] = k;
  }
  pop(): number {
    const { items, keys } = this;
    const top = items[0];
    const v = items.pop() as number;
    const k = keys.pop() as number;
    const n = items.length;
    if (n > 0) {
      let i = 0;
      for (;;) {
        let c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && keys[c + 1] < keys[c]) c++;
        if (keys[c] >= k) break;
        items[i] = items[c];
        keys[i] = keys[c];
        i = c;
      }
      items[i] = v;
      keys[i] = k;
    }
    return top;
  }
}
