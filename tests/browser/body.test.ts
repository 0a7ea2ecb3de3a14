// The body moves as a body, as a user drags from the rest pose with real mouse events:
// a hand pulled past its reach leaves the head and the other hand on their targets at every
// frame and says "out of reach"; the knight's hand turned 88 degrees keeps its position and names
// the orientation when that cannot be met. With the panel's "strict priority" off, the pinned
// effectors are pulled off their targets again. The head bowed leaves the pinned hands' places and
// frames as they were. Writes docs/out-of-reach.png when UPDATE_SCREENSHOT=1.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { nextFrame, openPage, renderedFrames, repoRoot } from './harness.js';
import {
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  statText,
  targetScreen,
  usePageServer,
  waitForSettled,
} from './page_helpers.js';

const env = usePageServer();

async function tipErrors(page: Page): Promise<number[]> {
  return page.evaluate(() => {
    const p = window.ikPage;
    return (p?.effectors() ?? []).map((_, k) => p?.effectorError(k) ?? NaN);
  });
}

async function screenshot(page: Page, name: string): Promise<void> {
  await renderedFrames(page);
  const shot = process.env.UPDATE_SCREENSHOT === '1' ? `docs/${name}` : `test-results/${name}`;
  mkdirSync(join(repoRoot, shot, '..'), { recursive: true });
  await page.screenshot({ path: join(repoRoot, shot) });
}

describe('the body moves as a body', () => {
  it("the character's left hand pulled past its reach: the head and the right hand stay on target at every frame", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const left = await effectorNamed(page, /LeftHand$/);
    const pinned = [await effectorNamed(page, /Head$/), await effectorNamed(page, /RightHand$/)];
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    await selectTarget(page, left);
    // Outward along the arm on screen, about 1 unit past its reach (the character is 1.8 units tall).
    const from = await targetScreen(page, left);
    const start = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, left);
    if (!start) throw new Error('no target');
    const out = await page.evaluate(
      ([x, y, z]) => window.ikPage?.worldToScreen([x + 1, y, z]) ?? null,
      start as [number, number, number],
    );
    if (!out) throw new Error('no screen point');
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    let worst = 0;
    const steps = 30,
      kinds: string[] = [];
    for (let i = 1; i <= steps; i++) {
      await page.mouse.move(from.x + ((out.x - from.x) * i) / steps, from.y + ((out.y - from.y) * i) / steps);
      await nextFrame(page);
      const e = await tipErrors(page);
      for (const k of pinned) worst = Math.max(worst, e[k]);
      kinds.push((await page.getAttribute('[data-stat="status"]', 'data-kind')) ?? '');
    }
    await page.mouse.up();
    await waitForSettled(page);
    const e = await tipErrors(page);
    for (const k of pinned) worst = Math.max(worst, e[k]);
    expect(worst).toBeLessThan(tolerance);
    expect(e[left]).toBeGreaterThan(0.3); // far out of reach
    expect(await statText(page, 'status')).toBe('out of reach (closest point)');
    // The words settle at once: "out of reach" from the frame the hand leaves its reach, not seconds of "time budget".
    console.log(`[status] pulling the hand past its reach, per step: ${kinds.join(' ')}`);
    const firstOut = kinds.indexOf('out-of-reach');
    expect(firstOut).toBeGreaterThanOrEqual(0);
    expect(kinds.slice(firstOut).filter((k) => k === 'budget').length).toBeLessThanOrEqual(3);
    await screenshot(page, 'out-of-reach.png');
    // The panel's "strict priority" off: the least-squares point of all targets pulls the others off theirs.
    await (await panelControl(page, /^strict priority$/)).locator('input').click();
    await page.waitForFunction(
      ([ks, tol]) => ks.some((k) => (window.ikPage?.effectorError(k) ?? 0) > 3 * tol),
      [pinned, tolerance] as const,
      { timeout: 20_000 },
    );
    expect(errors).toEqual([]);
  });

  it("the character's right hand across the chest towards the left shoulder in 40 steps, each frame solved to its iteration cap: no frame moves a joint more than 5% of the height", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const hand = await selectTarget(page, await effectorNamed(page, /RightHand$/));
    await solveEachFrameToItsCap(page);
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    const { shoulder, height } = await page.evaluate(() => {
      const p = window.ikPage!;
      const names = p.boneNames();
      const b = p.bounds()!;
      return { shoulder: p.boneTip(names.findIndex((n) => /LeftShoulder$/.test(n)))!, height: b.max[1] - b.min[1] };
    });
    const joints = async (): Promise<number[][]> =>
      page.evaluate(() => {
        const p = window.ikPage!;
        return p.boneNames().map((_, i) => p.boneTip(i) ?? [NaN, NaN, NaN]);
      });
    // 144 px towards the left shoulder on screen (a user's gesture: 24 steps of 6 px), in 40 steps.
    const from = await targetScreen(page, hand);
    const aim = await page.evaluate((q) => window.ikPage?.worldToScreen(q) ?? null, shoulder);
    if (!aim) throw new Error('no screen point');
    const length = Math.hypot(aim.x - from.x, aim.y - from.y);
    const to = {
      x: from.x + ((aim.x - from.x) * Math.min(144, length)) / length,
      y: from.y + ((aim.y - from.y) * Math.min(144, length)) / length,
    };
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    let before = await joints(),
      worst = 0,
      worstStep = 0;
    for (let i = 1; i <= 40; i++) {
      await page.mouse.move(from.x + ((to.x - from.x) * i) / 40, from.y + ((to.y - from.y) * i) / 40);
      await nextFrame(page);
      const now = await joints();
      now.forEach((q, j) => {
        const d = Math.hypot(q[0] - before[j][0], q[1] - before[j][1], q[2] - before[j][2]);
        if (d > worst) {
          worst = d;
          worstStep = i;
        }
      });
      before = now;
    }
    await page.mouse.up();
    await waitForSettled(page);
    console.log(
      `[across] ${Math.min(144, length).toFixed(0)} px of ${length.toFixed(0)}: largest joint move in one frame ${((100 * worst) / height).toFixed(2)}% of the height (step ${worstStep}); ${await statText(page, 'status')}`,
    );
    expect(worst / height).toBeLessThan(0.05);
    expect((await tipErrors(page))[hand]).toBeLessThan(tolerance);
    await screenshot(page, 'hand-across-chest.png');
    expect(errors).toEqual([]);
  });

  it("the knight's hand turned 88 degrees with the rotate ring keeps its position; the status names the orientation", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    await page.keyboard.press('e');
    await page.evaluate(() => window.ikPage?.turnGizmo([1, 0, 0], 88, 16));
    const reason = await waitForSettled(page);
    const e = await tipErrors(page);
    for (const d of e) expect(d).toBeLessThan(tolerance); // the turned hand's position too
    const off = await page.evaluate((k) => window.ikPage?.orientationError(k) ?? NaN, hand);
    const status = await statText(page, 'status');
    if (off > 0.5) expect(status, reason).toBe('orientation out of reach');
    else expect(status).toBe('on target');
    expect(errors).toEqual([]);
  });
});

