// Track mode on the page, on the project character: the Track panel's "track mode" box puts
// three gizmos on the head and hands; the left hand's gizmo dragged with the mouse, the avatar's
// left hand ends on it (within 0.1% of the height, δ) while the head and the right hand stay on
// theirs and the feet stay where they were planted; leaving the mode brings the drag mode's rig
// back as it was (its targets can be clicked again) and frees the avatar. "play clip" plays reach_wave on a faint ghost beside the
// avatar, and the avatar's head and hands follow the ghost's over the frames; leaving frees what
// the clip made. A rig that is no humanoid (the lamp) is not offered track mode, and says why.
// "enter VR" shows only where navigator.xr supports immersive-vr (a scripted navigator.xr here; no
// headset: the XR poses' path is tests/page/xr_tracking.test.ts), and a session that fails says so.
// Screenshots of both go to test-results/ (track-mode.png, track-clip.png).
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { nextFrame, openPage, renderedFrames, resultsDir } from './harness.js';
import { gotoRig, panelControl, selectTarget, usePageServer } from './page_helpers.js';

const env = usePageServer();

/** Distance between point i of `a` and point j of `b` (3 numbers per point). */
function distance(a: number[], i: number, b: number[], j = i): number {
  return Math.hypot(a[3 * i] - b[3 * j], a[3 * i + 1] - b[3 * j + 1], a[3 * i + 2] - b[3 * j + 2]);
}

/** Saves a screenshot as `name` in test-results/. */
async function screenshot(page: Page, name: string): Promise<void> {
  mkdirSync(resultsDir, { recursive: true });
  await page.screenshot({ path: join(resultsDir, name) });
}

/** Presses the panel's "play clip" (the clip menu shows clip `index`) and waits until it plays. */
async function playClip(page: Page, index: number): Promise<void> {
  await (await panelControl(page, /^play clip$/)).locator('button').click();
  await page.waitForFunction((i) => window.ikTrack?.playingClip() === i && window.ikTrack.source() === 'clip', index);
}

/** Ticks the panel's "track mode" box and waits for the avatar's first solve. */
async function enterTrackMode(page: Page): Promise<void> {
  await (await panelControl(page, /^track mode/)).locator('input').click();
  await page.waitForFunction(() => (window.ikTrack?.solves() ?? 0) > 0);
}

