// A still body on a rig without a humanoid map: the fox-like quadruped of
// quadruped_model.ts (root bone on the floor, no limits, the paws and the head its effectors, the
// tail none), opened through the file input. A paw's target dragged up 15% of the height with the
// mouse (the gizmo's up arrow): the paw ends on its target (within δ, the page's "on target
// within") and the body bone (the hips) and the tail's tip move less than 2% of the height, for a
// front and a hind paw. With the panel's "still body" cleared, the same front-paw lift moves the
// hips and the tail by more than 2%: the setting is what holds them. Prints the motions and the
// page's per-frame solve times with the setting on and off; writes
// test-results/quadruped-paw-lift.png (the front paw lifted, the setting on).
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragMouse,
  dragTargetAlongY,
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';
import { QUADRUPED_BODY, QUADRUPED_TAIL_TIP, quadrupedGlb } from './quadruped_model.js';

const env = usePageServer();

type Point = [number, number, number];

const distance = (a: Point, b: Point): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** Opens the quadruped through the file input and waits until it is shown (its stats start afresh). */
async function openQuadruped(page: Page): Promise<void> {
  const loads = (await page.evaluate(() => window.ikPage?.loads())) ?? 0;
  await page.setInputFiles('#rig-file', {
    name: 'quadruped.glb',
    mimeType: 'model/gltf-binary',
    buffer: Buffer.from(await quadrupedGlb()),
  });
  await page.waitForFunction(
    (n) =>
      (window.ikPage?.loads() ?? 0) > n &&
      window.ikPage?.rigName() === 'quadruped' &&
      document.getElementById('app')?.dataset.state === 'ready',
    loads,
  );
  await renderedFrames(page, 3);
}

async function boneTip(page: Page, name: string): Promise<Point> {
  const p = await page.evaluate((n) => {
    const probe = window.ikPage;
    return probe ? probe.boneTip(probe.boneNames().indexOf(n)) : null;
  }, name);
  if (!p) throw new Error(`no bone ${name}`);
  return p;
}

async function point(page: Page, what: 'tip' | 'target', k: number): Promise<Point> {
  const p = await page.evaluate(
    ([w, i]) => (w === 'tip' ? window.ikPage?.tipPosition(i) : window.ikPage?.targetPosition(i)) ?? null,
    [what, k] as const,
  );
  if (!p) throw new Error(`no ${what} ${k}`);
  return p;
}

/**
 * What one paw lift did: the target's rise and the hips' and tail tip's moves as shares of the
 * rig's height; the paw's distance from its target and the other tips' largest move, rig units; the
 * running median of the page's per-frame solve times since the rig opened, ms.
 */
interface Lift {
  rise: number;
  hips: number;
  tail: number;
  pawOff: number;
  othersOff: number;
  solveMs: number;
}

/** Puts the gizmo on target k: a click on it, else Tab through the targets (a paw behind another on screen). */
async function select(page: Page, k: number): Promise<void> {
  await selectTarget(page, k).catch(() => undefined);
  for (let i = 0; i < 8 && (await page.evaluate(() => window.ikPage?.selectedTarget())) !== k; i++)
    await page.keyboard.press('Tab');
  expect(await page.evaluate(() => window.ikPage?.selectedTarget())).toBe(k);
}

/** From the rest pose (R), drags paw effector k's target up 15% of `height` with the mouse and waits until on target. */
async function liftPaw(page: Page, k: number, height: number): Promise<Lift> {
  await page.keyboard.press('r');
  await page.waitForFunction(() => (window.ikPage?.angles() ?? [1]).every((a) => a === 0));
  await renderedFrames(page, 2);
  const hips0 = await boneTip(page, QUADRUPED_BODY),
    tail0 = await boneTip(page, QUADRUPED_TAIL_TIP),
    paw0 = await point(page, 'tip', k);
  const effectors = (await page.evaluate(() => window.ikPage?.effectors() ?? [])).length;
  const others0 = await Promise.all(Array.from({ length: effectors }, (_, j) => point(page, 'tip', j)));
  const solvesBefore = (await page.evaluate(() => window.ikPage?.solveMs().total)) ?? 0;
  await select(page, k);
  await dragTargetAlongY(page, k, 0.15 * height, 20);
  await waitForConvergence(page);
  const ms = await page.evaluate(() => window.ikPage?.solveMs() ?? null);
  expect(ms!.total).toBeGreaterThan(solvesBefore + 10); // the drag solved frame by frame
  const target = await point(page, 'target', k),
    paw = await point(page, 'tip', k);
  let othersOff = 0;
  for (let j = 0; j < effectors; j++)
    if (j !== k) othersOff = Math.max(othersOff, distance(await point(page, 'tip', j), others0[j]));
  return {
    rise: (target[1] - paw0[1]) / height,
    hips: distance(await boneTip(page, QUADRUPED_BODY), hips0) / height,
    tail: distance(await boneTip(page, QUADRUPED_TAIL_TIP), tail0) / height,
    pawOff: distance(paw, target),
    othersOff,
    solveMs: ms!.median,
  };
}

