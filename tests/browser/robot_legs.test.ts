// A robot with legs posed as a character: a stylised robot built like three.js's RobotExpressive
// (tests/helpers/robot_glb.ts: legs off the body, FootL/FootR Blender IK controls hanging off the
// root bone, each carrying its foot's mesh as in the real file), opened through the file input.
// The default leg effectors are the ends of the leg chains (LowerLegL, LowerLegR), not the
// controls, and the importer's message says so. The left leg's target dragged up 15% of the
// height with the mouse (the gizmo's up arrow): the leg's end reaches it within δ (the page's
// "on target within"), the foot's mesh comes up with it, held where it was relative to the leg's
// end (web/src/rig/humanoid/control_follow.ts), while the right foot, its mesh, the head and the hands stay
// where they were within δ and the right foot turns by less than 3°. Writes
// test-results/robot-leg-lift.png (the lifted leg, bones hidden).
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { robotGlb } from '../helpers/robot_glb.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragTargetAlongY,
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type Point = [number, number, number];
type Quat = [number, number, number, number];
interface Box {
  min: Point;
  max: Point;
}

const distance = (a: Point, b: Point): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const center = (b: Box): Point => [0, 1, 2].map((i) => (b.min[i] + b.max[i]) / 2) as Point;
const sub = (a: Point, b: Point): Point => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a: Point, b: Point): Point => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];

/** q * p * q^-1 for a unit quaternion [x, y, z, w]. */
function rotate(q: Quat, p: Point): Point {
  const [x, y, z, w] = q;
  const t = [2 * (y * p[2] - z * p[1]), 2 * (z * p[0] - x * p[2]), 2 * (x * p[1] - y * p[0])];
  return [
    p[0] + w * t[0] + y * t[2] - z * t[1],
    p[1] + w * t[1] + z * t[0] - x * t[2],
    p[2] + w * t[2] + x * t[1] - y * t[0],
  ];
}
const conjugate = (q: Quat): Quat => [-q[0], -q[1], -q[2], q[3]];
/** Angle between two unit quaternions' rotations, degrees. */
const turnDeg = (a: Quat, b: Quat): number =>
  (2 * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]))) * 180) / Math.PI;

async function probe<T>(
  page: Page,
  what: string,
  read: (arg: number | string) => T | null | undefined,
  arg: number | string,
): Promise<T> {
  const value = await page.evaluate(read, arg);
  if (value === null || value === undefined) throw new Error(`no ${what} ${arg}`);
  return value;
}
const tip = (page: Page, k: number) => probe<Point>(page, 'tip', (i) => window.ikPage?.tipPosition(i as number), k);
const target = (page: Page, k: number) =>
  probe<Point>(page, 'target', (i) => window.ikPage?.targetPosition(i as number), k);
const tipTurn = (page: Page, k: number) =>
  probe<Quat>(page, 'tip rotation', (i) => window.ikPage?.tipRotation(i as number), k);
const meshBox = (page: Page, name: string) =>
  probe<Box>(page, 'mesh', (n) => window.ikPage?.objectBounds(n as string), name);

