// Selection you can always make, on the project character with real mouse and keyboard:
// with the left foot's target selected, the right foot's target lies under the gizmo's handles (the
// gizmo's own hover says so), and a click on it selects it all the same, moving nothing; a drag
// that starts there on the gizmo's axis still drags the gizmo's target. Tab and Shift+Tab step
// through the targets (wrapping), Esc lets the gizmo go, Tab on a focused panel control moves the
// focus and leaves the selection alone, and the help lists the keys. A drag on an axis of the
// selected target moves it along that axis. In track mode Tab and Esc act on the three tracked
// points. A screenshot with a target selected goes to test-results/selection-keys.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import type { ScreenPoint } from '../../web/src/view/stage.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import { dragMouse, gotoRig, targetScreen, usePageServer } from './page_helpers.js';

const env = usePageServer();

const selected = (page: Page) => page.evaluate(() => window.ikPage?.selectedTarget() ?? null);
const targets = (page: Page) => page.evaluate(() => window.ikPage?.targets() ?? []);

/** The effector whose bone's name matches `pattern` (fails when there is none). */
async function effector(page: Page, pattern: RegExp): Promise<number> {
  const names = await page.evaluate(() => {
    const p = window.ikPage;
    return (p?.effectors() ?? []).map((b) => p?.boneNames()[b] ?? '');
  });
  const k = names.findIndex((n) => pattern.test(n));
  expect(k, `${pattern} among ${names.join(', ')}`).toBeGreaterThanOrEqual(0);
  return k;
}

/** The gizmo's handle under the mouse once it rests at `p` (the gizmo's own hover test), or null. */
async function gizmoAxisAt(page: Page, p: ScreenPoint): Promise<string | null> {
  await page.mouse.move(p.x - 3, p.y);
  await page.mouse.move(p.x, p.y);
  await renderedFrames(page);
  return page.evaluate(() => window.ikPage?.gizmoAxis() ?? null);
}

/** Largest coordinate change of target k between two target lists (rig units). */
function moved(a: number[], b: number[], k: number): number {
  return Math.max(...[0, 1, 2].map((i) => Math.abs(a[3 * k + i] - b[3 * k + i])));
}

/** Drags the mouse from `from` by (dx, dy) px, a frame after each move, and lets the page render. */
async function drag(page: Page, from: ScreenPoint, dx: number, dy: number): Promise<void> {
  await dragMouse(page, from, dx, dy);
  await renderedFrames(page);
}