describe('track mode', () => {
  it('a hand gizmo dragged: the hand reaches its point within δ, the head and the other hand stay, the feet stay planted; leaving restores the drag mode', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    expect(await page.evaluate(() => window.ikTrack?.problem())).toBe(null);
    const before = await page.evaluate(() => ({
      angles: window.ikPage!.angles(),
      targets: window.ikPage!.targets(),
      alive: window.ikPage!.alive(),
    }));
    await enterTrackMode(page);
    const h = await page.evaluate(() => window.ikTrack!.height());
    const delta = 1e-3 * h;
    const standing = await page.evaluate(() => window.ikTrack!.standingTips());

    // Put the gizmo on the left hand (a click on its handle), then drag it in and up with the mouse.
    const hand = await page.evaluate(() => window.ikTrack!.pointScreen(1));
    if (!hand) throw new Error('no left-hand handle');
    await page.mouse.click(hand.x, hand.y);
    await page.waitForFunction(() => window.ikTrack?.selected() === 1);
    const start = await page.evaluate(() => window.ikTrack!.points());
    await page.mouse.move(hand.x, hand.y);
    await page.mouse.down();
    for (let i = 1; i <= 15; i++) {
      await page.mouse.move(hand.x - 6 * i, hand.y - 4 * i);
      await nextFrame(page);
    }
    await page.mouse.up();
    const handOff = () =>
      page.evaluate(() => {
        const t = window.ikTrack!,
          tips = t.tips(),
          p = t.points();
        return Math.hypot(tips[3] - p[3], tips[4] - p[4], tips[5] - p[5]);
      });
    await page
      .waitForFunction(
        (d) => {
          const t = window.ikTrack!,
            tips = t.tips(),
            p = t.points();
          return Math.hypot(tips[3] - p[3], tips[4] - p[4], tips[5] - p[5]) < d;
        },
        delta,
        { timeout: 10_000 },
      )
      .catch(async (e: unknown) => {
        const status = (await page.textContent('.track-status')) ?? '';
        throw new Error(
          `the hand is ${(await handOff()).toExponential(2)} off its point after 10 s (δ ${delta.toExponential(2)}); status: ${status}`,
          { cause: e },
        );
      });
    const points = await page.evaluate(() => window.ikTrack!.points());
    const tips = await page.evaluate(() => window.ikTrack!.tips());
    expect(distance(points, 1, start)).toBeGreaterThan(0.05 * h); // the hand's point moved 5% of the height or more
    expect(distance(points, 0, start)).toBe(0); // the others did not move
    expect(distance(points, 2, start)).toBe(0);
    for (const k of [0, 1, 2]) expect(distance(tips, k, points), `tracked point ${k}`).toBeLessThan(delta);
    for (const k of [3, 4]) expect(distance(tips, k, standing), `foot ${k - 3}`).toBeLessThan(delta);
    expect(await page.getAttribute('.track-status', 'data-reached')).toBe('true');
    await renderedFrames(page);
    await screenshot(page, 'track-mode.png');

    // Leaving: the drag mode's pose and targets as they were, the avatar freed.
    await (await panelControl(page, /^track mode/)).locator('input').click();
    await page.waitForFunction(() => window.ikTrack?.active() === false);
    await renderedFrames(page);
    const after = await page.evaluate(() => ({
      angles: window.ikPage!.angles(),
      targets: window.ikPage!.targets(),
      alive: window.ikPage!.alive(),
    }));
    expect(after.angles).toEqual(before.angles);
    expect(after.targets).toEqual(before.targets);
    expect(after.alive.sessions).toBe(before.alive.sessions);
    await selectTarget(page, 2); // the drag mode's targets are back where clicks find them
    expect(errors).toEqual([]);
  });

  it('play clip: the ghost plays reach_wave beside the avatar, the avatar follows its head and hands with its feet planted; leaving frees the ghost', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const names = await page.evaluate(() => window.ikTrack!.clipNames());
    expect(names).toEqual(expect.arrayContaining(['idle', 'reach_wave', 'crouch', 'look_around']));
    await (await panelControl(page, /^clip$/)).locator('select').selectOption({ label: 'reach_wave' });
    await playClip(page, names.indexOf('reach_wave'));
    expect(await page.evaluate(() => window.ikTrack!.active())).toBe(true); // play clip turned track mode on
    const h = await page.evaluate(() => window.ikTrack!.height());
    const delta = 1e-3 * h;
    const offset = (await page.evaluate(() => window.ikTrack!.ghostOffset()))!;
    expect(Math.hypot(...offset)).toBeCloseTo(h, 6); // one height to the side: the character faces +Z, its left is +X
    expect(offset[0]).toBeCloseTo(h, 6);

    const worst: number[] = [],
      ghostRightHand: number[][] = [];
    let feet = 0;
    for (let f = 0; f < 40; f++) {
      await nextFrame(page);
      const { ghost, tips, planted } = await page.evaluate(() => ({
        ghost: window.ikTrack!.ghostTips()!,
        tips: window.ikTrack!.tips(),
        planted: window.ikTrack!.plantedFeet(),
      }));
      worst.push(Math.max(...[0, 1, 2].map((k) => distance(tips, k, ghost))) / delta);
      ghostRightHand.push(ghost.slice(6, 9));
      planted.forEach((at, k) => (feet = Math.max(feet, at ? distance(tips, 3 + k, at, 0) / delta : 0)));
    }
    const travel = Math.max(...ghostRightHand.map((p) => distance(p, 0, ghostRightHand[0])));
    expect(travel).toBeGreaterThan(0.05 * h); // the ghost's waving hand moved, and the avatar's with it
    expect(Math.max(...worst), worst.map((x) => x.toFixed(2)).join(' ')).toBeLessThan(10); // within 1% of the height on every frame
    expect([...worst].sort((a, b) => a - b)[20]).toBeLessThan(1); // within δ on most (the median)
    expect(feet).toBeLessThan(1);
    await screenshot(page, 'track-clip.png');

    await (await panelControl(page, /^stop clip$/)).locator('button').click();
    await page.waitForFunction(() => window.ikTrack?.source() === 'gizmos' && window.ikTrack.playingClip() === null);
    await page.keyboard.press('t');
    await page.waitForFunction(() => window.ikTrack?.active() === false);

    // The same again, left while playing: what the second play made (the avatar, the ghost) is freed.
    // (The first play counts as warm-up: some of the gizmo's shapes are first drawn, then kept.)
    await renderedFrames(page);
    const before = await page.evaluate(() => window.ikPage!.alive());
    await playClip(page, names.indexOf('reach_wave'));
    await renderedFrames(page, 5);
    await page.keyboard.press('t');
    await page.waitForFunction(() => window.ikTrack?.active() === false && window.ikTrack.playingClip() === null);
    await renderedFrames(page);
    expect(await page.evaluate(() => window.ikPage!.alive())).toEqual(before);
    expect(errors).toEqual([]);
  });

  it('is offered for recognised humanoids only: the lamp says why not; the knight tracks, with no clips to play', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    const box = (await panelControl(page, /^track mode/)).locator('input');
    expect(await box.isDisabled()).toBe(true);
    expect(await page.textContent('.track-status')).toBe('lamp is not recognised as a humanoid');
    await page.keyboard.press('t');
    await page.waitForFunction(() => document.getElementById('message')?.dataset.kind === 'error');
    expect(await page.textContent('#message')).toBe('track mode: lamp is not recognised as a humanoid');
    expect(await page.evaluate(() => window.ikTrack!.active())).toBe(false);

    await gotoRig(page, env.url, 'knight');
    expect(await page.evaluate(() => window.ikTrack!.clipNames())).toEqual([]);
    expect(await (await panelControl(page, /^play clip$/)).locator('button').isDisabled()).toBe(true);
    await enterTrackMode(page);
    await page.waitForFunction(() => window.ikTrack?.lastSolve()?.reached === true);
    expect(errors).toEqual([]);
  });

  it('offers "enter VR" only where navigator.xr supports immersive-vr; a session that cannot start is reported', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const vr = () => panelControl(page, /^enter VR$/);
    await renderedFrames(page, 5); // isSessionSupported has answered
    expect(await (await vr()).isVisible()).toBe(false); // headless Chromium has no immersive VR

    // A browser that says it has a headset, whose session then fails to start.
    await page.addInitScript(() => {
      const xr = {
        isSessionSupported: async (mode: string) => mode === 'immersive-vr',
        requestSession: async () => Promise.reject(new Error('no headset is connected')),
      };
      Object.defineProperty(navigator, 'xr', { value: xr });
    });
    await gotoRig(page, env.url, 'character');
    await (await vr()).waitFor({ state: 'visible' });
    await (await vr()).locator('button').click();
    await page.waitForFunction(() => document.getElementById('message')?.dataset.kind === 'error');
    expect(await page.textContent('#message')).toBe('could not enter VR: no headset is connected');
    expect(await page.evaluate(() => window.ikTrack!.source())).toBe('gizmos'); // track mode went on, the gizmos drive it
    expect(errors).toEqual([]);
  });
});
