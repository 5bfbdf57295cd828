// What the view shows besides head and hair: the style curves, the construction guides (the
// ponytail being built, or the selected ponytail's circles) and the display overlays of method
// S6.2 (constraints, field, supporting surface, box). Which show is view state (the view store,
// viewState.ts), not in the undo history or the session. Each overlay is rebuilt only when what
// it draws changes.

import { curveSurface } from '../editor/curveSurface';
import type { Editor } from '../editor/editor';
import type { GridSpec } from '../model/hairArrays';
import { defOf } from '../model/kinds';
import { normalize, type Vec3 } from '../model/vec3';
import type { SolveResult } from '../solver/solverClient';
import type { DisplayState } from '../ui/displayToggles';
import { BoundingVolumeView } from '../viewer/boundingVolume';
import { ConstraintPointsView } from '../viewer/constraintPoints';
import { FieldGlyphsView } from '../viewer/fieldGlyphs';
import { SupportingSurfaceView } from '../viewer/supportingSurfaceView';
import type { Viewer } from '../viewer/viewer';
import type { ViewStore } from './viewState';

export class OverlayPresenter {
  /** Construction lines of the ponytail being built (empty: none). */
  private toolGuides: Vec3[][] = [];
  /** Guide lines drawn now (test API displayInfo). */
  private guidesShown = 0;
  /** The result whose constraints / field the overlays draw. */
  private shown: SolveResult | null = null;
  private readonly views = {
    constraints: new ConstraintPointsView(),
    field: new FieldGlyphsView(),
    surface: new SupportingSurfaceView(),
    box: null as BoundingVolumeView | null,
  };
  /** What each overlay was last built from. */
  private readonly drawn = {
    constraints: null as unknown,
    field: null as unknown,
    surface: null as unknown,
  };

  constructor(
    private readonly viewer: Viewer,
    private readonly editor: Editor,
    private readonly view: ViewStore,
    private grid: GridSpec,
  ) {
    this.views.box = new BoundingVolumeView(grid);
    editor.listen((c) => {
      if (c.sessionChanged || c.selectionChanged) this.syncCurves();
    });
    view.listen((c) => {
      if (c.state.display !== c.previous.display) this.update();
    });
  }

  /** Which overlays show (the view store's). */
  get display(): Readonly<DisplayState> {
    return this.view.state.display;
  }

  /** The bounding volume moved (gridForSession): the box and later results use the new grid. */
  setGrid(grid: GridSpec): void {
    this.grid = grid;
    this.views.box?.update(grid);
  }

  get shownResult(): SolveResult | null {
    return this.shown;
  }

  result(r: SolveResult): void {
    this.shown = r;
    this.update();
  }

  setToolGuides(lines: readonly (readonly Vec3[])[]): void {
    this.toolGuides = lines.map((l) => l.slice());
    this.syncGuides();
  }

  /** What the overlays draw now (test API). */
  info(): { constraints: number; glyphs: number; surfaceTriangles: number; guides: number } {
    const v = this.views;
    const d = this.display;
    return {
      constraints: d.constraints ? v.constraints.count : 0,
      glyphs: d.field ? v.field.count : 0,
      surfaceTriangles: d.surface ? v.surface.triangles : 0,
      guides: this.guidesShown,
    };
  }

  syncCurves(): void {
    this.viewer.setCurves(this.editor.session.curves, this.editor.selectedId);
    this.syncGuides();
    this.update(); // the selected curve's surface follows edits and selection
  }

  private syncGuides(): void {
    // guides (a ponytail tool's spine and strokes, a selected ponytail's circles) are part of
    // the curves: hidden with them (key 1), for clean pictures (fresh eyes: the tool's spine
    // stayed on the tail with the curves hidden)
    let lines: Vec3[][] = [];
    if (this.toolGuides.length > 0) {
      if (this.display.curves) lines = this.toolGuides;
    } else {
      const c = this.display.curves ? this.editor.selectedCurve : null;
      lines = c ? (defOf(c).guides?.(c) ?? []).map(circlePolyline) : [];
    }
    this.guidesShown = lines.length;
    this.viewer.setGuides(lines);
  }

  /** Rebuilds what changed of the shown overlays and adds / removes them from the view. */
  private update(): void {
    const d = this.display;
    const v = this.views;
    const drawn = this.drawn;
    const r = this.shown;
    if (this.viewer.setCurvesVisible(d.curves)) this.syncGuides();
    let rebuilt = false;

    const constraints = d.constraints ? (r?.constraints ?? null) : null;
    if (drawn.constraints !== constraints) {
      drawn.constraints = constraints;
      v.constraints.update(constraints, this.grid);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.constraints.object, d.constraints);

    const field = d.field ? (r?.field?.vectors ?? null) : null;
    if (drawn.field !== field) {
      drawn.field = field;
      v.field.update(field, this.grid);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.field.object, d.field);

    // the surface hint strokes are lifted onto (cached per curve object, so per mode too)
    const curve = d.surface ? this.editor.selectedCurve : null;
    const surface = curve ? curveSurface(curve, this.grid.step) : null;
    if (drawn.surface !== surface) {
      drawn.surface = surface;
      v.surface.update(surface);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.surface.object, d.surface);

    if (v.box) this.viewer.showDisplay(v.box.object, d.box);
    if (rebuilt) this.viewer.requestRender();
  }
}

/** A circle as a closed polyline (48 segments), for display. */
export function circlePolyline(c: { centre: Vec3; axis: Vec3; radius: number }): Vec3[] {
  const a = normalize(c.axis);
  const ref: Vec3 = Math.abs(a[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const u = normalize([
    a[1] * ref[2] - a[2] * ref[1],
    a[2] * ref[0] - a[0] * ref[2],
    a[0] * ref[1] - a[1] * ref[0],
  ]);
  const v: Vec3 = [a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]];
  const out: Vec3[] = [];
  for (let i = 0; i <= 48; i++) {
    const t = (2 * Math.PI * i) / 48;
    const cs = Math.cos(t) * c.radius;
    const sn = Math.sin(t) * c.radius;
    out.push([
      c.centre[0] + cs * u[0] + sn * v[0],
      c.centre[1] + cs * u[1] + sn * v[1],
      c.centre[2] + cs * u[2] + sn * v[2],
    ]);
  }
  return out;
}
