// Builds the sketching tools with what each needs to know (stroke samples from the head, the
// camera, the selected curve) and what each may do: every edit is an editor command; the
// stream curve being drawn is the editor's stroke in progress (the solver previews it from
// there); drafts and guides go to the view.

import { curveSurface } from '../editor/curveSurface';
import type { Editor, ToolName } from '../editor/editor';
import type { Head } from '../head/head';
import type { ScalpPaintStroke } from '../head/scalpPaint';
import { defaultParams, type PlainTieKind } from '../model/curveParams';
import { STROKE_KINDS } from '../model/kinds';
import { type MirrorPlane, snapToPlane, X_PLANE } from '../model/mirror';
import { newCurveExtends, streamExtends, tieAtEnd } from '../model/session';
import { distance, sub, type Vec3 } from '../model/vec3';
import { BunTool } from '../tools/bunTool';
import type { StrokeSample } from '../tools/depthRule';
import { DividingCurveTool } from '../tools/dividingCurveTool';
import { PONYTAIL_STAGE_HINT, type PonytailStage, PonytailTool } from '../tools/ponytailTool';
import { ScalpBrushTool } from '../tools/scalpBrushTool';
import { SelectTool } from '../tools/selectTool';
import { StreamCurveTool } from '../tools/streamCurveTool';
import type { Tool } from '../tools/tool';
import type { Viewer } from '../viewer/viewer';
import { partingOverOutline } from './partingOverOutline';
import { streamOnMiddle } from './streamOnMiddle';
import { TIE_TOOL_KINDS, TIE_TOOLS } from './tieTools';

const TOOL_HINTS: Record<Exclude<ToolName, 'ponytail' | PlainTieKind>, string> = {
  stream:
    'Drag from the scalp to draw a stream curve · a stroke starting on the selected curve cuts, extends or re-routes it · right-drag orbits · wheel zooms · ? lists shortcuts',
  dividing:
    'Drag on the scalp to draw a parting · a stroke starting beside the selected one tilts that side · right-drag orbits',
  select:
    'Click a curve to select it · drag orbits · wheel zooms · right-drag pans · ? lists shortcuts',
  scalp:
    'Drag on the head to paint scalp (where hair grows) · Shift+drag erases · wheel sets the brush radius · right-drag orbits',
};

/** The hint line for the tool `name` (the ponytail's says which stroke comes next). */
export function toolHint(name: ToolName, ponytailStage: PonytailStage): string {
  if (name === 'ponytail') return PONYTAIL_STAGE_HINT[ponytailStage];
  return Object.hasOwn(TIE_TOOLS, name)
    ? TIE_TOOLS[name as PlainTieKind].hint
    : TOOL_HINTS[name as keyof typeof TOOL_HINTS];
}

export interface ToolDeps {
  editor: Editor;
  /** The head strokes land on (it changes when the user opens another). */
  head(): Head;
  viewer: Viewer;
  step: number;
  /** Mirror editing is on: new curves get a twin. */
  mirror(): boolean;
  /** The style curves are shown (hidden curves cannot be picked). */
  curvesShown(): boolean;
  /** Construction lines of the ponytail being built (empty: none). */
  showGuides(lines: readonly (readonly Vec3[])[]): void;
  /** A sentence for the status line. */
  notify(message: string): void;
  /** The ponytail tool's next stroke changed. */
  ponytailStage(stage: PonytailStage): void;
  /** Shows a scalp brush stroke painted while it is drawn (null: the preview ends). */
  previewScalp(stroke: ScalpPaintStroke | null, mirror: MirrorPlane | null): void;
}

export interface ToolSet {
  readonly byName: Record<ToolName, Tool>;
  readonly ponytail: PonytailTool;
  readonly scalpBrush: ScalpBrushTool;
}

