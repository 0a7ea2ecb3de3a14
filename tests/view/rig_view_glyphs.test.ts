// The bone glyphs of web/src/view/rig_view.ts: along each bone's x axis by its length, except where
// a bone's one child sits off that axis (a URDF link: its x axis is its joint's axis and the next
// joint is elsewhere), where the glyph runs from the bone's head to the child's, so the arm is drawn
// connected. Checked on the test robots of tests/rig/urdf_samples.ts and on a straight chain.
import { Vector3 } from 'three';
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
    const spec = {
      parents: Int32Array.of(-1, 0),
      rest: Float64Array.of(
        1,
        0,
        0,
        0,
        0,
        1,
        0,
        0,
        0,
        0,
        1,
        0,
        0,
        0,
        0,
        1,
        1,
        0,
        0,
        2,
        0,
        1,
        0,
        0,
        0,
        0,
        1,
        0,
        0,
        0,
        0,
        1,
      ),
      lengths: Float64Array.of(2, 1),
      lower: new Float64Array(6),
      upper: new Float64Array(6),
      names: ['a', 'b'],
      effectors: Int32Array.of(1),
    } as unknown as RigSpec;
    const view = new RigView(spec, restPoses(spec));
    expect(view.glyphEnd(0, new Vector3()).toArray()).toEqual([2, 0, 0]);
    expect(view.glyphEnd(1, new Vector3()).toArray()).toEqual([3, 0, 0]);
    view.dispose();
  });
});
