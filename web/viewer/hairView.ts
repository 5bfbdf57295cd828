// The displayed hair: strand arrays from the solver become one object in the viewer, drawn at
// the active quality: 'fast' = GL lines with the lighting precomputed in the worker (transmittance
// and occlusion per point), blended order-independently (hairOit.ts); 'high' = camera-facing
// tapered strips with alpha-to-coverage (where the canvas is multisampled, else weighted blended
// order-independent transparency: hairOit.ts) and deep opacity maps for the key light's shadow.
// Hair that is not final (a stroke's previews) is drawn as Fast draws it in either quality; a
// motion moves the hair shown in its vertex shader (strandFollowing.ts). Materials are shared across revisions (a new material would compile its
// shader again). The head receives the hair's shadow (per-vertex transmittance,
// headMaterial.ts).
import * as THREE from 'three';
import type { GrowthParams } from '../model/growthParams';
import type { FollowerAttributes } from '../model/guideFollowers';
import type { HairLightingArrays, StrandArrays } from '../model/hairArrays';
import { type HairLook, rootColor } from '../model/hairLook';
import { DEFAULT_HAIR_COLOR } from '../model/session';
import { buildCardsObject } from './cardsView';
import { DeepOpacityMaps } from './deepOpacity';
import { readFollowedVertices } from './followerProbe';
import { WeightedBlendedHair } from './hairOit';
import { setHeadHairShadow, setHeadHairUnder } from './headMaterial';
import type { LineAttributes } from './strandAttributes';
import { attachFollowers, GuideTextures, thinForMotion, unbindFollowers } from './strandFollowing';
import { buildStrandGeometry, buildStrandStripGeometry } from './strandGeometry';
import { createStrandMaterial, type StrandMaterial, setHairLook } from './strandMaterial';
import { representedWidth } from './strandWidth';
import type { Viewer } from './viewer';

export type ActiveQuality = 'fast' | 'high';

export class HairView {
  private lines: StrandMaterial | null = null;
  private strips: StrandMaterial | null = null;
  private color = DEFAULT_HAIR_COLOR;
  /** The colour model (null: the direct colour). */
  private look: HairLook | null = null;
  private quality: ActiveQuality = 'fast';
  private current: {
    strands: StrandArrays;
    lighting: HairLightingArrays | null;
    attributes: LineAttributes | null;
    /** Converged hair (previews are drawn as strands also in the Cards view). */
    final: boolean;
  } | null = null;
  /** The Cards view: the hair drawn as the hair cards export cuts it (null: as strands). */
  private cards: { count: number; growth: GrowthParams } | null = null;
  /** What the Cards view shows now (null: strands are shown). */
  cardsShown: { cards: number; triangles: number; ms: number } | null = null;
  /** Called after each rebuild of the shown hair with what the Cards view shows (null: strands). */
  onCards: ((shown: { cards: number; triangles: number; ms: number } | null) => void) | null = null;
  private object: THREE.Mesh | THREE.LineSegments | null = null;
  private dom: DeepOpacityMaps | null = null;
  /** High's order-independent drawing of the strips (null: alpha-to-coverage or unsorted). */
  private oit: WeightedBlendedHair | null = null;
  /** The lines' (undefined: not made yet; null: unsorted, no half-float targets here). */
  private linesOit: WeightedBlendedHair | null | undefined;
  private domDirty = false;
  /** The motion the hair shown follows (null: none): its attributes, guide textures and the
   *  pose of the last frame (null before the first). */
  private following: {
    attrs: FollowerAttributes;
    textures: GuideTextures;
    pose: Float32Array | null;
    /** Every how many points each strand is drawn (1: all), and what puts the object back. */
    stride: number;
    restore: (() => void) | null;
  } | null = null;
  /** Lighting precompute time of the hair shown (ms, in the worker), null without one. */
  lightingMs: number | null = null;

  constructor(
    private readonly viewer: Viewer,
    private readonly head: THREE.Mesh | null = null,
  ) {
    viewer.onFrame(() => this.renderDeepOpacity());
    viewer.onBeforeCapture(() => this.renderDeepOpacity());
  }

