// The viewer's overlay depth rule and colours (overlayStyle.ts) and its frame-detail choice
// (viewer.ts frameDetail). Expected values are worked out here, not read back from the code.
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { BoundingVolumeView } from '../../web/viewer/boundingVolume';
import { ConstraintPointsView } from '../../web/viewer/constraintPoints';
import { FieldGlyphsView } from '../../web/viewer/fieldGlyphs';
import {
  biasTowardsEye,
  curveRgb,
  DEPTH_BIAS_GLSL,
  HIDDEN_OPACITY,
  OVERLAY_DEPTH_BIAS,
  OVERLAY_ORDER,
  OVERLAY_RGB,
  overlayLineMaterial,
  overlayPolyline,
  SELECTED_HIDDEN_OPACITY,
  setOverlayGeometry,
} from '../../web/viewer/overlayStyle';
import { frameDetail } from '../../web/viewer/viewer';

const rgb01 = (hex: number) => [(hex >> 16) / 255, ((hex >> 8) & 255) / 255, (hex & 255) / 255];
const distance = (a: number, b: number) => {
  const x = rgb01(a);
  const y = rgb01(b);
  return Math.hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
};

describe('overlay colours', () => {
  it('gives each curve kind its own, clearly different colour', () => {
    const all = Object.values(OVERLAY_RGB);
    expect(new Set(all).size).toBe(6);
    for (let i = 0; i < all.length; i++)
      for (let j = i + 1; j < all.length; j++)
        expect(distance(all[i], all[j]), `${all[i]} vs ${all[j]}`).toBeGreaterThan(0.25);
  });

  it('stands out from the background, skin and default hair', () => {
    for (const c of Object.values(OVERLAY_RGB)) {
      expect(distance(c, 0xe9edf2)).toBeGreaterThan(0.3); // background
      expect(distance(c, 0xe2b59c)).toBeGreaterThan(0.25); // skin
      expect(distance(c, 0x5a3825)).toBeGreaterThan(0.3); // hair
    }
  });

  it('colours session curves by type, the selected one by selection', () => {
    expect(curveRgb('stream', false)).toBe(OVERLAY_RGB.stream);
    expect(curveRgb('dividing', false)).toBe(OVERLAY_RGB.dividing);
    expect(curveRgb('ponytail', false)).toBe(OVERLAY_RGB.ponytail);
    expect(curveRgb(undefined, false)).toBe(OVERLAY_RGB.stream);
    for (const t of ['stream', 'dividing', 'ponytail'])
      expect(curveRgb(t, true)).toBe(OVERLAY_RGB.selected);
  });
});

