// Compare runs in a Web Worker: on the knight with a hand dragged out of reach and unlimited
// restarts, every method runs to its time budget, about 2 s in all;
// meanwhile the page keeps drawing frames (no gap near one method's budget, as a main-thread solve
// would leave), the progress line names the method solving, rows appear one by one, and the table
// ends with one row per method. Cancel stops a long compare at once, keeps the rows shown, and
// the live solve takes drags again.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { openPage } from './harness.js';
import { dragBy, effectorNamed, gotoRig, panelControl, selectTarget, usePageServer, waitForConvergence, waitForSettled } from './page_helpers.js';

const env = usePageServer();

/** Types `value` into the panel's number field labelled `name`. */
async function setNumber(page: Page, name: RegExp, value: number): Promise<void> {
  const input = (await panelControl(page, name)).locator('input[type="text"], input[type="number"]').last();
  await input.fill(String(value));
  await input.press('Enter');
}

/** The knight with its left hand dragged far out of reach and compare set to run every method to `budgetMs`. */
async function longCompare(page: Page, budgetMs: number): Promise<number> {
  await gotoRig(page, env.url, 'knight');
  const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
  await dragBy(page, hand, 300, -250);
  await waitForSettled(page);
  await setNumber(page, /^compare: ms budget/, budgetMs);
  // Restarts beyond the panel's 20: every method restarts until its budget ends.
  await page.evaluate(() => Object.assign(window.ikPage!.settings(), { restarts: 1e9 }));
  return hand;
}

/** Counts animation frames from now on, keeping the longest gap between two (ms). */
async function watchFrames(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as { frames: { count: number; gap: number; last: number } };
    w.frames = { count: 0, gap: 0, last: performance.now() };
    const tick = (t: number): void => {
      w.frames.count++;
      w.frames.gap = Math.max(w.frames.gap, t - w.frames.last);
      w.frames.last = t;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
}

const frames = (page: Page) => page.evaluate(() => (window as unknown as { frames: { count: number; gap: number } }).frames);
const state = (page: Page) => page.getAttribute('#compare', 'data-state');

describe('compare in a worker', () => {
  it('keeps the page drawing during a 2 s compare; rows come one by one, one per method', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await longCompare(page, 400);
    await watchFrames(page);
    const t0 = Date.now();
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'running');
    await page.waitForFunction(() => /solving with \w+: 1 of 5/.test(document.querySelector('.compare-status')?.textContent ?? ''), null, { timeout: 10_000 });
    expect(await page.locator('#compare .compare-table tbody tr').count()).toBe(1);
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state !== 'running', null, { timeout: 30_000 });
    const seconds = (Date.now() - t0) / 1000;
    const f = await frames(page);
    console.log(`compare: ${seconds.toFixed(2)} s, ${f.count} frames drawn, longest gap ${f.gap.toFixed(0)} ms`);
    expect(await state(page)).toBe('done');
    expect(seconds).toBeGreaterThan(1.5);
    expect(f.count).toBeGreaterThan(10 * seconds);
    expect(f.gap).toBeLessThan(200); // a method solving on the main thread would block for its 400 ms
    expect(await page.locator('#compare .compare-table tbody tr').count()).toBe(5);
    expect(await page.textContent('.compare-status')).toMatch(/^done in \d+\.\d s$/);
    expect(errors).toEqual([]);
  });

  it('cancel stops a long compare at once, keeps the rows shown, and the live solve goes on', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    const hand = await longCompare(page, 3000);
    await page.keyboard.press('c');
    await page.waitForFunction(() => /solving with/.test(document.querySelector('.compare-status')?.textContent ?? ''));
    const t0 = Date.now();
    await page.locator('.compare-cancel').click();
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'cancelled', null, { timeout: 2_000 });
    expect(Date.now() - t0).toBeLessThan(1000);
    expect(await page.textContent('.compare-status')).toMatch(/^cancelled after \d+\.\d s \(0 of 5 methods done\)$/);
    expect(await page.locator('.compare-cancel').isHidden()).toBe(true);

    // The live solve takes drags again: the out-of-reach drag undone, a reachable one is solved.
    await page.keyboard.press('Control+z');
    await page.waitForFunction((k) => window.ikPage!.effectorError(k) < window.ikPage!.tipTolerance(), hand);
    await dragBy(page, hand, 30, -70);
    await waitForConvergence(page);

    // C while a compare runs cancels it too.
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'running');
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'cancelled', null, { timeout: 2_000 });
    expect(errors).toEqual([]);
  });
});