  /** Replaces the hair on screen with `strands` (lit by `lighting` when given); `shown` runs
   *  once a frame has drawn it. `headShadow` (default true): the hair's shadow on the head is
   *  updated too; previews leave it as the last converged hair cast it, so the head (the frame
   *  cache's static layer) is not drawn again for every preview. `attributes`: the strands'
   *  vertex attributes as the worker built them with this lighting (strandAttributes.ts), so
   *  they are not built here again. */
  show(
    strands: StrandArrays,
    lighting: HairLightingArrays | null | undefined,
    shown?: () => void,
    headShadow = true,
    attributes: LineAttributes | null = null,
  ): void {
    this.current = { strands, lighting: lighting ?? null, attributes, final: headShadow };
    this.lightingMs = lighting ? lighting.ms : null;
    if (this.head && lighting && headShadow) setHeadHairShadow(this.head, lighting.head);
    this.colourScalp();
    const hair = this.build();
    if (shown) {
      const off = this.viewer.onHairShown((h) => {
        if (h !== hair) return;
        off();
        shown();
      });
    }
    this.viewer.setHair(hair);
  }

  /** Draws the hair shown riding a motion's guides (strandFollowing.ts): `attrs` bind its
   *  points to them (every `stride`-th point of each strand and its tip, strandSubsample.ts
   *  everyNthPoint: drawn through those only), frames come through followFrame. False (nothing done) when the hair shown is
   *  not strands of these points (cards, another groom): the caller draws the motion itself. From
   *  the first frame on, the hair is drawn whole in every frame while it follows
   *  (Viewer.drawWhole). */
  follow(
    binding: { guideCount: number; guidePoints: number },
    attrs: FollowerAttributes,
    stride: number,
  ): boolean {
    this.unfollow();
    const o = this.object;
    const c = this.current;
    if (!c || this.cardsShown || !o) return false;
    const restore = this.followWith(o, c.strands.strandStart, attrs, stride);
    if (restore === null) return false;
    this.following = {
      attrs,
      textures: new GuideTextures(binding.guideCount, binding.guidePoints),
      pose: null,
      stride,
      restore,
    };
    return true;
  }

  /** Makes `o` follow: its own geometry (stride 1) or one of every few points (thinForMotion);
   *  null when its vertices are not the points of `attrs`. */
  private followWith(
    o: THREE.Mesh | THREE.LineSegments,
    strandStart: Uint32Array,
    attrs: FollowerAttributes,
    stride: number,
  ): (() => void) | null {
    if (stride > 1) return thinForMotion(o, strandStart, attrs, stride);
    return attachFollowers(o, attrs) ? () => {} : null;
  }

  /** A frame of the motion followed: the guides now (3 * (guide * G + point) + axis) and the
   *  head's pose (pose[0..8] rotation row-major, pose[9..11] translation). */
  followFrame(guides: Float32Array, pose: Float32Array): void {
    const f = this.following;
    if (!f) return;
    f.textures.update(guides);
    if (!f.pose) this.viewer.drawWhole('motion', true);
    f.pose = pose;
    for (const m of [this.lines, this.strips]) if (m) f.textures.bind(m.uniforms, pose);
    this.viewer.requestRender();
  }

  /** Test probe: where the strand shader puts each vertex of the hair shown now (3 floats a
   *  vertex) and the strands' point each vertex is (lines: one vertex a point, strips two; while
   *  a motion draws every few points, those points only); null when not following or not
   *  readable. */
  readFollowed(): { placed: Float32Array; pointOf: Uint32Array } | null {
    const o = this.object;
    if (!this.following || !o || !(o.material instanceof THREE.ShaderMaterial)) return null;
    const g = o.geometry as THREE.BufferGeometry;
    const placed = readFollowedVertices(
      this.viewer.renderer,
      g,
      (o.material as StrandMaterial).uniforms,
    );
    if (!placed) return null;
    const per = o instanceof THREE.Mesh ? 2 : 1;
    const points = g.userData.motionPoints as Uint32Array | undefined;
    const pointOf = new Uint32Array(placed.length / 3);
    for (let v = 0; v < pointOf.length; v++) {
      const i = Math.floor(v / per);
      pointOf[v] = points ? points[i] : i;
    }
    return { placed, pointOf };
  }

