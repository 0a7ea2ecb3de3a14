// Which effectors keep their frame while another is dragged (pinned_frames.ts): those whose own
// chain below the bones it shares with the dragged one has at least 6 angles of 30 degrees or
// more. On the character the hands keep theirs while the head bows, and the head while a hand
// moves, but a foot (a leg of 5 such angles) keeps only its place; on the hand no finger keeps
// its frame while another finger turns the wrist.
import { resolve } from 'node:path';

import { describe, expect, it } from 'vitest';

import { framesKept } from '../../web/src/live/pinned_frames.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';

async function kept(name: string, dragged: RegExp): Promise<Record<string, number>> {
  const { spec } = await loadRigFromPath(resolve(import.meta.dirname, `../../web/public/models/${name}.glb`));
  const d = Array.from(spec.effectors).findIndex((b) => dragged.test(spec.names[b]));
  expect(d).toBeGreaterThanOrEqual(0);
  const keep = framesKept(spec, spec.effectors, d);
  return Object.fromEntries(Array.from(spec.effectors, (b, k) => [spec.names[b].replace('mixamorig:', ''), keep[k]]));
}

describe('effectors whose chains can keep their frames', () => {
  it('character: the head bowed, the hands keep their frames, the feet their places only', async () => {
    expect(await kept('character', /Head$/)).toEqual({ Head: 0, LeftHand: 1, RightHand: 1, LeftFoot: 0, RightFoot: 0 });
    expect(await kept('character', /LeftHand$/)).toEqual({
      Head: 1,
      LeftHand: 0,
      RightHand: 1,
      LeftFoot: 0,
      RightFoot: 0,
    });
  });

  it('hand: a finger dragged turns the wrist, and no other fingertip keeps its frame', async () => {
    const keep = await kept('hand', /^index/);
    expect(Object.values(keep).every((k) => k === 0)).toBe(true);
  });

  it('knight: every other effector keeps its frame', async () => {
    expect(Object.values(await kept('knight', /^head$/))).toEqual([0, 1, 1, 1, 1]);
  });
});
