// The bone glyphs of web/src/view/rig_view.ts: along each bone's x axis by its length, except where
// a bone's one child sits off that axis (a URDF link: its x axis is its joint's axis and the next
// joint is elsewhere), where the glyph runs from the bone's head to the child's, so the arm is drawn
// connected. Checked on the test robots of tests/rig/urdf_samples.ts and on a straight chain.
import { Matrix4, Raycaster, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { RigView } from '../../web/src/view/rig_view.js';
import { arm2, arm4, urdfText } from '../rig/urdf_samples.js';

/** Identity poses (the rest pose), 16 row-major numbers per bone. */
const restPoses = (spec: RigSpec): Float64Array => {
  const out = new Float64Array(16 * spec.parents.length);
  for (let i = 0; i < spec.parents.length; i++) for (const k of [0, 5, 10, 15]) out[16 * i + k] = 1;
  return out;
};

/** Two bones along x, 2 and 1 long, the second at the first's tip. */
const twoBones = {
  parents: Int32Array.of(-1, 0),
  rest: Float64Array.from([
    ...new Matrix4().identity().transpose().elements,
    ...new Matrix4().makeTranslation(2, 0, 0).transpose().elements,
  ]),
  lengths: Float64Array.of(2, 1),
  lower: new Float64Array(6),
  upper: new Float64Array(6),
  names: ['a', 'b'],
  effectors: Int32Array.of(1),
} as unknown as RigSpec;

describe('bone glyphs', () => {
  it.each([arm2, arm4])('join each URDF joint to the next one ($label)', async (robot) => {
    const rig = await loadRig(new TextEncoder().encode(urdfText(robot.joints)), 'arm.urdf', undefined, {
      chain: robot.chain,
    });
    const spec = rig.spec,
      view = new RigView(spec, restPoses(spec));
    const end = new Vector3(),
      head = new Vector3(),
      tip = new Vector3();
    let offAxis = 0;
    for (let i = 0; i + 1 < spec.parents.length; i++) {
      expect(spec.parents[i + 1]).toBe(i); // a serial chain
      view.glyphEnd(i, end);
      view.boneBase(i + 1, head);
      expect(end.distanceTo(head)).toBeLessThan(1e-6); // instance matrices are float32
      if (view.boneTip(i, tip).distanceTo(head) > 1e-6) offAxis++; // drawn along x, it would have missed
    }
    expect(offAxis).toBeGreaterThan(0);
    view.dispose();
  });

  it('keep a bone whose child sits at its tip along its x axis', () => {
    const spec = twoBones;
    const view = new RigView(spec, restPoses(spec));
    expect(view.glyphEnd(0, new Vector3()).toArray()).toEqual([2, 0, 0]);
    expect(view.glyphEnd(1, new Vector3()).toArray()).toEqual([3, 0, 0]);
    view.dispose();
  });
});

describe('picking a bone', () => {
  const spec = twoBones; // its size (its diagonal) is 3
  const rayAt = (origin: [number, number, number], direction: [number, number, number]): Raycaster => {
    const r = new Raycaster();
    r.ray.set(new Vector3(...origin), new Vector3(...direction).normalize());
    return r;
  };

  it('takes the glyph the ray hits, else a bone whose axis it passes within 6 pixels', () => {
    const view = new RigView(spec, restPoses(spec));
    view.update(restPoses(spec), spec.effectors, null);
    // A pixel 0.001 wide at unit distance: 6 pixels are 0.03 at the rays' distance of 5.
    const pixel = 0.001;
    // Across bone 0's middle, through its glyph.
    expect(view.pick(rayAt([1, 5, 0], [0, -1, 0]), pixel)).toBe(0);
    // Along the x axis from beyond the tip, end-on: bone 1 is the nearer.
    expect(view.pick(rayAt([6, 0.02, 0], [-1, 0, 0]), pixel)).toBe(1);
    // Near bone 0's head, 0.02 off its axis (4 pixels): its glyph is 0.01 wide there (it widens to
    // 0.075 at 0.18 of its length), so only the tolerance picks it, and only when given.
    expect(view.pick(rayAt([0.05, 5, 0.02], [0, -1, 0]), pixel)).toBe(0);
    expect(view.pick(rayAt([0.05, 5, 0.02], [0, -1, 0]))).toBeNull();
    // 0.04 off (8 pixels): nothing; 0.3 off: nothing.
    expect(view.pick(rayAt([0.05, 5, 0.04], [0, -1, 0]), pixel)).toBeNull();
    expect(view.pick(rayAt([1, 5, 0.3], [0, -1, 0]), pixel)).toBeNull();
    view.dispose();
  });
});