  /** The hair drawn as groomed again (its geometry's positions were never changed). */
  unfollow(): void {
    const f = this.following;
    if (!f) return;
    this.following = null;
    f.restore?.();
    for (const m of [this.lines, this.strips]) if (m) unbindFollowers(m.uniforms);
    if (this.object) this.object.frustumCulled = true;
    f.textures.dispose();
    this.viewer.drawWhole('motion', false);
    this.viewer.requestRender();
  }

  /** The drawing path: rebuilds the shown hair when it changes. */
  setQuality(q: ActiveQuality): void {
    if (q === this.quality) return;
    this.quality = q;
    if (this.current) this.viewer.setHair(this.build());
    this.viewer.requestRender();
  }

  /** The Cards view on (the card count and the session's growth settings, whose seed the export
   *  uses) or off (null). */
  setCards(cards: { count: number; growth: GrowthParams } | null): void {
    const same =
      cards === this.cards ||
      (cards &&
        this.cards &&
        cards.count === this.cards.count &&
        cards.growth.seed === this.cards.growth.seed);
    if (same) return;
    this.cards = cards;
    if (this.current) this.viewer.setHair(this.build());
    this.viewer.requestRender();
  }

  get activeQuality(): ActiveQuality {
    return this.quality;
  }

  setColor(css: string): void {
    this.setLook(this.look, css);
  }

  /** The hair's colour model (hairLook.ts; null: the direct colour `css`, #rrggbb). */
  setLook(look: HairLook | null, css: string): void {
    // by value: a session edit that leaves the look as it was (a stroke) hands over a copy, and
    // the frame cache dropped here costs a whole frame before the stroke's hair can show
    if (css === this.color && sameLook(look, this.look)) return;
    this.color = css;
    this.look = look;
    for (const m of [this.lines, this.strips]) if (m) setHairLook(m, look, css);
    this.colourScalp();
    // the cards' colour is in their atlas
    if (this.cardsShown && this.current) this.viewer.setHair(this.build());
    this.viewer.invalidateFrameCache(); // a uniform: the cached hair layer cannot see it
  }

  /** The scalp's hairline band in the hair's root colour while there is hair to see (a strand
   *  longer than its root), its own tint on a bald head (the drawing tools' cue; a session
   *  with no curves grows each strand as its root alone). */
  private colourScalp(): void {
    if (!this.head) return;
    const start = this.current?.strands.strandStart;
    let seen = false;
    if (start)
      for (let s = 0; s + 1 < start.length && !seen; s++) seen = start[s + 1] - start[s] > 1;
    const under = seen ? rootColor(this.look, this.color) : null;
    if (setHeadHairUnder(this.head, under)) this.viewer.invalidateFrameCache();
  }

  private build(): THREE.Object3D {
    // while a motion plays the object shown goes back to its own geometry first (the viewer
    // disposes it with that geometry), and a new object for the same strands (Quality) follows
    // too; new hair stops the motion (MotionPlayer)
    const f = this.following;
    f?.restore?.();
    if (f) f.restore = null;
    const o = this.buildHair();
    this.onCards?.(this.cardsShown);
    const start = this.current?.strands.strandStart;
    const strands = o instanceof THREE.Mesh || o instanceof THREE.LineSegments;
    if (f && start && strands && !this.cardsShown)
      f.restore = this.followWith(o, start, f.attrs, f.stride);
    return o;
  }