// How near the scalp (world units: 5 mm) a stroke's last point must be to count as ending on it.
const SCALP_END_REACH = 0.05;
// A stroke that ends on the scalp this near its edge (world units: 2 cm from the face, an ear or
// the neck) ends its hair there, as one that leaves the head does: fresh eyes drew a pixie's nape
// down to what looked like the neck, ended 1 cm above the hairline (its points, a grid step
// apart, stop up to a step short of the pointer: 1.3 cm at 25K), and the hair combed on down the
// neck as a mullet.
const HAIRLINE_END_BAND = 0.2;
// A stroke drawn downward (its last segment at least 37° below level) that ends on the scalp
// where the head faces sideways or down (the surface's normal under 12° above level: the back
// below the crown, the sides) ends its hair there: hair hangs there anyway, and fresh eyes who
// drew a pixie's nape over the hair from behind, stopping where the neck seemed to begin (3 cm
// above the hairline the hair hid), got the nape hair combed on down the neck.
const HANG_STROKE_Y = -0.6;
const HANG_SURFACE_Y = 0.2;
// How far off the scalp (world units: 2 cm) a stroke's press may land and still start on it.
const START_REACH = 0.2;
// How far past the head's outline (world units: 3 cm, about as far as hair stands off it) a
// press still starts on it: fresh eyes pressed on the hair beside a long style's crown, 1-2 cm
// outside the head, and were refused.
const OUTLINE_REACH = 0.3;

/** What every tool is built from: the page's picking, the camera, the draft line and the rule
 *  for whether a stroke's hair grows on past its end. */
interface ToolKit {
  d: ToolDeps;
  editor: ToolDeps['editor'];
  viewer: ToolDeps['viewer'];
  step: () => number;
  camera: () => ReturnType<ToolDeps['viewer']['cameraState']>;
  sample: (x: number, y: number) => StrokeSample;
  sampleStart: (x: number, y: number) => StrokeSample;
  eye: () => Vec3;
  forward: () => Vec3;
  showDraft: (pts: readonly Vec3[] | null) => void;
  strokeExtends: (pts: readonly Vec3[]) => boolean;
  /** Whether a stroke's last point lies on the scalp (within SCALP_END_REACH), inside its edge
   *  (HAIRLINE_END_BAND): it combs. */
  endsOnScalp: (pts: readonly Vec3[]) => boolean;
}

