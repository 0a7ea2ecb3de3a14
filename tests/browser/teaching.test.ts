// The page as a teaching tool, in Chromium at 1280x800: the panel fits the screen (its folders open
// one at a time, every folder title in view without scrolling, Teaching's last control too once
// opened); numbers show 3 significant digits; paper mode is named wherever its results show (the
// stats' method, step mode's line, the help's compare line); the help describes the settings in
// use; stop reasons read as words with the code in the tooltip; the iteration axis is logarithmic
// and can be made linear; the timer note stays hidden on a cross-origin isolated page.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames } from './harness.js';
import { dragTowardsRoot, gotoRig, panelControl, usePageServer, waitForSettled } from './page_helpers.js';

const env = usePageServer();

/** The bounding box of `selector`'s first match, client pixels. */
async function box(page: Page, selector: string): Promise<{ top: number; bottom: number }> {
  const b = await page.locator(selector).first().boundingBox();
  if (!b) throw new Error(`${selector} is not shown`);
  return { top: b.y, bottom: b.y + b.height };
}

/** Significant digits of a number written in plain or exponential notation. */
const significant = (text: string): number => text.replace(/e.*$/i, '').replace(/[-.]/g, '').replace(/^0+/, '').length;

describe('teaching clarity', () => {
  it('the panel fits the screen: one folder open at a time, every folder title in view, Teaching reachable', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const viewport = page.viewportSize()!;
    const titles = page.locator('.lil-gui .lil-gui > .lil-title');
    expect(await titles.allTextContents()).toEqual(['Rig', 'Pose', 'Solver (every frame)', 'Teaching']);
    for (let i = 0; i < 4; i++)
      expect((await titles.nth(i).boundingBox())!.y + 20).toBeLessThanOrEqual(viewport.height);
    expect(await page.locator('#side').evaluate((el) => el.scrollTop)).toBe(0);

    await titles.nth(3).click();
    await page.waitForFunction(() => document.querySelectorAll('.lil-gui .lil-gui:not(.lil-closed)').length === 1);
    expect(await titles.nth(0).getAttribute('aria-expanded')).toBe('false');
    await page.waitForTimeout(400); // lil-gui's open animation
    const help = await box(page, '.lil-controller:has(.lil-name:text("keyboard help (?)"))');
    expect(help.bottom).toBeLessThanOrEqual(viewport.height);
    expect(errors).toEqual([]);
  });

  it('numbers show 3 significant digits; stop reasons are words with the code in the tooltip', async (ctx) => {
    const { page } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    for (const name of [/^on target within/, /^‖∇E‖ tolerance/]) {
      const value = await (await panelControl(page, name)).locator('input').inputValue();
      expect(Number(value)).toBeGreaterThan(0);
      expect(significant(value), value).toBeLessThanOrEqual(3);
    }
    await dragTowardsRoot(page, 0, 0.3);
    await waitForSettled(page);
    for (const key of ['E', 'gradNorm', 'ms']) {
      const text = (await page.textContent(`[data-stat="${key}"]`)) ?? '';
      expect(significant(text), `${key}: ${text}`).toBeLessThanOrEqual(3);
    }
    const status = page.locator('[data-stat="status"]');
    expect(await status.textContent()).not.toMatch(/_/);
    expect(await status.getAttribute('title')).toMatch(/stop reason: [a-z_]+/);
  });

  it('paper mode is named in the stats, step mode and the help; the help follows the compare settings', async (ctx) => {
    const { page } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp', '&method=gd');
    await page.keyboard.press('?');
    const compareLine = () => page.locator('#help tr', { hasText: /^Ccompare/ }).textContent();
    expect(await compareLine()).toMatch(/from the rest pose: 1000 ms and 100000 iterations each, 0 restarts/);
    expect(await compareLine()).not.toMatch(/paper/);
    await page.keyboard.press('Escape');

    await (await panelControl(page, /^paper mode/)).locator('input').check();
    await (await panelControl(page, /^compare: start from$/)).locator('select').selectOption('current pose');
    await dragTowardsRoot(page, 0, 0.3);
    await waitForSettled(page);
    expect(await page.textContent('[data-stat="method"]')).toBe('gd (paper mode)');
    await page.keyboard.press('?');
    expect(await compareLine()).toMatch(/from the current pose, as the report ran them \(paper mode\)/);
    await page.keyboard.press('Escape');

    await (await panelControl(page, /^step mode$/)).locator('input').check();
    await dragTowardsRoot(page, 0, 0.2);
    await page.keyboard.press('s');
    await page.waitForFunction(() => /iteration 1/.test(document.getElementById('step-info')?.textContent ?? ''));
    expect(await page.textContent('#step-info')).toMatch(
      /^gradient descent \(paper mode\), iteration 1: .*stopped: .*\[[a-z_]+\]|^gradient descent \(paper mode\), iteration 1: .*running/,
    );
  });

  it('the iteration axis is logarithmic, and linear with the box unticked; no timer note when isolated', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    await page.locator('#side > .plot').scrollIntoViewIfNeeded();
    const plot = page.locator('#side > .plot');
    expect(await plot.getAttribute('data-axis')).toBe('log');
    expect(await plot.locator('.uplot').count()).toBe(1);
    await plot.locator('.plot-axis input').uncheck();
    await renderedFrames(page);
    expect(await plot.getAttribute('data-axis')).toBe('linear');
    expect(await plot.locator('.uplot').count()).toBe(1);

    expect(await page.evaluate(() => window.crossOriginIsolated)).toBe(true);
    expect(await page.locator('[data-stat="timer"]').count()).toBe(0);
    expect(errors).toEqual([]);
  });
});