  private buildHair(): THREE.Object3D {
    const c = this.current;
    if (!c) throw new Error('no hair to build');
    this.cardsShown = null;
    if (this.cards && c.final) {
      const made = buildCardsObject(
        c.strands,
        { hairColor: this.color, hairLook: this.look, growth: this.cards.growth },
        this.cards.count,
      );
      this.object = made.object;
      this.domDirty = false; // the deep opacity maps are the strips'
      this.dom?.bindReceivers(false);
      this.cardsShown = { cards: made.cards, triangles: made.triangles, ms: made.ms };
      return made.object;
    }
    const { points, strandStart } = c.strands;
    const light = c.lighting?.strand ?? null;
    // High draws the converged hair as strips; a stroke's previews and a motion's frames (drawn
    // many times a second, each soon replaced) are drawn as Fast draws them, lines of the same
    // width's coverage, so they cost in High what they cost in Fast and the deep opacity maps
    // are not rendered again for each (the head keeps the converged hair's shadow, as in Fast)
    if (this.quality === 'high' && c.final) {
      const geometry = buildStrandStripGeometry(points, strandStart, 0, light, c.attributes);
      this.strips ??= this.createStripMaterial();
      const mesh = new THREE.Mesh(geometry, this.strips);
      if (this.oit) mesh.userData.oit = this.oit; // drawn order-independently (drawLayers)
      this.object = mesh;
      this.domDirty = this.dom !== null;
      return mesh;
    }
    if (this.quality === 'fast') this.dom?.bindReceivers(false); // the head's per-vertex shadow
    const geometry = buildStrandGeometry(points, strandStart, 0, light, c.attributes);
    this.lines ??= createStrandMaterial({
      color: this.color,
      look: this.look,
      kind: 'lines',
    });
    if (this.linesOit === undefined)
      this.linesOit = WeightedBlendedHair.supported(this.viewer.renderer)
        ? new WeightedBlendedHair(this.lines)
        : null;
    const lines = new THREE.LineSegments(geometry, this.lines);
    // converged hair is drawn order-independently; a stroke's previews (each soon replaced) and
    // interactive samples (drawLayers) are blended unsorted, which keeps drawing as quick as
    // before thin strands
    if (this.linesOit && c.final) lines.userData.oit = this.linesOit;
    this.object = lines;
    return lines;
  }

  private createStripMaterial(): StrandMaterial {
    const r = this.viewer.renderer;
    const gl = r.getContext() as WebGL2RenderingContext;
    const msaa = Number(gl.getParameter(gl.SAMPLES)) > 1;
    const canDom = r.extensions.has('EXT_color_buffer_float');
    const m = createStrandMaterial({
      color: this.color,
      look: this.look,
      kind: 'strips',
      alphaToCoverage: msaa,
      deepOpacity: canDom,
    });
    if (canDom) {
      this.dom = new DeepOpacityMaps(this.viewer.software ? 512 : 1024);
      this.dom.bind(m);
    }
    // without multisampling: weighted blended order-independent transparency where the
    // renderer has half-float targets, else blended unsorted
    if (!msaa && WeightedBlendedHair.supported(r)) this.oit = new WeightedBlendedHair(m);
    return m;
  }

  /** Deep opacity maps for the shown strips, once per hair revision (the light is fixed). */
  private renderDeepOpacity(): void {
    if (!this.domDirty || !this.dom || !this.strips) return;
    this.domDirty = false;
    const hair = this.object;
    if (!(hair instanceof THREE.Mesh)) return;
    this.strips.uniforms.strandWidth.value = representedWidth(hair.geometry.userData.strands);
    this.dom.render(this.viewer.renderer, hair.geometry, this.strips, this.head);
    this.dom.refresh(this.strips);
    this.dom.bindReceivers(true);
    this.viewer.invalidateFrameCache(); // new maps and uniforms: the cached hair is stale
  }
}

/** Whether two looks are equal, field for field (null: the direct colour). */
function sameLook(a: HairLook | null, b: HairLook | null): boolean {
  if (a === b) return true;
  if (!a || !b) return false;
  const keys = Object.keys(a) as (keyof HairLook)[];
  return keys.length === Object.keys(b).length && keys.every((k) => a[k] === b[k]);
}
