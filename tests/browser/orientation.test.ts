// Orientation goals on the page, from the knight's rest pose as a user starts: the rotate gizmo
// (E) starts at the hand's current frame, and turning it makes the hand's bone frame turn to it
// (within the solver's 0.5° orientation tolerance), the status saying "on target" only once the
// orientation is reached too; swing mode (Q) still swings the target about the root joint; a target
// with an orientation goal shows its axes, which go with the goal (O, the panel's box, reset).
// The gizmo is turned through the page's test hook (window.ikPage.turnGizmo), which drives the
// gizmo's own 'dragging-changed' and 'objectChange' events as a mouse drag on its rings does.
// Writes docs/orientation-goal.png when UPDATE_SCREENSHOT=1 (else test-results/orientation-goal.png).
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames, repoRoot } from './harness.js';
import {
  dragBy,
  effectorNamed,
  gotoRig,
  selectTarget,
  stat,
  statText,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type Quat = [number, number, number, number];

/** Angle between two rotations given as quaternions [x, y, z, w], degrees. */
function angleDeg(a: Quat, b: Quat): number {
  const dot = Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]) / (Math.hypot(...a) * Math.hypot(...b));
  return (2 * Math.acos(Math.min(1, dot)) * 180) / Math.PI;
}

/** What the page says of effector k's orientation: its goal, its frame, the error (degrees), whether its axes show. */
async function orientation(
  page: Page,
  k: number,
): Promise<{ goal: Quat | null; tip: Quat | null; error: number; axes: boolean }> {
  return page.evaluate((i) => {
    const p = window.ikPage;
    return {
      goal: p?.orientationGoal(i) ?? null,
      tip: p?.tipRotation(i) ?? null,
      error: p?.orientationError(i) ?? NaN,
      axes: p?.axesShown(i) ?? false,
    };
  }, k);
}

/** The largest tip error over all effectors, rig units. */
async function worstTipError(page: Page): Promise<number> {
  return page.evaluate(() => {
    const p = window.ikPage;
    return Math.max(...(p?.effectors() ?? []).map((_, k) => p?.effectorError(k) ?? Infinity));
  });
}

/** The panel's "orientation goal" checkbox. */
function orientationBox(page: Page) {
  return page
    .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^orientation goal/ }) })
    .locator('input');
}

