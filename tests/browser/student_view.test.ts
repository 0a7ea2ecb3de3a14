// What a student and a teacher see (issue 33), in Chromium at 1280x800.
// 1. Step mode tells the truth after a drag: on the knight, hand.L selected, S pressed (step mode
//    on), its target dragged up 120 px: the stats say the pose is not solved for the new target,
//    with the hand's real distance from it, until S takes an iteration towards it.
// Writes test-results/step-mode-after-drag.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames, resultsDir } from './harness.js';
import { dragTargetAlongY, effectorNamed, gotoRig, selectTarget, stat, statText, tipAt, targetAt, usePageServer } from './page_helpers.js';

const env = usePageServer();

describe('what a student sees', () => {
  it('step mode: a dragged target shows the pose as not solved, with its real error, until S', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await effectorNamed(page, /^hand\.L$/);
    await selectTarget(page, hand);
    await page.keyboard.press('s'); // step mode on, one iteration (the hand is on its target: nothing to do)
    await page.waitForFunction(() => document.getElementById('step-info')?.dataset.iterations !== undefined);
    const px = await page.evaluate(() => window.ikPage?.pixelsPerUnit() ?? NaN);
    await dragTargetAlongY(page, hand, 120 / px);
    await renderedFrames(page, 3);
    const target = await targetAt(page, hand), tip = await tipAt(page, hand);
    const distance = Math.hypot(target[0] - tip[0], target[1] - tip[1], target[2] - tip[2]);
    expect(distance * px).toBeGreaterThan(100); // the hand stayed where it was: step mode solves nothing by itself
    await page.waitForFunction(() => document.querySelector('[data-stat="status"]')?.textContent === 'not solved yet: press S');
    await page.waitForFunction((d) => Math.abs(Number(document.querySelector('[data-stat="tipDistance"]')?.getAttribute('data-value')) - d) < 1e-9 * (1 + d), distance);
    expect(await statText(page, 'tipDistance')).toMatch(/\(1\d\d\.\d px\)$/);
    expect(Number(await stat(page, 'E'))).toBeCloseTo((distance * distance) / 2, 6);
    expect(await statText(page, 'iterations')).toBe('0');
    expect(await statText(page, 'ms')).toBe('–');
    expect(await page.textContent('#step-info')).toMatch(/^The targets moved: press S/);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'step-mode-after-drag.png') });
    // One S: an iteration towards the new target, and the stats say so.
    await page.keyboard.press('s');
    await page.waitForFunction(() => document.querySelector('[data-stat="status"]')?.textContent !== 'not solved yet: press S');
    expect(await statText(page, 'iterations')).toBe('1');
    expect(await page.textContent('#step-info')).toMatch(/iteration 1: E/);
    expect(Number(await stat(page, 'tipDistance'))).toBeLessThan(distance);
    expect(errors).toEqual([]);
  });
});
