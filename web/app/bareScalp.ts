// Bare scalp where hair should be: from a few directions (orthographic, parallel to the view
// direction), which scalp points show through the hair although the hair round them hides the
// scalp: a gap or a thin patch in hair that otherwise covers the head. Bare scalp in the open (a
// shaved side, the scalp outside a bob's hairline) is not counted: its neighbourhood is bare too.
//
// Per view: the sample points are the centroids of the scalp triangles that face the viewer
// (normal · toViewer > `facing`) and that the head itself does not hide (an orthographic depth
// raster of every head triangle, sampled at cell centres). Every strand segment is drawn into a
// second raster of the same cells (world-space cells of `cell`, 2 mm), keeping per cell the depth
// nearest the viewer. A point is covered when some hair in its cell or the 8 cells round it lies
// in front of it: nearer the viewer than the point's own triangle's plane at that cell, less a
// tolerance for where in the cell the hair and the point lie (it grows with the plane's slope).
// A point is bare where hair should be when it is not covered but at least `share` (75 %) of the
// view's other points within `radius` (2 cm) of it on screen are (points are counted per cell:
// within `radius` cell centre to cell centre).
//
// Hair is drawn along each segment's centre line: a 0.5 mm wide line would mark other cells only
// within 0.25 mm of a cell's border, which the 3 × 3 neighbourhood absorbs. Any hair at all
// covers in this test, a root too: with the app's ~1 mm root spacing every scalp cell holds
// roots, so only a patch of scalp without hair shows, not a parting or a whorl where strands
// leave their roots apart. `minOpacity` asks in addition that the hair in front hide a share of
// the point's own cell, each segment counted as a line `lineWidth` (0.5 mm) wide.
//
// Pure: no DOM, no three.js; the test hook (testApi.ts bareScalp) passes the head shown and the
// hair drawn.

export interface BareScalpMesh {
  positions: ArrayLike<number>; // positions[3 * vertex + axis]
  indices: ArrayLike<number>; // indices[3 * triangle + corner], counter-clockwise from outside
  scalp: ArrayLike<number>; // scalp[triangle] = 1 on the hair-bearing region
}

export interface BareScalpHair {
  points: ArrayLike<number>; // points[3 * point + axis]
  strandStart: ArrayLike<number>; // strand s owns strandStart[s] .. strandStart[s + 1] - 1
}

export interface BareScalpView {
  name: string;
  /** Unit direction from the head towards the viewer (front: [0, 0, 1], the face looks at +z). */
  toViewer: [number, number, number];
}

/** Front (from +z), side (from +x), back (from −z) and top (from +y). */
export const BARE_SCALP_VIEWS: readonly BareScalpView[] = [
  { name: 'front', toViewer: [0, 0, 1] },
  { name: 'side', toViewer: [1, 0, 0] },
  { name: 'back', toViewer: [0, 0, -1] },
  { name: 'top', toViewer: [0, 1, 0] },
];

export interface BareScalpOptions {
  /** Raster cell, world units (default 0.02: 2 mm). */
  cell?: number;
  /** A scalp triangle is a sample when normal · toViewer exceeds this (default 0.2). */
  facing?: number;
  /** Neighbourhood on screen of the bare-where-hair test, world units (default 0.2: 2 cm). */
  radius?: number;
  /** Share of covered neighbours that makes an uncovered point bare where hair should be
   *  (default 0.75). */
  share?: number;
  /** Also return the bare-where-hair points (flat x, y, z), for pictures and tests. */
  keepPoints?: boolean;
  /** A stricter cover (default 0: off): a point is covered only when, besides, the hair in front
   *  of the head in its own cell hides at least this share of the cell, each segment a line
   *  `lineWidth` wide: 1 − exp(−Σ width · length / cell²). A root alone then no longer covers. */
  minOpacity?: number;
  /** Width of a hair line for minOpacity, world units (default 0.005: 0.5 mm). */
  lineWidth?: number;
}

export interface BareScalpCounts {
  /** Scalp points seen from the view. */
  points: number;
  /** Of those, points hair hides. */
  covered: number;
  /** Of those, uncovered points whose neighbourhood is covered. */
  bareWhereHair: number;
  /** covered / points (0 with no points). */
  coveredShare: number;
  /** bareWhereHair / points (0 with no points). */
  bareShare: number;
}

