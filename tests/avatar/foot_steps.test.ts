// The avatar's feet (web/src/avatar/foot_steps.ts): planted while the body stays over them, one
// step at a time when the hips move away or the head turns, lifted on an arc that never goes below
// the floor, and still between steps.
import { describe, expect, it } from 'vitest';

import { type FootPose, FootSteps } from '../../web/src/avatar/foot_steps.js';

const H = 1.8;
const identity = [0, 0, 0, 1];
const rest: FootPose[] = [
  { position: [0.1, 0.05, 0], orientation: identity },
  { position: [-0.1, 0.05, 0], orientation: identity },
];
const hips = [0, 1, 0];
const yaw = (degrees: number) => [0, Math.sin((degrees * Math.PI) / 360), 0, Math.cos((degrees * Math.PI) / 360)];

/**
 * Runs `frames` frames with the head's frame, the hips' tip and the head's tip (default: over the
 * hips) given per frame; the targets per frame.
 */
function run(
  frames: number,
  head: (f: number) => number[],
  at: (f: number) => number[],
  headAt = (f: number) => [at(f)[0], at(f)[1] + 0.5, at(f)[2]],
): FootPose[][] {
  const steps = new FootSteps(rest, hips, { position: [0, 1.5, 0], orientation: identity }, H);
  const tracked = (f: number) => ({ position: headAt(f), orientation: head(f) });
  return Array.from({ length: frames }, (_, f) =>
    steps.update(tracked(f), at(f)).map((p) => ({ position: [...p.position], orientation: [...p.orientation] })),
  );
}

/** Frames in which foot k's target moves. */
function moving(out: FootPose[][], k: number): number[] {
  const frames: number[] = [];
  for (let f = 1; f < out.length; f++)
    if (Math.hypot(...out[f][k].position.map((p, i) => p - out[f - 1][k].position[i])) > 1e-12) frames.push(f);
  return frames;
}

describe('the avatar feet', () => {
  it('stay where they stand while the body stays over them (a lean, a look aside)', () => {
    const out = run(
      120,
      (f) => yaw(45 * Math.sin(f / 20)),
      (f) => [0.1 * H * Math.sin(f / 15), 1, 0.05 * H],
    );
    expect(moving(out, 0)).toEqual([]);
    expect(moving(out, 1)).toEqual([]);
  });

  it('step, one at a time, when the head turns round: lifted, never below the floor, still between steps, turned with the head', () => {
    const out = run(
      240,
      (f) => yaw(Math.min(180, 1.5 * f)),
      () => hips,
    );
    const left = moving(out, 0),
      right = moving(out, 1);
    expect(left.length).toBeGreaterThan(0);
    expect(right.length).toBeGreaterThan(0);
    expect(left.filter((f) => right.includes(f))).toEqual([]); // never both feet in the air
    for (const frame of out) for (const foot of frame) expect(foot.position[1]).toBeGreaterThanOrEqual(0.05 - 1e-12);
    expect(Math.max(...out.map((frame) => frame[0].position[1]))).toBeGreaterThan(0.05 + 0.02 * H); // lifted
    // At the end both feet face within the turn that starts a step of the head (180 degrees).
    const facing = (q: number[]) => (2 * Math.atan2(q[1], q[3]) * 180) / Math.PI;
    for (const foot of out[out.length - 1]) expect(Math.abs(Math.abs(facing(foot.orientation)) - 180)).toBeLessThan(60);
  });

  it('stay where they stand in a crouch that sits the hips back while the head stays over the feet', () => {
    // The hips 0.2 of the height back and a quarter down, the head lowered above the feet: by the
    // hips alone (beyond 0.15 of the height from the feet) both feet stepped back.
    const out = run(
      90,
      () => identity,
      (f) => [0, 1 - 0.25 * H * Math.min(1, f / 60), -0.2 * H * Math.min(1, f / 60)],
      (f) => [0, 1.5 - 0.25 * H * Math.min(1, f / 60), 0.02 * H * Math.min(1, f / 60)],
    );
    expect(moving(out, 0)).toEqual([]);
    expect(moving(out, 1)).toEqual([]);
  });

  it('step towards the hips when they move away from the feet', () => {
    const out = run(
      90,
      () => identity,
      (f) => [Math.min(0.3 * H, 0.01 * H * f), 1, 0],
    );
    const last = out[out.length - 1];
    expect(last[0].position[0]).toBeGreaterThan(rest[0].position[0] + 0.1 * H);
    expect(last[1].position[0]).toBeGreaterThan(rest[1].position[0] + 0.1 * H);
  });
});