describe('orientation goals on the page', () => {
  it('rotate (E): the gizmo starts at the hand frame; turning it turns the hand to it, and "on target" waits for the orientation', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await page.keyboard.press('e');
    expect(await page.evaluate(() => window.ikPage?.gizmoMode())).toBe('rotate');
    const before = await orientation(page, hand);
    expect(before.goal).toBeNull();
    expect(before.axes).toBe(false);
    expect(await orientationBox(page).isChecked()).toBe(false);
    // The gizmo starts at the hand's current frame: nothing jumps.
    const gizmo = await page.evaluate(() => window.ikPage?.gizmoQuaternion() ?? null);
    if (!gizmo || !before.tip) throw new Error('no gizmo or no tip rotation');
    expect(angleDeg(gizmo, before.tip)).toBeLessThan(1e-3);

    // Every time the status turns to "on target", record the orientation error at that moment.
    await page.evaluate((k) => {
      const cell = document.querySelector<HTMLElement>('[data-stat="status"]');
      const seen: number[] = [];
      (window as unknown as { onTargetErrors: number[] }).onTargetErrors = seen;
      if (!cell) throw new Error('no status cell');
      new MutationObserver(() => {
        if (cell.dataset.reached === 'true') seen.push(window.ikPage?.orientationError(k) ?? NaN);
      }).observe(cell, { attributes: true, attributeFilter: ['data-reached'] });
    }, hand);

    await page.evaluate(() => window.ikPage?.turnGizmo([0, 1, 0], 70, 12));
    const turned = await orientation(page, hand);
    if (!turned.goal) throw new Error('turning the gizmo set no orientation goal');
    expect(angleDeg(turned.goal, before.tip)).toBeGreaterThan(69.9);
    expect(angleDeg(turned.goal, before.tip)).toBeLessThan(70.1);
    expect(turned.axes).toBe(true);
    expect(await orientationBox(page).isChecked()).toBe(true);
    await waitForConvergence(page);
    const after = await orientation(page, hand);
    if (!after.tip || !after.goal) throw new Error('no rotation');
    expect(angleDeg(after.tip, after.goal)).toBeLessThan(0.5);
    expect(after.error).toBeLessThan(0.5);
    expect(angleDeg(after.tip, before.tip)).toBeGreaterThan(69); // the hand did turn
    expect(await worstTipError(page)).toBeLessThan(await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0));
    const onTargetErrors = await page.evaluate(
      () => (window as unknown as { onTargetErrors: number[] }).onTargetErrors,
    );
    for (const e of onTargetErrors) expect(e).toBeLessThan(0.5);
    // The panel shows the orientation error in degrees, 3 significant digits.
    await page.waitForFunction(() =>
      document.querySelector('[data-stat="orientationErrorDeg"]')?.textContent?.endsWith('°'),
    );
    expect(await page.isVisible('[data-stat="orientationErrorDeg"]')).toBe(true);
    expect(Number(await stat(page, 'orientationErrorDeg'))).toBeLessThan(0.5);
    expect(await statText(page, 'orientationErrorDeg')).toMatch(/^\d\.\d\d°$|^\d\.\d\de-\d+°$|^0\.\d+°$/);

    // The picture: zoomed in on the hand's target, its rotate gizmo and its axes.
    const view = await page.locator('#viewport').boundingBox();
    if (!view) throw new Error('no viewport');
    await page.mouse.move(view.x + view.width / 2, view.y + view.height * 0.6);
    await page.mouse.wheel(0, -800);
    await page.mouse.move(view.x + 10, view.y + 10); // off the gizmo: no hover highlight
    await renderedFrames(page, 3);
    const shot =
      process.env.UPDATE_SCREENSHOT === '1' ? 'docs/orientation-goal.png' : 'test-results/orientation-goal.png';
    mkdirSync(join(repoRoot, shot, '..'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, shot) });
    expect(errors).toEqual([]);
  });

  it('step by step, the status says "on target" exactly when the tips and the hand orientation are within tolerance', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await page.keyboard.press('s'); // step mode on: no per-frame solve from here
    await page.keyboard.press('e');
    await page.evaluate(() => window.ikPage?.turnGizmo([1, 0, 0], -30, 6));
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    const states: boolean[] = [];
    for (let i = 0; i < 200 && !states.at(-1); i++) {
      await page.keyboard.press('s');
      const onTarget = (await statText(page, 'status')) === 'on target';
      const { error } = await orientation(page, hand);
      const reached = error < 0.5 && (await worstTipError(page)) < tolerance;
      expect(onTarget, `step ${i + 1}: orientation error ${error}°`).toBe(reached);
      states.push(onTarget);
    }
    expect(states[0]).toBe(false); // 30° off after the turn
    expect(states.at(-1)).toBe(true);
    expect((await orientation(page, hand)).error).toBeLessThan(0.5);
    expect(errors).toEqual([]);
  });

  it('swing (Q) still swings the target about the root joint; an orientation goal swings with it', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await page.keyboard.press('q');
    expect(await page.evaluate(() => window.ikPage?.gizmoMode())).toBe('swing');
    const root = await page.evaluate(() => window.ikPage?.rootJoint() ?? null);
    const from = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, hand);
    if (!root || !from) throw new Error('no root or target');
    await page.evaluate(() => window.ikPage?.turnGizmo([0, 1, 0], 20, 8));
    const to = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, hand);
    if (!to) throw new Error('no target');
    const r0 = from.map((x, i) => x - root[i]),
      r1 = to.map((x, i) => x - root[i]);
    expect(Math.hypot(...r1)).toBeCloseTo(Math.hypot(...r0), 6); // on a sphere about the root joint
    expect(r1[1]).toBeCloseTo(r0[1], 6); // about the vertical axis: the height stays
    const swung = ((Math.atan2(r0[2], r0[0]) - Math.atan2(r1[2], r1[0])) * 180) / Math.PI;
    expect(((swung + 540) % 360) - 180).toBeCloseTo(20, 3);
    const o = await orientation(page, hand);
    expect(o.goal).toBeNull();
    expect(o.axes).toBe(false);
    await waitForConvergence(page);

    // With an orientation goal, swinging carries it along: the goal turns by the same 20° about the vertical.
    await page.keyboard.press('o');
    await page.waitForFunction((k) => window.ikPage?.axesShown(k) === true, hand, { timeout: 5_000 }); // set at the next frame
    const held = (await orientation(page, hand)).goal;
    if (!held) throw new Error('O set no orientation goal');
    await page.evaluate(() => window.ikPage?.turnGizmo([0, 1, 0], 20, 8));
    const carried = (await orientation(page, hand)).goal;
    if (!carried) throw new Error('swinging dropped the orientation goal');
    const s = Math.sin((10 * Math.PI) / 180),
      c = Math.cos((10 * Math.PI) / 180); // 20° about +y
    const [x, y, z, w] = held;
    const expected: Quat = [c * x + s * z, c * y + s * w, c * z - s * x, c * w - s * y];
    expect(angleDeg(carried, expected)).toBeLessThan(1e-3);
    await waitForConvergence(page);
    expect((await orientation(page, hand)).error).toBeLessThan(0.5);
    expect(errors).toEqual([]);
  });

  it('a target shows its axes while it has an orientation goal: O and the panel box turn it on and off, moving keeps it, the reset clears it', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    const others = await page.evaluate(() => (window.ikPage?.effectors() ?? []).map((_, k) => k));
    for (const k of others) expect((await orientation(page, k)).axes).toBe(false);

    await page.keyboard.press('o');
    await page.waitForFunction((k) => window.ikPage?.axesShown(k) === true, hand, { timeout: 5_000 }); // shown at the next frame's redraw
    const on = await orientation(page, hand);
    if (!on.goal || !on.tip) throw new Error('O set no orientation goal');
    expect(angleDeg(on.goal, on.tip)).toBeLessThan(1e-3); // at the hand's current frame: nothing jumps
    expect(on.axes).toBe(true);
    expect(await orientationBox(page).isChecked()).toBe(true);
    for (const k of others) if (k !== hand) expect((await orientation(page, k)).axes).toBe(false);

    // Moving the target (translate) keeps its orientation goal; the hand ends on both.
    await dragBy(page, hand, 30, -60);
    await waitForConvergence(page);
    const moved = await orientation(page, hand);
    if (!moved.goal) throw new Error('moving the target dropped its orientation goal');
    expect(angleDeg(moved.goal, on.goal)).toBeLessThan(1e-9);
    expect(moved.axes).toBe(true);
    expect(moved.error).toBeLessThan(0.5);

    // The panel's box turns it off.
    await orientationBox(page).click();
    await page.waitForFunction((k) => window.ikPage?.axesShown(k) === false, hand, { timeout: 5_000 }); // hidden at the next frame's redraw
    const off = await orientation(page, hand);
    expect(off.goal).toBeNull();
    expect(off.axes).toBe(false);
    await renderedFrames(page);
    expect(await page.isVisible('[data-stat="orientationErrorDeg"]')).toBe(false);

    // On again with the box, then the panel's reset clears it.
    await orientationBox(page).click();
    await page.waitForFunction((k) => window.ikPage?.axesShown(k) === true, hand, { timeout: 5_000 }); // shown at the next frame's redraw
    await page
      .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^reset pose/ }) })
      .locator('button')
      .click();
    await renderedFrames(page);
    const reset = await orientation(page, hand);
    expect(reset.goal).toBeNull();
    expect(reset.axes).toBe(false);
    expect(await orientationBox(page).isChecked()).toBe(false);

    // The help lists the new keys.
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await page.keyboard.press('h');
    const help = (await page.textContent('#help')) ?? '';
    expect(help).toMatch(/swing the target about the root joint/);
    expect(help).toMatch(/orientation goal of the selected target/);
    expect(errors).toEqual([]);
  });
});