describe('selection you can always make', () => {
  it('a click on a target under the gizmo selects it; a drag there still drags the gizmo', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const left = await effector(page, /LeftFoot$/);
    const right = await effector(page, /RightFoot$/);

    // Select the left foot's target with a click on its handle.
    const l = await targetScreen(page, left);
    await page.mouse.click(l.x, l.y);
    await page.waitForFunction((k) => window.ikPage?.selectedTarget() === k, left);
    await renderedFrames(page);

    // The right foot's target is within the gizmo's reach: its handles are under that point.
    const r = await targetScreen(page, right);
    const apart = Math.hypot(r.x - l.x, r.y - l.y);
    expect(apart).toBeLessThan(80);
    const axis = await gizmoAxisAt(page, r);
    expect(axis, `the left foot's gizmo under the right foot's target, ${apart.toFixed(0)} px away`).not.toBeNull();

    // A drag that starts there, on the gizmo's axis, drags the gizmo's target (the left foot's).
    const before = await targets(page);
    await drag(page, r, 25, -25);
    const afterDrag = await targets(page);
    expect(await selected(page)).toBe(left);
    expect(moved(before, afterDrag, left)).toBeGreaterThan(0);
    expect(moved(before, afterDrag, right)).toBe(0);

    // A click there selects the right foot's target and moves nothing.
    const r2 = await targetScreen(page, right);
    expect(await gizmoAxisAt(page, r2)).not.toBeNull();
    await page.mouse.down();
    await page.mouse.up();
    await renderedFrames(page);
    expect(await selected(page)).toBe(right);
    expect(await targets(page)).toEqual(afterDrag);

    // A screenshot with a target selected.
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'selection-keys.png') });

    // A click on the selected target itself is the gizmo's: nothing changes.
    await page.mouse.click(r2.x, r2.y);
    await renderedFrames(page);
    expect(await selected(page)).toBe(right);
    expect(await targets(page)).toEqual(afterDrag);
    expect(errors).toEqual([]);
  });

  it('Tab and Shift+Tab step through the targets, Esc deselects; Tab on a panel control moves the focus', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const n = (await page.evaluate(() => window.ikPage?.effectors().length)) ?? 0;
    expect(n).toBeGreaterThanOrEqual(5);
    const right = await effector(page, /RightFoot$/);
    const p = await targetScreen(page, right);
    await page.mouse.click(p.x, p.y);
    await page.waitForFunction((k) => window.ikPage?.selectedTarget() === k, right);

    await page.keyboard.press('Tab');
    expect(await selected(page)).toBe((right + 1) % n);
    await page.keyboard.press('Shift+Tab');
    expect(await selected(page)).toBe(right);
    await page.keyboard.press('Shift+Tab');
    expect(await selected(page)).toBe((right + n - 1) % n);
    await page.keyboard.press('Tab');
    for (let i = 0; i < n; i++) await page.keyboard.press('Tab'); // once round: wraps back
    expect(await selected(page)).toBe(right);

    // Esc: no target selected, the gizmo holds nothing.
    await page.keyboard.press('Escape');
    expect(await selected(page)).toBeNull();
    expect(await page.evaluate(() => window.ikPage?.gizmoQuaternion() ?? null)).toBeNull();
    await page.keyboard.press('Escape'); // again: still nothing
    expect(await selected(page)).toBeNull();
    // From none, Tab takes the first target and Shift+Tab the last.
    await page.keyboard.press('Tab');
    expect(await selected(page)).toBe(0);
    await page.keyboard.press('Escape');
    await page.keyboard.press('Shift+Tab');
    expect(await selected(page)).toBe(n - 1);

    // With a panel control focused, Tab is the browser's: the focus moves, the selection stays.
    const title = page.locator('.lil-gui > .lil-title').first();
    await title.focus();
    const focusedBefore = await page.evaluate(() => document.activeElement?.outerHTML.slice(0, 80));
    await page.keyboard.press('Tab');
    expect(await selected(page)).toBe(n - 1);
    expect(await page.evaluate(() => document.activeElement?.outerHTML.slice(0, 80))).not.toBe(focusedBefore);
    // A click in the view takes the focus back to the page: Tab selects again.
    const box = await page.locator('#viewport canvas').boundingBox();
    if (!box) throw new Error('no canvas');
    await page.mouse.click(box.x + 12, box.y + box.height - 12); // an empty corner: no bone, no target
    await page.keyboard.press('Tab');
    expect(await selected(page)).toBe(0);

    // The help lists the keys; Esc with the help open closes it and keeps the selection.
    await page.keyboard.press('?');
    const help = (await page.textContent('#help')) ?? '';
    expect(help).toMatch(/Tab.*select the next target/);
    expect(help).toMatch(/Shift\+Tab.*select the previous target/);
    expect(help).toMatch(/Escape.*deselect/);
    await page.keyboard.press('Escape');
    expect(await page.isHidden('#help')).toBe(true);
    expect(await selected(page)).toBe(0);
    expect(errors).toEqual([]);
  });

  it('a drag on an axis of the selected target moves it along that axis', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const left = await effector(page, /LeftFoot$/);
    const l = await targetScreen(page, left);
    await page.mouse.click(l.x, l.y);
    await page.waitForFunction((k) => window.ikPage?.selectedTarget() === k, left);
    await renderedFrames(page);

    // Find the gizmo's X arrow on screen: along the target's +x direction, where the gizmo's hover says X.
    const at = (await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, left))!;
    const size = await page.evaluate(() => {
      const b = window.ikPage!.bounds()!;
      return b.max[1] - b.min[1];
    });
    const ahead = await page.evaluate(([x, y, z]) => window.ikPage!.worldToScreen([x, y, z]), [
      at[0] + 0.1 * size,
      at[1],
      at[2],
    ] as [number, number, number]);
    const len = Math.hypot(ahead.x - l.x, ahead.y - l.y);
    const dir = { x: (ahead.x - l.x) / len, y: (ahead.y - l.y) / len };
    let grip: ScreenPoint | null = null;
    for (let d = 20; d <= 160 && !grip; d += 5) {
      const p = { x: l.x + dir.x * d, y: l.y + dir.y * d };
      if ((await gizmoAxisAt(page, p)) === 'X') grip = p;
    }
    if (!grip) throw new Error('no X arrow found along +x');

    const before = await targets(page);
    await drag(page, grip, dir.x * 40, dir.y * 40);
    const after = await targets(page);
    expect(await selected(page)).toBe(left);
    const dx = after[3 * left] - before[3 * left];
    expect(dx).toBeGreaterThan(0.01 * size); // along +x
    expect(Math.abs(after[3 * left + 1] - before[3 * left + 1])).toBeLessThan(1e-9);
    expect(Math.abs(after[3 * left + 2] - before[3 * left + 2])).toBeLessThan(1e-9);
    for (let k = 0; k < before.length / 3; k++) if (k !== left) expect(moved(before, after, k)).toBe(0);
    expect(errors).toEqual([]);
  });

  it('in track mode Tab and Esc act on the three tracked points', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    await page.keyboard.press('t');
    await page.waitForFunction(() => (window.ikTrack?.solves() ?? 0) > 0);
    const tracked = () => page.evaluate(() => window.ikTrack?.selected() ?? null);
    expect(await tracked()).toBe(0); // the head
    await page.keyboard.press('Tab');
    expect(await tracked()).toBe(1);
    await page.keyboard.press('Tab');
    await page.keyboard.press('Tab');
    expect(await tracked()).toBe(0);
    await page.keyboard.press('Shift+Tab');
    expect(await tracked()).toBe(2);
    expect(await selected(page)).toBeNull(); // the drag mode's targets are put away meanwhile
    await page.keyboard.press('Escape');
    expect(await tracked()).toBeNull();

    // A click on a tracked point's handle takes the gizmo again.
    const hand = (await page.evaluate(() => window.ikTrack!.pointScreen(1)))!;
    await page.mouse.click(hand.x, hand.y);
    await page.waitForFunction(() => window.ikTrack?.selected() === 1);
    await page.keyboard.press('t');
    expect(await page.evaluate(() => window.ikTrack?.active())).toBe(false);
    expect(errors).toEqual([]);
  });
});