function toolKit(d: ToolDeps): ToolKit {
  const { editor, viewer } = d;
  const step = () => d.step;
  const camera = () => viewer.cameraState();
  const sample = (x: number, y: number): StrokeSample => {
    const ray = viewer.rayAt(x, y);
    const origin: Vec3 = [ray.origin.x, ray.origin.y, ray.origin.z];
    const direction: Vec3 = [ray.direction.x, ray.direction.y, ray.direction.z];
    const hit = d.head().raycast(origin, direction);
    return {
      origin,
      direction,
      scalpHit: hit?.scalp ? hit.point : null,
      headDistance: hit ? hit.distance : null,
    };
  };
  // A stroke's press just off the scalp (on the forehead or a sideburn's skin under the hair,
  // where the scalp's edge cannot be seen) starts at the nearest scalp point within
  // START_REACH; the rest of the stroke is sampled as it is.
  const sampleStart = (x: number, y: number): StrokeSample => {
    const s = sample(x, y);
    if (s.scalpHit) return s;
    const head = d.head();
    let at: Vec3;
    if (s.headDistance != null) {
      at = [
        s.origin[0] + s.headDistance * s.direction[0],
        s.origin[1] + s.headDistance * s.direction[1],
        s.origin[2] + s.headDistance * s.direction[2],
      ];
    } else {
      // a press on the outline or just outside it (the ray grazes past the head): the head
      // point nearest the ray where it passes closest to the head's centre, within OUTLINE_REACH
      const c = head.center;
      const t =
        (c[0] - s.origin[0]) * s.direction[0] +
        (c[1] - s.origin[1]) * s.direction[1] +
        (c[2] - s.origin[2]) * s.direction[2];
      const p: Vec3 = [
        s.origin[0] + t * s.direction[0],
        s.origin[1] + t * s.direction[1],
        s.origin[2] + t * s.direction[2],
      ];
      const near = head.closest(p);
      if (!(near.distance < OUTLINE_REACH)) return s;
      at = near.point;
    }
    // failing that, the scalp the press is beside on screen: from the top view, a press on an ear
    // or just past the head's outline beside it was refused
    const scalpHit =
      head.nearestScalpPoint(at, START_REACH) ??
      head.scalpPointNearRay(s.origin, s.direction, OUTLINE_REACH);
    return { ...s, scalpHit };
  };
  // with natural fall a new curve's hair ends where the stroke ends: the draft marks it
  // A stream stroke's hair grows on past its end when the session says so, when it ends at a
  // tie, or when it ends on the scalp inside the hairline (a stroke that stays on the head combs
  // the hair, one that leaves it, or ends at the hairline, says where the hair ends)
  const endsOnScalp = (pts: readonly Vec3[]) => {
    const end = pts[pts.length - 1];
    if (!end) return false;
    const h = d.head();
    const near = h.closest(end);
    if (!(near.distance < SCALP_END_REACH && h.mesh.scalp[near.triangle] === 1)) return false;
    const last = pts[pts.length - 2];
    const along = last ? sub(end, last) : ([0, 0, 0] as Vec3);
    const len = Math.hypot(along[0], along[1], along[2]);
    const hangs = len > 0 && along[1] / len < HANG_STROKE_Y && near.normal[1] < HANG_SURFACE_Y;
    return !hangs && !h.nearScalpEdge(end, HAIRLINE_END_BAND);
  };
  const strokeExtends = (pts: readonly Vec3[]) =>
    streamExtends(editor.session, pts) || endsOnScalp(pts);
  const showDraft = (pts: readonly Vec3[] | null) =>
    viewer.setDraft(pts, !(pts ? strokeExtends(pts) : newCurveExtends(editor.session)));
  const eye = () => viewer.eye();
  const forward = () => viewer.viewForward();

  return {
    d,
    editor,
    viewer,
    step,
    camera,
    sample,
    sampleStart,
    eye,
    forward,
    showDraft,
    strokeExtends,
    endsOnScalp,
  };
}

/** The tools, each built from the shared kit (toolKit). */
export function createTools(d: ToolDeps): ToolSet {
  const k = toolKit(d);
  const ponytail = ponytailTool(k);
  const scalpBrush = scalpBrushTool(k);
  const ties = Object.fromEntries(TIE_TOOL_KINDS.map((kind) => [kind, tieTool(k, kind)]));
  const byName = {
    stream: streamTool(k),
    dividing: dividingTool(k),
    ponytail,
    ...(ties as Record<PlainTieKind, Tool>),
    select: selectTool(k),
    scalp: scalpBrush,
  } satisfies Record<ToolName, Tool>;
  return { byName, ponytail, scalpBrush };
}

/** The ponytail tool: one stroke makes a ponytail; a cross-section and two profiles may shape
 *  it (S4.6). */
