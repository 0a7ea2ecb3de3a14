// The posed .glb round trip, as a user does it on the character: the
// left foot's target dragged up 30% of the height with the mouse (the gizmo's up arrow), the posed
// model saved through the panel (a real download) and opened through the file input. Reopened, the
// joint limits are the original's (1e-5 degrees: float32 bind matrices), the importer warns of no
// limb bent the other way and no node out of the bind pose, and the rig opens posed: the left foot
// where it was saved, the right foot where it stands (within δ, the page's "on target within").
// Dragged back down with the mouse, the foot ends within δ of where it stood, on target; R puts it
// back at its rest place. Writes test-results/posed-roundtrip.png (the reopened posed model).
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragTargetAlongY,
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  statText,
  targetAt,
  tipAt,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type Point = [number, number, number];

const distance = (a: Point, b: Point): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** Largest difference between two limit lists (equal infinities count as 0); Infinity when the lengths differ. */
function worstDifference(a: number[], b: number[]): number {
  if (a.length !== b.length) return Infinity;
  return a.reduce((w, x, i) => Math.max(w, x === b[i] ? 0 : Math.abs(x - b[i])), 0);
}

describe('the posed .glb round trip', () => {
  it('reopened, the limits are equal and the rig opens posed; the foot goes back down to within δ, and R to its rest', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const left = await effectorNamed(page, /LeftFoot$/);
    const right = await effectorNamed(page, /RightFoot$/);
    const names = await page.evaluate(() =>
      (window.ikPage?.effectors() ?? []).map((b) => window.ikPage?.boneNames()[b] ?? ''),
    );
    expect(names[left]).toMatch(/LeftFoot$/);
    expect(names[right]).toMatch(/RightFoot$/);
    const delta = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0); // δ: 0.1% of the size
    expect(delta).toBeGreaterThan(0);
    const height = await page.evaluate(() => {
      const b = window.ikPage?.bounds();
      return b ? b.max[1] - b.min[1] : NaN;
    });
    const limits = await page.evaluate(() => window.ikPage?.limits() ?? { lower: [], upper: [] });
    expect(limits.lower.length).toBeGreaterThan(0);
    const stood = await tipAt(page, left),
      rightStood = await tipAt(page, right);

    // 1. The left foot's target up 30% of the height with the mouse.
    await selectTarget(page, left);
    await dragTargetAlongY(page, left, 0.3 * height, 20);
    await waitForConvergence(page);
    const lifted = await targetAt(page, left);
    expect(lifted[1] - stood[1]).toBeGreaterThan(0.29 * height);
    const savedLeft = await tipAt(page, left),
      savedRight = await tipAt(page, right);
    expect(distance(savedLeft, lifted)).toBeLessThan(delta);
    expect(distance(savedRight, rightStood)).toBeLessThan(delta);

    // 2. Saved as .glb through the panel and opened through the file input.
    const save = (await panelControl(page, /^save posed model/)).locator('button');
    const [saved] = await Promise.all([page.waitForEvent('download'), save.click()]);
    expect(saved.suggestedFilename()).toBe('character-posed.glb');
    mkdirSync(resultsDir, { recursive: true });
    const file = join(resultsDir, 'character-posed.glb');
    await saved.saveAs(file);
    await page.setInputFiles('#rig-file', file);
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'character-posed' && document.getElementById('app')?.dataset.state === 'ready',
    );
    await renderedFrames(page, 3);

    // 3. The same limits, no warning of a limb bent the other way or nodes out of the bind pose, opened posed.
    const message = (await page.textContent('#message')) ?? '';
    console.log(`[posed round trip] reopened: "${message}"`);
    expect(message).not.toMatch(/bent the other way/);
    expect(message).not.toMatch(/not in the bind pose/);
    const again = await page.evaluate(() => window.ikPage?.limits() ?? { lower: [], upper: [] });
    const lowerOff = worstDifference(limits.lower, again.lower),
      upperOff = worstDifference(limits.upper, again.upper);
    expect(await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0)).toBeCloseTo(delta, 6);
    const left2 = await effectorNamed(page, /LeftFoot$/),
      right2 = await effectorNamed(page, /RightFoot$/);
    const openedLeft = await tipAt(page, left2),
      openedRight = await tipAt(page, right2);
    console.log(
      `[posed round trip] limits: lower off by ${lowerOff.toExponential(2)}°, upper by ${upperOff.toExponential(2)}° over ${again.lower.length} angles; ` +
        `reopened left foot ${(distance(openedLeft, savedLeft) / delta).toExponential(2)} δ from where it was saved, right foot ${(distance(openedRight, rightStood) / delta).toExponential(2)} δ from where it stands (δ = ${delta.toPrecision(3)})`,
    );
    expect(lowerOff).toBeLessThan(1e-5);
    expect(upperOff).toBeLessThan(1e-5);
    expect(distance(openedLeft, savedLeft)).toBeLessThan(delta);
    expect(distance(openedRight, rightStood)).toBeLessThan(delta);
    await waitForConvergence(page);

    // 6. (before the drag back) the reopened posed model as drawn.
    await renderedFrames(page);
    await page.screenshot({ path: join(resultsDir, 'posed-roundtrip.png') });

    // 4. Dragged back down with the mouse to where the foot stood at first.
    await selectTarget(page, left2);
    const from = await targetAt(page, left2);
    await dragTargetAlongY(page, left2, stood[1] - from[1], 20);
    await waitForConvergence(page);
    const down = await tipAt(page, left2),
      downTarget = await targetAt(page, left2);
    const pixels = await page.evaluate(() => window.ikPage?.pixelsPerUnit() ?? NaN);
    console.log(
      `[posed round trip] dragged back down: target ${(distance(downTarget, stood) / delta).toFixed(3)} δ from where the foot stood (${(distance(downTarget, stood) * pixels).toFixed(2)} px; δ is ${(delta * pixels).toFixed(2)} px), ` +
        `foot ${(distance(down, stood) / delta).toFixed(3)} δ; right foot ${(distance(await tipAt(page, right2), rightStood) / delta).toExponential(2)} δ`,
    );
    expect(distance(down, stood)).toBeLessThan(delta);
    expect(await statText(page, 'status')).toBe('on target');

    // 5. R: the bind pose, the left foot back at its rest place.
    await page.keyboard.press('r');
    await renderedFrames(page, 3);
    const reset = await tipAt(page, left2);
    console.log(
      `[posed round trip] after R: left foot ${(distance(reset, stood) / delta).toExponential(2)} δ from its rest place`,
    );
    expect(distance(reset, stood)).toBeLessThan(delta);
    expect(errors).toEqual([]);
  });
});
