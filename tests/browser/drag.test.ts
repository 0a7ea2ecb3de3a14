// Dragging as a user does, from the pose a user starts in (the rest pose, straight limbs), with
// real mouse events on the page's gizmo: the README's knight drag ends on target; lifting the
// character's foot straight up bends the leg and the foot follows within the tip tolerance at every
// step while the hands and the head stay on theirs; a target dragged past a limb's reach ends at
// the closest point and says so, and a reset and its undo each show their own pose's status, and a
// freshly loaded rig says it is on target. With the humanoid limits and without them (the README's
// before and after); writes docs/foot-lift.png and docs/foot-lift-free.png when
// UPDATE_SCREENSHOT=1.
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
  targetScreen,
  usePageServer,
  waitForConvergence,
  waitForSettled,
} from './page_helpers.js';

const env = usePageServer();

/** Distance of every effector's tip from its target (rig units), in effector order. */
async function tipErrors(page: Page): Promise<number[]> {
  return page.evaluate(() => {
    const p = window.ikPage;
    return (p?.effectors() ?? []).map((_, k) => p?.effectorError(k) ?? NaN);
  });
}

async function tipTolerance(page: Page): Promise<number> {
  return page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
}

describe('dragging from the rest pose', () => {
  it("the README's knight drag: hand.L dragged by (30, -70) px ends on its target", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    await waitForConvergence(page); // a loaded rig says it is on target (its targets sit on the tips)
    expect(await stat(page, 'iterations')).toBe('0');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragBy(page, hand, 30, -70);
    await waitForConvergence(page);
    const tolerance = await tipTolerance(page);
    for (const e of await tipErrors(page)) expect(e).toBeLessThan(tolerance);
    expect(errors).toEqual([]);
  });

  it.for([
    ['humanoid limits', true, 'docs/foot-lift.png'],
    ['+-180 limits (the switch off)', false, 'docs/foot-lift-free.png'],
  ] as const)(
    "lifting the character's foot by 0.3 of its height with %s: the foot follows at every step, hands and head stay",
    async ([, humanoid, docsShot], ctx) => {
      const { page, errors } = await openPage(env.browser, ctx);
      await gotoRig(page, env.url, 'character');
      const toggle = page
        .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^humanoid limits$/ }) })
        .locator('input');
      expect(await toggle.isChecked()).toBe(true); // a recognised humanoid starts with anatomical limits
      if (!humanoid) await toggle.click();
      const names = await page.evaluate(() => {
        const p = window.ikPage;
        return (p?.effectors() ?? []).map((b) => p?.boneNames()[b] ?? '');
      });
      const foot = names.findIndex((n) => /LeftFoot$/.test(n));
      expect(foot, names.join(', ')).toBeGreaterThanOrEqual(0);
      const pinned = names.map((n, k) => (/hand|head/i.test(n) ? k : -1)).filter((k) => k >= 0);
      expect(pinned.length).toBeGreaterThanOrEqual(3);
      await selectTarget(page, foot);
      const tolerance = await tipTolerance(page);
      const bounds = await page.evaluate(() => window.ikPage?.bounds() ?? null);
      if (!bounds) throw new Error('no bounds');
      const height = bounds.max[1] - bounds.min[1];
      const start = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, foot);
      if (!start) throw new Error('no target');

      // Grab the gizmo's up (Y) arrow a little above the target and pull it up along the arrow by
      // about 30% of the height on screen: the target moves straight up.
      const center = await targetScreen(page, foot);
      const above = await page.evaluate(([x, y, z]) => window.ikPage?.worldToScreen([x, y, z]) ?? null, [
        start[0],
        start[1] + 0.01 * height,
        start[2],
      ] as const);
      if (!above) throw new Error('no screen point');
      const up = { x: above.x - center.x, y: above.y - center.y };
      const unit = Math.hypot(up.x, up.y);
      const pixels = (0.3 * height * unit) / (0.01 * height); // screen length of 30% of the height along the arrow
      const grab = { x: center.x + (35 * up.x) / unit, y: center.y + (35 * up.y) / unit };
      const steps = 20;
      await page.mouse.move(grab.x, grab.y);
      await page.mouse.down();
      let worstFoot = 0,
        worstPinned = 0;
      for (let i = 1; i <= steps; i++) {
        const along = (pixels * i) / steps;
        await page.mouse.move(grab.x + (along * up.x) / unit, grab.y + (along * up.y) / unit);
        // The per-frame solve brings the foot onto its moved target; waiting times out if it does not.
        await page.waitForFunction(
          ([k, tol]) => (window.ikPage?.effectorError(k) ?? Infinity) < tol,
          [foot, tolerance] as const,
          { timeout: 5_000 },
        );
        const e = await tipErrors(page);
        worstFoot = Math.max(worstFoot, e[foot]);
        for (const k of pinned) worstPinned = Math.max(worstPinned, e[k]);
      }
      await page.mouse.up();
      await waitForConvergence(page);
      const end = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, foot);
      if (!end) throw new Error('no target');
      expect(end[1] - start[1]).toBeGreaterThan(0.27 * height); // the target went up by about 30% of the height
      expect(Math.hypot(end[0] - start[0], end[2] - start[2])).toBeLessThan(1e-6 * height); // straight up
      expect(worstFoot).toBeLessThan(tolerance);
      expect(worstPinned).toBeLessThan(tolerance);
      expect(await statText(page, 'status')).toBe('on target');

      // Orbit to a side view (drag on empty ground) so that the picture shows the bent leg.
      const camera = await page.evaluate(() => window.ikPage?.cameraPosition());
      await page.mouse.move(800, 650);
      await page.mouse.down();
      await page.mouse.move(800 - 100, 650, { steps: 10 });
      await page.mouse.up();
      expect(await page.evaluate(() => window.ikPage?.cameraPosition())).not.toEqual(camera);
      await renderedFrames(page);
      const shot = process.env.UPDATE_SCREENSHOT === '1' ? docsShot : `test-results/${docsShot.slice(5)}`;
      mkdirSync(join(repoRoot, shot, '..'), { recursive: true });
      await page.screenshot({ path: join(repoRoot, shot) });
      expect(errors).toEqual([]);
    },
  );

  it('a target dragged past the arm ends at the closest point, says so, and the pinned effectors stay', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    const from = await targetScreen(page, hand);
    const root = await page.evaluate(() => window.ikPage?.boneScreen(0) ?? null);
    if (!root) throw new Error('no root');
    // Straight away from the body, far past the arm's length.
    const away = { x: from.x - root.x, y: from.y - root.y };
    const len = Math.hypot(away.x, away.y);
    await dragBy(page, hand, (away.x / len) * 400, (away.y / len) * 400, 20);
    const reason = await waitForSettled(page);
    // A stationary point, or a run settled at the closest point with the others held (strict priority).
    expect(['converged_grad', 'zero_step']).toContain(reason);
    expect(await statText(page, 'status')).toBe('out of reach (closest point)');
    expect(await page.getAttribute('[data-stat="status"]', 'data-reached')).toBe('false');
    const tolerance = await tipTolerance(page);
    const e = await tipErrors(page);
    expect(e[hand]).toBeGreaterThan(10 * tolerance);
    e.forEach((d, k) => {
      if (k !== hand) expect(d, `effector ${k}`).toBeLessThan(tolerance);
    });
    // The stats describe the pose shown: pinned drift leaves out the hand (still selected, no longer
    // dragged); a reset and its undo each show their own pose's status and tip error.
    expect(Number(await stat(page, 'tipDistance'))).toBeCloseTo(Math.max(...e), 6);
    expect(Number(await stat(page, 'pinnedDrift'))).toBeLessThan(tolerance);
    await page.keyboard.press('r');
    await waitForConvergence(page);
    expect(Number(await stat(page, 'tipDistance'))).toBeLessThan(tolerance);
    await page.keyboard.press('Control+z');
    await page.waitForFunction(
      () => document.querySelector<HTMLElement>('[data-stat="status"]')?.dataset.reached === 'false',
    );
    expect(await statText(page, 'status')).toBe('out of reach (closest point)');
    const undone = await tipErrors(page);
    expect(undone[hand]).toBeCloseTo(e[hand], 6);
    expect(Number(await stat(page, 'tipDistance'))).toBeCloseTo(Math.max(...undone), 6);
    expect(errors).toEqual([]);
  });
});