function ponytailTool(k: ToolKit): PonytailTool {
  const { d, editor, viewer, camera, sample, sampleStart, eye, forward, step, showDraft } = k;
  const tool = new PonytailTool({
    sample,
    sampleStart,
    eye,
    forward,
    step,
    showDraft,
    showGuides: (lines) => d.showGuides(lines),
    preview: (points) => {
      viewer.expectHair(points !== null);
      editor.setStroke(
        points && {
          points: snapToPlane(points, editor.session.symmetry ?? X_PLANE, forward()).points,
          viewpoint: camera(),
          kind: 'ponytail',
        },
      );
    },
    commitSpine: (drawn) => {
      const { points, snapped } = snapToPlane(drawn, editor.session.symmetry ?? X_PLANE, forward());
      const curve = STROKE_KINDS.ponytail.fromStroke(
        points,
        camera(),
        newCurveExtends(editor.session),
      );
      if (curve.circles.length === 0) {
        d.notify('A ponytail spine needs to run on past the band: nothing was created.');
        return null;
      }
      const made = editor.run({
        kind: 'addCurve',
        curve,
        what: snapped ? 'ponytail {id} (centred on the head)' : 'ponytail {id}',
        // a ponytail on the symmetry plane is its own mirror image
        mirror: d.mirror() && !snapped,
      });
      const c = editor.selectedCurve;
      return made && c?.type === 'ponytail' ? { id: c.id, spine: c.points } : null;
    },
    shape: (id, p) =>
      editor.run({
        kind: 'shapePonytail',
        id,
        crossSection: p.crossSection,
        profiles: p.profiles,
        circles: p.circles,
      }),
    nearSpine: (x, y, spine) => {
      const pts = spine.map((q) => viewer.worldToScreen(q)).filter((q) => q !== null);
      for (let i = 0; i + 1 < pts.length; i++) {
        const [a, b] = [pts[i], pts[i + 1]];
        const ab = { x: b.x - a.x, y: b.y - a.y };
        const l2 = ab.x ** 2 + ab.y ** 2;
        const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - a.x) * ab.x + (y - a.y) * ab.y) / l2)) : 0;
        if (Math.hypot(x - a.x - t * ab.x, y - a.y - t * ab.y) <= SHAPING_NEAR_PX) return true;
      }
      return false;
    },
    notify: d.notify,
    stageChanged: (stage) => d.ponytailStage(stage),
  });
  // an Undo (or any edit) that takes away the ponytail being shaped ends its shaping
  editor.listen((c) => {
    if (c.sessionChanged) tool.sessionChanged(c.session.curves);
  });
  return tool;
}

/** A shaping stroke (cross-section, profiles) starts within this many pixels of the spine. */
const SHAPING_NEAR_PX = 80;

/** The scalp brush: paints and erases scalp, its ring on the head. */
function scalpBrushTool(k: ToolKit): ScalpBrushTool {
  const { d, editor, viewer } = k;
  return new ScalpBrushTool({
    hit: (x, y) => {
      const ray = viewer.rayAt(x, y);
      const hit = d
        .head()
        .raycast(
          [ray.origin.x, ray.origin.y, ray.origin.z],
          [ray.direction.x, ray.direction.y, ray.direction.z],
        );
      return hit ? hit.point : null;
    },
    preview: (stroke) =>
      d.previewScalp(stroke, d.mirror() ? (editor.session.symmetry ?? X_PLANE) : null),
    commit: (stroke) =>
      editor.run({
        kind: 'paintScalp',
        stroke: { ...stroke, points: [...stroke.points] },
        mirror: d.mirror(),
      }),
    radiusChanged: (r) =>
      d.notify(`Scalp brush radius ${(r * 10).toFixed(1)} cm (wheel: 5 % a notch).`),
    ring: (at) => {
      if (!at) {
        viewer.setBrushRing(null);
        return;
      }
      const { normal } = d.head().closest(at.point);
      viewer.setBrushRing({ centre: at.point, normal, radius: at.radius, erase: at.erase });
    },
    notify: d.notify,
  });
}