/**
 * No time budget: each frame solves to its iteration cap, as on a fast machine. A frame cut by its
 * 3 ms budget takes another path, which depends on the machine's load (the hand across the chest
 * moved a joint 3.3% of the height one run and over 5% another).
 */
async function solveEachFrameToItsCap(page: Page): Promise<void> {
  await page.evaluate(() => {
    const settings = window.ikPage?.settings();
    if (settings) settings.timeBudgetMs = 0;
  });
}

/** The angle, degrees, between two unit quaternions [x, y, z, w]. */
function turnDeg(a: readonly number[], b: readonly number[]): number {
  const d = Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return (2 * Math.acos(Math.min(1, d)) * 180) / Math.PI;
}

/**
 * Drags the character's head target down and forward (a bow) in 30 steps and returns the most
 * either hand turned from its frame at the drag's start, degrees, and its largest position error.
 */
async function bowWithPinnedHands(page: Page): Promise<{ turn: number; drift: number }> {
  const head = await effectorNamed(page, /Head$/);
  const hands = [await effectorNamed(page, /LeftHand$/), await effectorNamed(page, /RightHand$/)];
  await selectTarget(page, head);
  const start = await page.evaluate((k) => window.ikPage?.targetPosition(k) ?? null, head);
  if (!start) throw new Error('no target');
  const from = await targetScreen(page, head);
  const to = await page.evaluate(
    ([x, y, z]) => window.ikPage?.worldToScreen([x, y - 0.3, z + 0.3]) ?? null,
    start as [number, number, number],
  );
  if (!to) throw new Error('no screen point');
  // After the next frame: the hands' frames and position errors (one round trip a step).
  const handsAfterFrame = async (): Promise<{ turns: number[][]; errors: number[] }> =>
    page.evaluate(async (ks) => {
      await new Promise<void>((done) => requestAnimationFrame(() => done()));
      const p = window.ikPage;
      return {
        turns: ks.map((k) => p?.tipRotation(k) ?? [0, 0, 0, 1]),
        errors: ks.map((k) => p?.effectorError(k) ?? NaN),
      };
    }, hands);
  const before = (await handsAfterFrame()).turns;
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  let turn = 0,
    drift = 0;
  for (let i = 1; i <= 30; i++) {
    await page.mouse.move(from.x + ((to.x - from.x) * i) / 30, from.y + ((to.y - from.y) * i) / 30);
    const now = await handsAfterFrame();
    hands.forEach((_, j) => (turn = Math.max(turn, turnDeg(before[j], now.turns[j]))));
    for (const e of now.errors) drift = Math.max(drift, e);
  }
  await page.mouse.up();
  await waitForSettled(page);
  return { turn, drift };
}

describe('pinned means pinned', () => {
  // Two bows of 30 mouse moves, each frame a carry solved to its cap: 25 s here, over 60 s once on CI.
  it(
    "the character's head bowed: the pinned hands keep their place and their turn at every frame",
    { timeout: 180_000 },
    async (ctx) => {
      const { page, errors } = await openPage(env.browser, ctx);
      await gotoRig(page, env.url, 'character');
      const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
      const pinned = await bowWithPinnedHands(page);
      console.log(
        `[pinned] head bowed, hands pinned: turned at most ${pinned.turn.toFixed(3)} deg, drift ${pinned.drift.toExponential(2)}`,
      );
      expect(pinned.drift).toBeLessThan(tolerance);
      expect(pinned.turn).toBeLessThan(0.5);
      // The panel's "pin orientations" off: only places are pinned, and the hands turn with the body.
      await page.keyboard.press('r');
      await (await panelControl(page, /^pin orientations$/)).locator('input').click();
      const free = await bowWithPinnedHands(page);
      console.log(`[pinned] the same with "pin orientations" off: turned ${free.turn.toFixed(1)} deg`);
      expect(free.turn).toBeGreaterThan(5);
      expect(errors).toEqual([]);
    },
  );
});
