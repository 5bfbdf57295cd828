// The frame cache's decisions (viewer/frameCache.ts): which cached layer a frame starts from and
// when a cached layer is stale. Expected values are worked out here, not read back from the code.
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import {
  drawableStamp,
  type FramePlan,
  OverlayWait,
  planFrame,
  sameLayer,
  viewKey,
} from '../../web/viewer/frameCache';

describe('planFrame', () => {
  it('draws everything when nothing is cached', () => {
    expect(planFrame('interactive', 1000, 100, false, null)).toEqual({
      source: 'none',
      count: 100,
      fullDetailNext: false,
    });
    expect(planFrame('full', 1000, 100, false, null)).toEqual({
      source: 'none',
      count: 1000,
      fullDetailNext: false,
    });
  });

  it('draws hair and overlays over the cached head when only the hair changed', () => {
    expect(planFrame('interactive', 1000, 100, true, null)).toEqual({
      source: 'static',
      count: 100,
      fullDetailNext: false,
    });
    // a settled view on a slow rasteriser: a sample now, every strand a frame later
    expect(planFrame('settled', 1000, 100, true, null)).toEqual({
      source: 'static',
      count: 100,
      fullDetailNext: true,
    });
  });

  it('draws only the overlays when the cached hair has the detail the frame wants', () => {
    // a stroke's draft moves while the preview hair stays
    expect(planFrame('interactive', 1000, 100, true, 100)).toEqual({
      source: 'hair',
      count: 100,
      fullDetailNext: false,
    });
    // the whole hair is cached: an overlay change while idle costs no hair, and no full frame
    // follows
    expect(planFrame('settled', 1000, 100, true, 1000)).toEqual({
      source: 'hair',
      count: 1000,
      fullDetailNext: false,
    });
    // more detail than an interactive frame would draw is free
    expect(planFrame('interactive', 1000, 100, true, 1000)).toEqual({
      source: 'hair',
      count: 1000,
      fullDetailNext: false,
    });
    // the settled view from the cached sample: every strand still to come
    expect(planFrame('settled', 1000, 100, true, 100)).toEqual({
      source: 'hair',
      count: 100,
      fullDetailNext: true,
    });
  });

  it('draws the hair again when the cached layer has less detail than wanted', () => {
    expect(planFrame('full', 1000, 100, true, 100)).toEqual({
      source: 'static',
      count: 1000,
      fullDetailNext: false,
    });
    expect(planFrame('interactive', 1000, 200, true, 100)).toEqual({
      source: 'static',
      count: 200,
      fullDetailNext: false,
    });
  });

  it('a bald head (no hair indices) is fully shown by any cached hair layer', () => {
    expect(planFrame('settled', 0, 0, true, 0)).toEqual({
      source: 'hair',
      count: 0,
      fullDetailNext: false,
    });
  });
});

describe('cache keys', () => {
  const camera = new THREE.PerspectiveCamera(35, 4 / 3, 0.05, 100);
  camera.position.set(2.6, 0.9, 7);
  camera.updateMatrixWorld();
  const key = () =>
    viewKey(camera.matrixWorld.elements, camera.projectionMatrix.elements, 1000, 750);

  it('the view key changes with the camera and the drawing-buffer size only', () => {
    const k0 = key();
    expect(key()).toBe(k0);
    expect(
      viewKey(camera.matrixWorld.elements, camera.projectionMatrix.elements, 500, 375),
    ).not.toBe(k0);
    camera.position.x += 1e-6; // the smallest orbit
    camera.updateMatrixWorld();
    expect(key()).not.toBe(k0);
    camera.position.x -= 1e-6;
    camera.updateMatrixWorld();
    camera.aspect = 1;
    camera.updateProjectionMatrix(); // a resize
    expect(key()).not.toBe(k0);
  });

  it('sameLayer needs both the view and the static part to match', () => {
    const a = { view: 'v', scene: 's' };
    expect(sameLayer(null, a)).toBe(false);
    expect(sameLayer({ view: 'v', scene: 's' }, a)).toBe(true);
    expect(sameLayer({ view: 'v2', scene: 's' }, a)).toBe(false);
    expect(sameLayer({ view: 'v', scene: 's2' }, a)).toBe(false);
  });

  it('the drawable stamp sees attribute and material updates, visibility and replacements', () => {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(9), 3));
    g.setAttribute('hairShadow', new THREE.BufferAttribute(new Float32Array(3), 1));
    const m = new THREE.MeshStandardMaterial();
    const head = new THREE.Mesh(g, m);
    const s0 = drawableStamp([head]);
    expect(drawableStamp([head])).toBe(s0);
    // the draw range is not part of it (the hair's is set every frame; its count is keyed apart)
    g.setDrawRange(0, 3);
    expect(drawableStamp([head])).toBe(s0);
    // the hair's shadow on the head: an attribute flagged for upload
    (g.getAttribute('hairShadow') as THREE.BufferAttribute).needsUpdate = true;
    const s1 = drawableStamp([head]);
    expect(s1).not.toBe(s0);
    m.needsUpdate = true;
    const s2 = drawableStamp([head]);
    expect(s2).not.toBe(s1);
    head.visible = false;
    expect(drawableStamp([head])).not.toBe(s2);
    head.visible = true;
    // another hair object (a new revision, another quality) in the same group
    const group = new THREE.Group();
    group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial()));
    const h0 = drawableStamp([group]);
    group.clear();
    group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial()));
    expect(drawableStamp([group])).not.toBe(h0);
  });
});

describe('OverlayWait', () => {
  const overlays: FramePlan = { source: 'hair', count: 100, fullDetailNext: false };
  const hair: FramePlan = { source: 'static', count: 100, fullDetailNext: false };

  it('holds overlay-only interactive frames for at most its time from the first expect', () => {
    const w = new OverlayWait(50);
    expect(w.waits(overlays, 'interactive', 0)).toBe(false); // nothing expected yet
    w.expect(100);
    expect(w.waits(overlays, 'interactive', 100)).toBe(true);
    // later expects within the wait do not extend it: the stroke line moves at least every 50 ms
    w.expect(120);
    w.expect(149);
    expect(w.waits(overlays, 'interactive', 149.9)).toBe(true);
    expect(w.waits(overlays, 'interactive', 150)).toBe(false);
    // the first expect after it ran out starts a new one
    w.expect(151);
    expect(w.waits(overlays, 'interactive', 200)).toBe(true);
    expect(w.waits(overlays, 'interactive', 201)).toBe(false);
  });

  it('never holds a frame that draws hair, a settled frame, or after cancel', () => {
    const w = new OverlayWait(50);
    w.expect(0);
    expect(w.waits(hair, 'interactive', 10)).toBe(false);
    expect(w.waits({ ...hair, source: 'none' }, 'interactive', 10)).toBe(false);
    expect(w.waits(overlays, 'settled', 10)).toBe(false);
    expect(w.waits(overlays, 'full', 10)).toBe(false);
    expect(w.waits(overlays, 'interactive', 10)).toBe(true);
    w.cancel();
    expect(w.waits(overlays, 'interactive', 10)).toBe(false);
  });
});