/** The stream curve tool: strokes, hint strokes on the selected curve, previews. */
function streamTool(k: ToolKit): Tool {
  const { d, editor, viewer, step, camera, sample, sampleStart, eye, forward, showDraft } = k;
  const { strokeExtends, endsOnScalp } = k;
  // drawn from the side along the head's middle (with Mirror on, from any view), it is put on
  // the middle
  const onMiddle = (points: Vec3[]) =>
    streamOnMiddle(points, editor.session.symmetry ?? X_PLANE, forward(), d.head(), d.mirror());
  return new StreamCurveTool({
    sample,
    sampleStart,
    eye,
    forward,
    step,
    showDraft,
    toScreen: (p) => viewer.worldToScreen(p),
    hintTarget: () => {
      const c = editor.selectedCurve;
      const surface = c ? curveSurface(c, d.step) : null;
      if (!c || !surface) return null;
      // the view the curve's surface faces: from its viewpoint to its target
      const { position: p, target: t } = c.viewpoint;
      const len = Math.hypot(t[0] - p[0], t[1] - p[1], t[2] - p[2]);
      const viewDir: Vec3 | undefined =
        len > 1e-9 ? [(t[0] - p[0]) / len, (t[1] - p[1]) / len, (t[2] - p[2]) / len] : undefined;
      return { points: c.points, surface, viewDir };
    },
    deselect: () => editor.select(null),
    applyHint: (r) => {
      const c = editor.selectedCurve;
      if (!c) return;
      if (r.op.kind === 'none') {
        d.notify(`Hint: no operation (${r.op.reason}) — nothing changed.`);
        return;
      }
      editor.run({ kind: 'hintEdit', id: c.id, op: r.op.kind, points: r.points });
    },
    // the commit ends the stroke in progress in the same change (one solve follows)
    commit: (drawn) => {
      const { points, snapped } = onMiddle(drawn);
      const tie = tieAtEnd(editor.session.curves, points[points.length - 1]);
      const extend = strokeExtends(points);
      // with the shape rules the hair of a stroke that ends on the scalp is as long as the
      // stroke (docs/natural-fall.md): say so, with that length, so a user wanting long hair
      // knows to draw past the head
      let cm = 0;
      for (let i = 1; i < points.length; i++) cm += 10 * distance(points[i], points[i - 1]);
      const middle = snapped ? ", on the head's middle" : '';
      const why = tie
        ? `, on into ${tie.type} ${tie.id}`
        : extend && !newCurveExtends(editor.session)
          ? editor.session.shape
            ? combingOnNote(
                cm,
                10 * editor.session.growth.maxLength,
                editor.session.curves.some(
                  (c) =>
                    c.type === 'stream' &&
                    !(c.extend && endsOnScalp(c.points)) &&
                    !tieAtEnd(editor.session.curves, c.points[c.points.length - 1]),
                ),
              )
            : ', combing on: it ends on the scalp'
          : '';
      editor.run({
        kind: 'addCurve',
        curve: {
          type: 'stream',
          points,
          extend,
          viewpoint: camera(),
        },
        what: `stream curve {id} (${points.length - 1} segments${why}${middle})`,
        // a stroke on the symmetry plane is its own mirror image
        mirror: d.mirror() && !snapped,
      });
    },
    preview: (drawn) => {
      viewer.expectHair(drawn !== null);
      const points = drawn && onMiddle(drawn).points;
      editor.setStroke(points && { points, viewpoint: camera(), extend: strokeExtends(points) });
    },
    notify: d.notify,
  });
}

/** What the status says of a stroke that ends on the scalp (with the shape rules): its hair is
 *  about as long as the stroke, `cm`, or Max length (`maxCm`) when that is shorter (fresh eyes
 *  read "11 cm" for hair capped at 5). */
export function combingOnNote(cm: number, maxCm: number, othersEndHair = false): string {
  // a stroke that combs says nothing of the length beside strokes that end hair
  // (docs/natural-fall.md, length from the strokes around)
  if (othersEndHair)
    return ', combing on: it ends on the scalp; its hair takes its length from the strokes that end hair';
  return cm <= maxCm
    ? `, combing on: it ends on the scalp; its hair is about as long as the stroke, ${Math.round(cm)} cm (draw on past the head for longer hair)`
    : `, combing on: it ends on the scalp; its hair is ${Math.round(maxCm)} cm, Max length (the stroke is ${Math.round(cm)} cm: raise Max length in the Hair panel for longer hair)`;
}