describe('a robot whose feet are control bones off the root (RobotExpressive-like)', () => {
  it('gets the leg ends as foot effectors, and a leg lifted with the mouse takes its foot mesh along', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    mkdirSync(resultsDir, { recursive: true });
    const file = join(resultsDir, 'robot_legs.glb');
    writeFileSync(file, await robotGlb());
    await page.setInputFiles('#rig-file', file);
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'robot_legs' && document.getElementById('app')?.dataset.state === 'ready',
    );
    await renderedFrames(page, 3);

    // 1. The legs' effectors are the ends of the leg chains; the message names the controls left out.
    const names = await page.evaluate(() =>
      (window.ikPage?.effectors() ?? []).map((b) => window.ikPage?.boneNames()[b] ?? ''),
    );
    expect(names).toContain('LowerLegL');
    expect(names).toContain('LowerLegR');
    for (const control of ['FootL', 'FootR', 'PoleTargetL', 'PoleTargetR']) expect(names).not.toContain(control);
    const message = (await page.textContent('#message')) ?? '';
    console.log(`[robot legs] effectors ${names.join(', ')}; message: "${message}"`);
    expect(message).toContain('4 control bones (FootL, PoleTargetL, FootR, PoleTargetR) off the root');
    expect(message).toContain(
      'end effectors are the hands, feet and head of the humanoid mapping, the ends of the limbs (LowerLegL, LowerLegR) in place of the control bones off the root (FootL, FootR) (Head, Palm2L, Palm2R, LowerLegL, LowerLegR)',
    );

    const left = await effectorNamed(page, /^LowerLegL$/),
      right = await effectorNamed(page, /^LowerLegR$/);
    // The importer's other effectors (the page may add a hips target of its own, free while another is dragged).
    const others = ['Head', 'Palm2L', 'Palm2R', 'LowerLegR'].map((n) => names.indexOf(n));
    expect(others).not.toContain(-1);
    const delta = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    expect(delta).toBeGreaterThan(0);
    const height = await page.evaluate(() => {
      const b = window.ikPage?.bounds();
      return b ? b.max[1] - b.min[1] : NaN;
    });
    expect(height).toBeGreaterThan(1.5); // the robot stands about 1.95 tall
    const stood = await tip(page, left),
      stoodTurn = await tipTurn(page, left);
    const othersStood = await Promise.all(others.map((k) => tip(page, k)));
    const rightTurn = await tipTurn(page, right);
    const footL = await meshBox(page, 'FootMeshL'),
      footR = await meshBox(page, 'FootMeshR');
    expect(footL.min[1]).toBeLessThan(0.01); // on the floor, below the leg's end
    expect(footL.max[1]).toBeLessThan(stood[1]);

    // 2. The left leg's target up 15% of the height with the mouse; the leg's end reaches it.
    await selectTarget(page, left);
    await dragTargetAlongY(page, left, 0.15 * height, 20);
    await waitForConvergence(page);
    await renderedFrames(page, 2);
    const lifted = await target(page, left),
      reached = await tip(page, left);
    const rise = reached[1] - stood[1];
    expect(lifted[1] - stood[1]).toBeGreaterThan(0.14 * height);
    expect(distance(reached, lifted)).toBeLessThan(delta);

    // 3. The foot's mesh came up with the leg: held where it was relative to the leg's end.
    const footL2 = await meshBox(page, 'FootMeshL');
    const offset = rotate(conjugate(stoodTurn), sub(center(footL), stood)); // in the leg end's frame
    const expected = add(reached, rotate(await tipTurn(page, left), offset));
    const footRise = footL2.min[1] - footL.min[1];
    console.log(
      `[robot legs] leg end up ${rise.toFixed(3)} (${((100 * rise) / height).toFixed(1)}% of ${height.toFixed(3)}), ${(distance(reached, lifted) / delta).toFixed(3)} δ from its target; ` +
        `foot mesh bottom up ${footRise.toFixed(3)}, centre up ${(center(footL2)[1] - center(footL)[1]).toFixed(3)}, ` +
        `${(distance(center(footL2), expected) / delta).toExponential(2)} δ from where the leg end's frame holds it`,
    );
    expect(distance(center(footL2), expected)).toBeLessThan(delta);
    expect(footRise).toBeGreaterThan(0.6 * rise);
    expect(footRise).toBeLessThan(1.4 * rise);

    // 4. The rest stayed: the right foot (place, turn, mesh), the head and the hands.
    const othersNow = await Promise.all(others.map((k) => tip(page, k)));
    const moved = others.map((k, i) => ({ name: names[k], by: distance(othersNow[i], othersStood[i]) }));
    const rightTurned = turnDeg(rightTurn, await tipTurn(page, right));
    const footR2 = await meshBox(page, 'FootMeshR');
    const footRMoved = Math.max(distance(footR2.min, footR.min), distance(footR2.max, footR.max));
    console.log(
      `[robot legs] others moved (δ): ${moved.map((m) => `${m.name} ${(m.by / delta).toExponential(2)}`).join(', ')}; ` +
        `right foot turned ${rightTurned.toFixed(3)}°, its mesh moved ${(footRMoved / delta).toExponential(2)} δ`,
    );
    for (const m of moved) expect(m.by, m.name).toBeLessThan(delta);
    expect(rightTurned).toBeLessThan(3);
    expect(footRMoved).toBeLessThan(delta);

    // The picture without the bones' markers, so the meshes show: the left foot up with its leg.
    await (await panelControl(page, /^show bones/)).locator('input').uncheck();
    await renderedFrames(page, 2);
    await page.screenshot({ path: join(resultsDir, 'robot-leg-lift.png') });
    expect(errors).toEqual([]);
  });
});