export interface BareScalpViewResult extends BareScalpCounts {
  view: string;
  /** With keepPoints: the bare-where-hair points, x, y, z each. */
  bareAt?: number[];
}

export interface BareScalpResult {
  views: BareScalpViewResult[];
  /** Sums over the views (shares of the summed points). */
  total: BareScalpCounts;
}

export function bareScalp(
  mesh: BareScalpMesh,
  hair: BareScalpHair | null,
  views: readonly BareScalpView[] = BARE_SCALP_VIEWS,
  opts: BareScalpOptions = {},
): BareScalpResult {
  const out = views.map((v) => oneView(mesh, hair, v, opts));
  const points = out.reduce((n, r) => n + r.points, 0);
  const covered = out.reduce((n, r) => n + r.covered, 0);
  const bareWhereHair = out.reduce((n, r) => n + r.bareWhereHair, 0);
  return { views: out, total: counts(points, covered, bareWhereHair) };
}

function counts(points: number, covered: number, bareWhereHair: number): BareScalpCounts {
  return {
    points,
    covered,
    bareWhereHair,
    coveredShare: points > 0 ? covered / points : 0,
    bareShare: points > 0 ? bareWhereHair / points : 0,
  };
}

function oneView(
  mesh: BareScalpMesh,
  hair: BareScalpHair | null,
  view: BareScalpView,
  opts: BareScalpOptions,
): BareScalpViewResult {
  const cell = opts.cell ?? 0.02;
  const facing = opts.facing ?? 0.2;
  const radius = opts.radius ?? 0.2;
  const share = opts.share ?? 0.75;
  const minOpacity = opts.minOpacity ?? 0;
  const width = opts.lineWidth ?? 0.005;
  const P = mesh.positions;
  const I = mesh.indices;
  // the view's frame: depth d along w (larger = nearer the viewer), screen axes a, b across it
  const w = unit(view.toViewer);
  const up: [number, number, number] = Math.abs(w[1]) < 0.9 ? [0, 1, 0] : [0, 0, -1];
  const a = unit(cross(up, w));
  const b = cross(w, a);
  const nv = P.length / 3;
  const va = new Float64Array(nv);
  const vb = new Float64Array(nv);
  const vd = new Float64Array(nv);
  for (let i = 0; i < nv; i++) {
    const x = P[3 * i];
    const y = P[3 * i + 1];
    const z = P[3 * i + 2];
    va[i] = x * a[0] + y * a[1] + z * a[2];
    vb[i] = x * b[0] + y * b[1] + z * b[2];
    vd[i] = x * w[0] + y * w[1] + z * w[2];
  }

  // the samples: facing scalp triangles' centroids with their plane's depth slope on screen
  const nt = I.length / 3;
  const sa: number[] = [];
  const sb: number[] = [];
  const sd: number[] = [];
  const ga: number[] = []; // ∂d/∂a of the triangle's plane
  const gb: number[] = [];
  const tri: number[] = [];
  for (let t = 0; t < nt; t++) {
    if (mesh.scalp[t] !== 1) continue;
    const i0 = I[3 * t];
    const i1 = I[3 * t + 1];
    const i2 = I[3 * t + 2];
    // the normal in view coordinates (a, b, d) from the projected corners
    const ea = [va[i1] - va[i0], vb[i1] - vb[i0], vd[i1] - vd[i0]];
    const eb = [va[i2] - va[i0], vb[i2] - vb[i0], vd[i2] - vd[i0]];
    const na = ea[1] * eb[2] - ea[2] * eb[1];
    const nb = ea[2] * eb[0] - ea[0] * eb[2];
    const nd = ea[0] * eb[1] - ea[1] * eb[0];
    const len = Math.hypot(na, nb, nd);
    if (!(len > 0) || nd / len <= facing) continue;
    sa.push((va[i0] + va[i1] + va[i2]) / 3);
    sb.push((vb[i0] + vb[i1] + vb[i2]) / 3);
    sd.push((vd[i0] + vd[i1] + vd[i2]) / 3);
    ga.push(-na / nd);
    gb.push(-nb / nd);
    tri.push(t);
  }
  const result = (pts: number, cov: number, bare: number, at?: number[]): BareScalpViewResult => ({
    view: view.name,
    ...counts(pts, cov, bare),
    ...(opts.keepPoints ? { bareAt: at ?? [] } : {}),
  });
  const ns = sa.length;
  if (ns === 0) return result(0, 0, 0);

  // the raster: the samples' extent on screen and a margin of two cells
  let a0 = Number.POSITIVE_INFINITY;
  let a1 = Number.NEGATIVE_INFINITY;
  let b0 = Number.POSITIVE_INFINITY;
  let b1 = Number.NEGATIVE_INFINITY;
  for (let k = 0; k < ns; k++) {
    a0 = Math.min(a0, sa[k]);
    a1 = Math.max(a1, sa[k]);
    b0 = Math.min(b0, sb[k]);
    b1 = Math.max(b1, sb[k]);
  }
  a0 -= 2 * cell;
  b0 -= 2 * cell;
  const nx = Math.ceil((a1 + 2 * cell - a0) / cell) + 1;
  const ny = Math.ceil((b1 + 2 * cell - b0) / cell) + 1;

  // the head's depth at cell centres: every triangle (the nearest surface wins)
  const head = new Float32Array(nx * ny).fill(Number.NEGATIVE_INFINITY);
  for (let t = 0; t < nt; t++) {
    const i0 = I[3 * t];
    const i1 = I[3 * t + 1];
    const i2 = I[3 * t + 2];
    const ax = va[i0];
    const ay = vb[i0];
    const bx = va[i1];
    const by = vb[i1];
    const cx = va[i2];
    const cy = vb[i2];
    const area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (area === 0) continue;
    const x0 = Math.max(0, Math.ceil((Math.min(ax, bx, cx) - a0) / cell - 0.5));
    const x1 = Math.min(nx - 1, Math.floor((Math.max(ax, bx, cx) - a0) / cell - 0.5));
    const y0 = Math.max(0, Math.ceil((Math.min(ay, by, cy) - b0) / cell - 0.5));
    const y1 = Math.min(ny - 1, Math.floor((Math.max(ay, by, cy) - b0) / cell - 0.5));
    for (let y = y0; y <= y1; y++) {
      const py = b0 + (y + 0.5) * cell;
      for (let x = x0; x <= x1; x++) {
        const px = a0 + (x + 0.5) * cell;
        // barycentric weights (signed areas, the triangle's orientation divided out)
        const l0 = ((bx - px) * (cy - py) - (by - py) * (cx - px)) / area;
        const l1 = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) / area;
        const l2 = 1 - l0 - l1;
        if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
        const d = l0 * vd[i0] + l1 * vd[i1] + l2 * vd[i2];
        const c = y * nx + x;
        if (d > head[c]) head[c] = d;
      }
    }
  }
  // a sample's plane depth at the centre of cell (x, y)
  const planeAt = (k: number, x: number, y: number) =>
    sd[k] + ga[k] * (a0 + (x + 0.5) * cell - sa[k]) + gb[k] * (b0 + (y + 0.5) * cell - sb[k]);
  const seen: number[] = [];
  for (let k = 0; k < ns; k++) {
    const x = Math.floor((sa[k] - a0) / cell);
    const y = Math.floor((sb[k] - b0) / cell);
    if (head[y * nx + x] <= planeAt(k, x, y) + 0.005) seen.push(k);
  }

  // the hair's nearest depth per cell: each segment sampled every half cell
  const near = new Float32Array(nx * ny).fill(Number.NEGATIVE_INFINITY);
  // with minOpacity: the line area per cell of hair in front of the head's surface there (less
  // 1 cm, for where in the cell each lies), divided by the cell's area
  const amount = minOpacity > 0 ? new Float32Array(nx * ny) : null;
  const H = hair?.points;
  const S = hair?.strandStart;
  if (H && S) {
    const np = H.length / 3;
    const ha = new Float32Array(np);
    const hb = new Float32Array(np);
    const hd = new Float32Array(np);
    for (let i = 0; i < np; i++) {
      const x = H[3 * i];
      const y = H[3 * i + 1];
      const z = H[3 * i + 2];
      ha[i] = x * a[0] + y * a[1] + z * a[2];
      hb[i] = x * b[0] + y * b[1] + z * b[2];
      hd[i] = x * w[0] + y * w[1] + z * w[2];
    }
    const aEnd = a0 + nx * cell;
    const bEnd = b0 + ny * cell;
    const step = cell / 2;
    for (let s = 0; s + 1 < S.length; s++)
      for (let i = S[s]; i + 1 < S[s + 1]; i++) {
        const pa = ha[i];
        const pb = hb[i];
        const qa = ha[i + 1];
        const qb = hb[i + 1];
        // off the raster altogether
        if ((pa < a0 && qa < a0) || (pa >= aEnd && qa >= aEnd)) continue;
        if ((pb < b0 && qb < b0) || (pb >= bEnd && qb >= bEnd)) continue;
        const pd = hd[i];
        const qd = hd[i + 1];
        const len = Math.hypot(qa - pa, qb - pb);
        const n = Math.ceil(len / step);
        const per = (width * len) / (n + 1) / (cell * cell);
        for (let j = 0; j <= n; j++) {
          const f = n > 0 ? j / n : 0;
          const x = Math.floor((pa + f * (qa - pa) - a0) / cell);
          const y = Math.floor((pb + f * (qb - pb) - b0) / cell);
          if (x < 0 || y < 0 || x >= nx || y >= ny) continue;
          const d = pd + f * (qd - pd);
          const c = y * nx + x;
          if (d > near[c]) near[c] = d;
          if (amount && d > head[c] - 0.1) amount[c] += per;
        }
      }
  }
  const covered = new Uint8Array(seen.length);
  let nCovered = 0;
  for (let m = 0; m < seen.length; m++) {
    const k = seen[m];
    const x = Math.floor((sa[k] - a0) / cell);
    const y = Math.floor((sb[k] - b0) / cell);
    // where in a cell the hair and the point lie moves the plane's depth by up to this much
    const tol = 0.005 + 0.75 * cell * Math.hypot(ga[k], gb[k]);
    let hit = false;
    for (let dy = -1; dy <= 1 && !hit; dy++)
      for (let dx = -1; dx <= 1 && !hit; dx++) {
        const c = (y + dy) * nx + (x + dx); // inside: the raster has a two-cell margin
        if (near[c] > planeAt(k, x + dx, y + dy) - tol) hit = true;
      }
    if (hit && amount && 1 - Math.exp(-amount[y * nx + x]) < minOpacity) hit = false;
    if (hit) {
      covered[m] = 1;
      nCovered++;
    }
  }

  // bare where hair should be: the points seen and those covered counted per cell, on a grid
  // with a margin of `radius`; a point's neighbourhood is the cells whose centres lie within
  // `radius` of its cell's centre (a disc of ~314 cells at the defaults)
  const R = Math.ceil(radius / cell);
  const mx = nx + 2 * R;
  const total = new Int32Array(mx * (ny + 2 * R));
  const hidden = new Int32Array(mx * (ny + 2 * R));
  const cellAt = new Int32Array(seen.length);
  for (let m = 0; m < seen.length; m++) {
    const k = seen[m];
    const c = (Math.floor((sb[k] - b0) / cell) + R) * mx + Math.floor((sa[k] - a0) / cell) + R;
    cellAt[m] = c;
    total[c]++;
    hidden[c] += covered[m];
  }
  const disc: number[] = [];
  for (let dy = -R; dy <= R; dy++)
    for (let dx = -R; dx <= R; dx++)
      if ((dx * dx + dy * dy) * cell * cell <= radius * radius) disc.push(dy * mx + dx);
  let bare = 0;
  const at: number[] = [];
  for (let m = 0; m < seen.length; m++) {
    if (covered[m]) continue;
    const c0 = cellAt[m];
    let others = -1; // not the point itself (uncovered: it adds nothing to cov)
    let cov = 0;
    for (const o of disc) {
      others += total[c0 + o];
      cov += hidden[c0 + o];
    }
    if (others > 0 && cov >= share * others) {
      bare++;
      if (opts.keepPoints) {
        const t = tri[seen[m]];
        for (let axis = 0; axis < 3; axis++)
          at.push(
            (P[3 * I[3 * t] + axis] + P[3 * I[3 * t + 1] + axis] + P[3 * I[3 * t + 2] + axis]) / 3,
          );
      }
    }
  }
  return result(seen.length, nCovered, bare, at);
}

function cross(p: readonly number[], q: readonly number[]): [number, number, number] {
  return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
}

function unit(p: readonly number[]): [number, number, number] {
  const l = Math.hypot(p[0], p[1], p[2]);
  return [p[0] / l, p[1] / l, p[2] / l];
}