/** The dividing curve tool: partings on the scalp and their tilt handles. */
function dividingTool(k: ToolKit): Tool {
  const { d, editor, step, camera, sample, sampleStart, showDraft, forward } = k;
  return new DividingCurveTool({
    sample,
    sampleStart,
    step,
    selected: () => {
      const c = editor.selectedCurve;
      return c?.type === 'dividing' ? c : null;
    },
    normalsAt: (pts) => pts.map((p) => d.head().normalAt(p)),
    showDraft,
    commit: (drawn, drawnNormals) => {
      // an end drawn up to the head's outline goes on over it (partingOverOutline.ts)
      const { points, carried } = partingOverOutline(drawn, forward(), d.head(), step());
      const normals = carried ? points.map((p) => d.head().normalAt(p)) : drawnNormals;
      editor.run({
        kind: 'addCurve',
        curve: {
          type: 'dividing',
          points,
          normals,
          ...defaultParams('dividing'),
          viewpoint: camera(),
        },
        what: `dividing curve {id} (${points.length - 1} segments${carried ? ', carried over the outline' : ''})`,
        mirror: d.mirror(),
      });
    },
    setTilt: (end, alpha, side) => {
      const c = editor.selectedCurve;
      if (c?.type === 'dividing') editor.run({ kind: 'setTilt', id: c.id, end, alpha, side });
    },
    notify: d.notify,
  });
}

/** The tool of a tie drawn as one stroke (tieTools.ts): a `spine` is drawn as a stream curve is
 *  (the depth rule past the scalp), without hint strokes, and previewed as the tie it will make;
 *  a `loop` is drawn on the head. Its stroke makes a new curve of its kind, extending as a new
 *  curve does. */
function tieTool(k: ToolKit, kind: PlainTieKind): Tool {
  const { d, editor, viewer, step, camera, sample, sampleStart, eye, forward, showDraft } = k;
  const spec = TIE_TOOLS[kind];
  // a spine drawn near the head's middle is put on it, as a ponytail's is (a centred braid)
  const onMiddle = (points: Vec3[]) =>
    spec.draw === 'spine'
      ? snapToPlane(points, editor.session.symmetry ?? X_PLANE, forward())
      : { points, snapped: false };
  const commit = (drawn: Vec3[]) => {
    const { points, snapped } = onMiddle(drawn);
    return editor.run({
      kind: 'addCurve',
      curve: STROKE_KINDS[kind].fromStroke(points, camera(), newCurveExtends(editor.session)),
      what: `${spec.what(points)}${snapped ? ', centred on the head' : ''}`,
      // a tie on the symmetry plane is its own mirror image
      mirror: d.mirror() && !snapped,
    });
  };
  if (spec.draw === 'loop')
    return new BunTool({ sample, step, showDraft, commit, notify: d.notify });
  return new StreamCurveTool({
    sample,
    sampleStart,
    eye,
    forward,
    step,
    showDraft,
    noun: `A ${spec.label.toLowerCase()}`,
    commit,
    preview: (points) => {
      viewer.expectHair(points !== null);
      editor.setStroke(points && { points: onMiddle(points).points, viewpoint: camera(), kind });
    },
    notify: d.notify,
  });
}

/** The select tool: picks a shown curve. */
function selectTool(k: ToolKit): Tool {
  const { d, editor, viewer } = k;
  return new SelectTool({
    // hidden curves (Curves display off) cannot be picked: a click says so rather than nothing
    curves: () => (d.curvesShown() ? editor.session.curves : []),
    toScreen: (p) => viewer.worldToScreen(p),
    select: (id, missedBy) => {
      if (id === null && !d.curvesShown() && editor.session.curves.length > 0)
        d.notify('The curves are hidden: tick Curves (key 1) to select one.');
      else if (id === null && missedBy !== undefined)
        // a click that missed says so (new users clicked beside a line and saw nothing happen)
        d.notify(
          `No curve under the click: the nearest line is ${Math.round(missedBy)} px away. Click on a curve's line to select it.`,
        );
      editor.select(id);
    },
  });
}