describe('overlay depth rule', () => {
  it('draws the hidden pass faint where something is in front, the visible pass in full', () => {
    const hidden = overlayLineMaterial(0x123456, 'hidden');
    const visible = overlayLineMaterial(0x123456, 'visible');
    expect([hidden.depthTest, hidden.depthWrite, hidden.transparent]).toEqual([true, false, true]);
    expect([visible.depthTest, visible.depthWrite, visible.transparent]).toEqual([
      true,
      false,
      true,
    ]);
    expect(hidden.depthFunc).toBe(THREE.GreaterDepth);
    expect(visible.depthFunc).toBe(THREE.LessEqualDepth);
    expect(hidden.opacity).toBe(HIDDEN_OPACITY);
    expect(HIDDEN_OPACITY).toBeGreaterThan(0.1);
    expect(HIDDEN_OPACITY).toBeLessThan(0.5);
    expect(visible.opacity).toBe(1);
    // shared, never rebuilt (a new material would compile its shader again)
    expect(overlayLineMaterial(0x123456, 'hidden')).toBe(hidden);
    expect(overlayLineMaterial(0x123456, 'hidden', SELECTED_HIDDEN_OPACITY).opacity).toBe(
      SELECTED_HIDDEN_OPACITY,
    );
  });

  it('a polyline is its visible pass with a hidden-pass twin sharing its geometry, drawn first', () => {
    const line = overlayPolyline(
      [
        [0, 0, 0],
        [1, 2, 3],
      ],
      OVERLAY_RGB.dividing,
    );
    expect(line.children).toHaveLength(1);
    const twin = line.children[0] as THREE.Line;
    expect(twin.geometry).toBe(line.geometry);
    expect(twin.renderOrder).toBeLessThan(line.renderOrder);
    expect((twin.material as THREE.Material).depthFunc).toBe(THREE.GreaterDepth);
    expect(Array.from(line.geometry.getAttribute('position').array)).toEqual([0, 0, 0, 1, 2, 3]);
    expect(OVERLAY_ORDER.hidden).toBeLessThan(OVERLAY_ORDER.visible);
    expect(OVERLAY_ORDER.visible).toBeLessThan(OVERLAY_ORDER.selected);
    // new geometry reaches the twin too, and the old one is freed
    const old = line.geometry;
    let freed = false;
    old.addEventListener('dispose', () => {
      freed = true;
    });
    const g = new THREE.BufferGeometry();
    setOverlayGeometry(line, g);
    expect([line.geometry, twin.geometry, freed]).toEqual([g, g, true]);
  });

  it('applies to constraint glyphs, field glyphs and the box', () => {
    const c = new ConstraintPointsView();
    const f = new FieldGlyphsView();
    const b = new BoundingVolumeView({ dims: [2, 2, 2], origin: [0, 0, 0], step: 1 });
    const drawables: THREE.Object3D[] = [];
    for (const o of [c.object, f.object, b.object])
      o.traverse((x) => {
        if ((x as THREE.Line).isLine || (x as THREE.Points).isPoints) drawables.push(x);
      });
    const funcs = drawables.map((x) => ((x as THREE.Line).material as THREE.Material).depthFunc);
    expect(funcs.filter((d) => d === THREE.GreaterDepth)).toHaveLength(4);
    expect(funcs.filter((d) => d === THREE.LessEqualDepth)).toHaveLength(4);
    for (const x of drawables)
      expect(((x as THREE.Line).material as THREE.Material).depthTest).toBe(true);
    // the box's hidden twin follows its geometry
    expect((b.object.children[0] as THREE.LineSegments).geometry).toBe(b.object.geometry);
  });

  it('injects the eye-ward bias after the projection, with its uniform', () => {
    const m = overlayLineMaterial(0x654321, 'visible');
    const shader = {
      uniforms: {} as Record<string, THREE.IUniform>,
      vertexShader: 'void main() {\n#include <project_vertex>\n}',
      fragmentShader: '',
    };
    m.onBeforeCompile(shader as unknown as THREE.WebGLProgramParametersWithUniforms, {} as never);
    expect(shader.uniforms.overlayDepthBias).toBe(OVERLAY_DEPTH_BIAS);
    expect(shader.vertexShader.startsWith('uniform float overlayDepthBias;')).toBe(true);
    expect(shader.vertexShader).toContain(`#include <project_vertex>${DEPTH_BIAS_GLSL}`);
  });

  it('moves a point towards the eye without moving it on screen', () => {
    const cam = new THREE.PerspectiveCamera(35, 1.6, 0.05, 100);
    const project = (v: number[]) => new THREE.Vector3(...v).applyMatrix4(cam.projectionMatrix);
    for (const v of [
      [0.3, -0.2, -7],
      [-1.1, 0.8, -5.5],
      [0, 0, -2],
    ] as [number, number, number][]) {
      const b = biasTowardsEye(v, 0.02);
      expect(Math.hypot(...v) - Math.hypot(...b)).toBeCloseTo(0.02, 9);
      const p = project(v);
      const q = project(b);
      expect(q.x).toBeCloseTo(p.x, 9);
      expect(q.y).toBeCloseTo(p.y, 9);
      expect(q.z).toBeLessThan(p.z); // nearer: wins the depth test against the scalp under it
    }
    expect(biasTowardsEye([0, 0, -0.01], 0.02)).toEqual([0, 0, -0]);
  });
});

describe('frame detail', () => {
  it('draws interactive frames at interactive detail', () => {
    expect(frameDetail('interactive', 1000, 100)).toEqual({ count: 100, fullDetailNext: false });
  });
  it('draws a settled view whole when that is affordable', () => {
    expect(frameDetail('settled', 1000, 1000)).toEqual({ count: 1000, fullDetailNext: false });
    expect(frameDetail('settled', 0, 0)).toEqual({ count: 0, fullDetailNext: false });
  });
  it('draws an expensive settled view at interactive detail first, then whole', () => {
    expect(frameDetail('settled', 1000, 100)).toEqual({ count: 100, fullDetailNext: true });
    expect(frameDetail('full', 1000, 100)).toEqual({ count: 1000, fullDetailNext: false });
  });
});
