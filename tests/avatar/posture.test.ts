// The avatar's posture (web/src/avatar/posture.ts): each frame's preferred move on the project's
// character, and what it buys.
// - From a wound pose (the hips turned 20 degrees, the spine twisted the other way, the hips forward
//   of the feet) the move turns the hips back, untwists the spine and moves the hips back, by a
//   share of each; with the hips tracked, or a foot stepping, it leaves the hips alone.
// - In a crouch it bends straight knees the way they bend, at most 3 degrees a frame, and never
//   straightens a knee that bends more than a squat's.
// - The stress clip with a tracker's noise (bench --experiment track --noise 0.001): without the
//   posture 5 seeds of 6 lost 7-10% of the frames in its leaning crouch, a foot sliding up to 35% of
//   the height; with it every frame of seeds 1-6 is on target and no foot slides.
import { describe, expect, it } from 'vitest';

import { runTrack } from '../../bench-node/track.js';
import { Posture } from '../../web/src/avatar/posture.js';
import { useCharacterAvatar } from '../helpers/character_rig.js';
import type { HumanoidMap } from '../../web/src/rig/humanoid/humanoid_roles.js';

const c = useCharacterAvatar();

/** The avatar's whole floating rig (effectors: head, hands, feet, hips) at rest, its Posture, and its feet where they stand. */
function restPosture() {
  const rest = new Float64Array(c.avatar.rig.numAngles);
  const posture = new Posture(c.avatar.rig, c.rig.humanoid, rest);
  const tips = c.avatar.rig.tips(rest);
  const feet = [3, 4].map((k) => ({ position: tips.subarray(3 * k, 3 * k + 3) }));
  return { rest, posture, feet, rotations: c.avatar.rig.tipRotations(rest) };
}

const bone = (humanoid: HumanoidMap, role: 'hips' | 'spine' | 'chest' | 'leftLowerLeg' | 'rightLowerLeg') =>
  humanoid.bones[role]!;

describe("the avatar's posture", () => {
  it('turns wound hips back to the feet, untwists the spine and moves the hips back over the feet', () => {
    const { rest, posture, feet, rotations } = restPosture();
    const h = c.rig.humanoid,
      hips = bone(h, 'hips'),
      spine = bone(h, 'spine'),
      chest = bone(h, 'chest');
    const wound = rest.slice();
    wound[3 * hips] = -20;
    wound[3 * spine] = wound[3 * spine + 2] = 6;
    wound[3 * chest] = wound[3 * chest + 2] = 4;
    const root = wound.length - 3;
    wound[root + 2] = 0.05 * c.avatar.height; // the hips 5% of the height forward
    const move = posture.move(wound, feet, rotations, false);
    expect(move[3 * hips]).toBeCloseTo(0.05 * 20, 1); // HIPS_FACING of the turn
    expect(move[3 * spine]).toBeCloseTo(-0.02 * 6, 6); // SPINE_UNWIND of the twist a0 + a2 = 12, half on each
    expect(move[3 * spine + 2]).toBeCloseTo(-0.02 * 6, 6);
    expect(move[3 * chest]).toBeCloseTo(-0.02 * 4, 6);
    expect(move[root + 2]).toBeCloseTo(-0.1 * 0.05 * c.avatar.height, 6); // HIPS_OVER_FEET of the offset
    expect(Math.abs(move[root])).toBeLessThan(1e-9);
    // At rest nothing moves.
    expect(Array.from(posture.move(rest, feet, rotations, false)).every((x) => Math.abs(x) < 1e-9)).toBe(true);
    // Hips tracked, or a foot stepping: the hips are left to their goal; the spine still untwists.
    for (const [tracked, stepping] of [
      [true, false],
      [false, true],
    ]) {
      const m = posture.move(wound, stepping ? [feet[0], null] : feet, rotations, tracked);
      expect([m[3 * hips], m[root], m[root + 2]]).toEqual([0, 0, 0]);
      expect(m[3 * spine]).toBeCloseTo(-0.12, 6);
    }
  });

  it('bends straight knees in a crouch the way they bend, 3 degrees a frame at most, and never straightens one', () => {
    const { rest, posture, feet, rotations } = restPosture();
    const knees = [bone(c.rig.humanoid, 'leftLowerLeg'), bone(c.rig.humanoid, 'rightLowerLeg')];
    const spec = c.avatar.rig.spec;
    const drop = 0.1 * c.avatar.height;
    const move = posture.move(rest, feet, rotations, false, drop);
    for (const k of knees) {
      // The way the knee's limits let it bend (its a1's larger side), by the cap.
      const way = spec.upper[3 * k + 1] >= -spec.lower[3 * k + 1] ? 1 : -1;
      expect(move[3 * k + 1]).toBe(3 * way);
    }
    // Standing (no drop): nothing. Bent past a squat's bend for that drop: nothing either.
    expect(knees.map((k) => posture.move(rest, feet, rotations, false, 0)[3 * k + 1])).toEqual([0, 0]);
    const bent = rest.slice();
    for (const k of knees) bent[3 * k + 1] = spec.upper[3 * k + 1] >= -spec.lower[3 * k + 1] ? 120 : -120;
    expect(knees.map((k) => posture.move(bent, feet, rotations, false, drop)[3 * k + 1])).toEqual([0, 0]);
  });

  it("keeps the stress clip's leaning crouch on target under a tracker's noise, on every seed", async () => {
    const seeds = [1, 2, 3, 4, 5, 6];
    const rows = [];
    for (const seed of seeds)
      rows.push(...(await runTrack(c.ik, c.rig, ['stress'], { points: 3, noise: 0.001, seed })));
    console.log(
      `[posture] stress clip, noise 0.001, seeds ${seeds.join(', ')}: success ${rows.map((r) => (100 * r.success_rate).toFixed(1)).join(', ')}%; ` +
        `largest foot slide ${(100 * Math.max(...rows.map((r) => r.foot_slide))).toFixed(2)}% of the height`,
    );
    for (const row of rows) {
      expect(row.success_rate).toBe(1);
      expect(row.foot_slide).toBeLessThan(0.01);
      expect(row.flips).toBe(0);
    }
  });
});