const pct = (x: number): string => `${(100 * x).toFixed(2)}%`;

describe('a still body on a quadruped without a humanoid map', () => {
  it('lifting one paw moves only its leg: hips and tail within 2% of the height, front and hind; off, they move more', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    await openQuadruped(page);
    const message = (await page.textContent('#message')) ?? '';
    expect(message).not.toMatch(/humanoid/); // no humanoid map
    expect(await page.evaluate(() => window.ikPage?.settings().stillBody)).toBe(true); // the default
    const names = await page.evaluate(() =>
      (window.ikPage?.effectors() ?? []).map((b) => window.ikPage?.boneNames()[b] ?? ''),
    );
    expect(names).toEqual(['head', 'fore_paw.L', 'fore_paw.R', 'hind_paw.L', 'hind_paw.R']);
    const limits = await page.evaluate(() => window.ikPage?.limits() ?? { lower: [], upper: [] });
    expect(Math.max(...limits.lower)).toBe(-180); // no limits anywhere
    expect(Math.min(...limits.upper)).toBe(180);
    const delta = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    const height = await page.evaluate(() => {
      const b = window.ikPage?.bounds();
      return b ? b.max[1] - b.min[1] : NaN;
    });
    expect(delta).toBeGreaterThan(0);
    expect(height).toBeGreaterThan(0.5);
    const front = await effectorNamed(page, /^fore_paw\.L$/),
      hind = await effectorNamed(page, /^hind_paw\.L$/);
    expect([names[front], names[hind]]).toEqual(['fore_paw.L', 'hind_paw.L']);

    const on: Record<string, Lift> = {};
    for (const [label, k] of [
      ['front', front],
      ['hind', hind],
    ] as const) {
      const lift = (on[label] = await liftPaw(page, k, height));
      console.log(
        `[quadruped] still body on, ${label} paw up ${pct(lift.rise)}: hips ${pct(lift.hips)}, tail tip ${pct(lift.tail)} of the height; paw ${(lift.pawOff / delta).toFixed(2)} δ off its target, other tips moved ≤ ${(lift.othersOff / delta).toFixed(2)} δ; solve median ${lift.solveMs.toFixed(3)} ms`,
      );
      expect(lift.rise).toBeGreaterThan(0.14);
      expect(lift.pawOff).toBeLessThan(delta);
      expect(lift.othersOff).toBeLessThan(delta);
      expect(lift.hips).toBeLessThan(0.02);
      expect(lift.tail).toBeLessThan(0.02);
      if (label === 'front') {
        // The camera orbited down to the rig's left side (a drag on the empty floor), so the lift shows.
        await dragMouse(page, { x: 120, y: 760 }, -80, -120, 12);
        await renderedFrames(page);
        await page.screenshot({ path: join(resultsDir, 'quadruped-paw-lift.png') });
      }
    }

    // The panel's "still body" cleared: the least change over the whole body moves the hips and the
    // tail. The rig opened again, so the solve times' running median holds this setting's solves only.
    await (await panelControl(page, /^still body/)).locator('input').click();
    expect(await page.evaluate(() => window.ikPage?.settings().stillBody)).toBe(false);
    await openQuadruped(page);
    for (const [label, k] of [
      ['front', front],
      ['hind', hind],
    ] as const) {
      const lift = await liftPaw(page, k, height);
      console.log(
        `[quadruped] still body off, ${label} paw up ${pct(lift.rise)}: hips ${pct(lift.hips)}, tail tip ${pct(lift.tail)} of the height; paw ${(lift.pawOff / delta).toFixed(2)} δ off its target; solve median ${lift.solveMs.toFixed(3)} ms (on: ${on[label].solveMs.toFixed(3)} ms)`,
      );
      expect(lift.pawOff).toBeLessThan(delta);
      expect(lift.hips).toBeGreaterThan(0.02);
      expect(lift.tail).toBeGreaterThan(0.02);
    }
    expect(errors).toEqual([]);
  });
});
