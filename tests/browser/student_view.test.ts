// What a student and a teacher see, in Chromium at 1280x800.
// 1. Step mode tells the truth after a drag: on the knight, hand.L selected, S pressed (step mode
//    on), its target dragged up 120 px: the stats say the pose is not solved for the new target,
//    with the hand's real distance from it, until S takes an iteration towards it.
// 2. A compare right after a drag shows something: every method starts from the rest pose by
//    default and takes iterations towards the dragged target; its results sit in the side column,
//    clear of the view.
// 4. On a 390x844 phone the compare's results are readable in the expanded sheet.
// 5. A long note (the character's recognition message) is one line on a desktop and a phone, its
//    details behind a click, and it goes once a target is dragged.
// 6. The first view: the lamp's selected target shows over its shade and the gizmo, the side plot
//    says what will show there instead of an empty frame, and the first solve's time is a solve's,
//    not the warm-up's.
// 7. A compare on a busy machine: what blocked the page's main thread was the 3D view, drawn at
//    every animation frame though nothing in it moved (the character drawn in software: 50 ms a
//    frame, up to 290 ms with the cores busy); the compare's own messages, table and plot took
//    about 30 ms in all. A still view now draws one frame a second (a key press: one frame). Measured here with two
//    busy workers in the page: drawn frames, long tasks and frame gaps during a character compare.
// Writes test-results/step-mode-after-drag.png, compare-after-drag.png, phone-compare.png and lamp-first-view.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { type BrowserSession, launchBrowser, openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragTargetAlongY,
  dragTowardsRoot,
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  stat,
  statText,
  swipe,
  targetAt,
  targetScreen,
  tipAt,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

/** Whether two client rectangles overlap. */
const overlaps = (
  a: { x: number; y: number; width: number; height: number },
  b: { x: number; y: number; width: number; height: number },
): boolean => a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

const env = usePageServer();
let phone: BrowserSession;
beforeAll(async () => {
  phone = await launchBrowser(true); // 390x844, touch
});
afterAll(async () => {
  await phone?.close();
});

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
    const target = await targetAt(page, hand),
      tip = await tipAt(page, hand);
    const distance = Math.hypot(target[0] - tip[0], target[1] - tip[1], target[2] - tip[2]);
    expect(distance * px).toBeGreaterThan(100); // the hand stayed where it was: step mode solves nothing by itself
    await page.waitForFunction(
      () => document.querySelector('[data-stat="status"]')?.textContent === 'not solved yet: press S',
    );
    await page.waitForFunction(
      (d) =>
        Math.abs(Number(document.querySelector('[data-stat="tipDistance"]')?.getAttribute('data-value')) - d) <
        1e-9 * (1 + d),
      distance,
    );
    expect(await statText(page, 'tipDistance')).toMatch(/\(1\d\d\.\d px\)$/);
    expect(Number(await stat(page, 'E'))).toBeCloseTo((distance * distance) / 2, 6);
    expect(await statText(page, 'iterations')).toBe('0');
    expect(await statText(page, 'ms')).toBe('–');
    expect(await page.textContent('#step-info')).toMatch(/^The targets moved: press S/);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'step-mode-after-drag.png') });
    // One S: an iteration towards the new target, and the stats say so.
    await page.keyboard.press('s');
    await page.waitForFunction(
      () => document.querySelector('[data-stat="status"]')?.textContent !== 'not solved yet: press S',
    );
    expect(await statText(page, 'iterations')).toBe('1');
    expect(await page.textContent('#step-info')).toMatch(/iteration 1: E/);
    expect(Number(await stat(page, 'tipDistance'))).toBeLessThan(distance);
    expect(errors).toEqual([]);
  });

  it('a compare right after a drag: every method solves from the rest pose, its results beside the view', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragTowardsRoot(page, hand, 0.3);
    await waitForConvergence(page);
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
      timeout: 60_000,
    });
    expect(await page.textContent('#compare h2')).toMatch(/from the rest pose/);
    const iterations = await page.$$eval('#compare .compare-table tbody tr', (rows) =>
      rows.map((r) => Number((r as HTMLTableRowElement).cells[2].textContent)),
    );
    console.log(`[student] compare iterations: ${iterations.join(', ')}`);
    expect(iterations.length).toBe(5);
    for (const n of iterations) expect(n).toBeGreaterThan(0);
    const view = (await page.locator('#viewport').boundingBox())!,
      box = (await page.locator('#compare').boundingBox())!;
    expect(overlaps(view, box)).toBe(false);
    // The plot shows each method's E per iteration, not a dot: drawn with every history in it.
    await page.waitForFunction(() => {
      const plot = document.querySelector<HTMLElement>('#compare .plot');
      return plot?.dataset.state === 'drawn' && plot.dataset.empty === 'false';
    });
    expect(await page.locator('#compare .plot-note').isHidden()).toBe(true);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'compare-after-drag.png') });
    expect(errors).toEqual([]);
  });

  it('on a phone, the compare reads in the expanded sheet', async (ctx) => {
    const { page, errors } = await openPage(phone, ctx);
    await gotoRig(page, env.url, 'knight');
    // A finger drags the left hand's target (a tap gives it the gizmo), then the sheet opens.
    const hand = await effectorNamed(page, /^hand\.L$/);
    const cdp = await phone.context.newCDPSession(page);
    const from = await targetScreen(page, hand);
    await swipe(cdp, from.x, from.y, 0, 0, 1);
    await page.waitForFunction((k) => window.ikPage?.selectedTarget() === k, hand);
    await swipe(cdp, from.x, from.y, 10, -25);
    await waitForConvergence(page);
    await page.locator('#sheet-handle').tap();
    await page.waitForFunction(() => document.getElementById('app')?.dataset.sheet === 'expanded');
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
      timeout: 60_000,
    });
    await renderedFrames(page, 2);
    const box = (await page.locator('#compare').boundingBox())!;
    const rows = await page.$$eval('#compare .compare-table tbody tr', (r) => r.length);
    console.log(`[student] phone compare: ${box.height.toFixed(0)} px tall, ${rows} rows`);
    expect(rows).toBe(5);
    const iterations = await page.$$eval('#compare .compare-table tbody tr', (r) =>
      r.map((row) => Number((row as HTMLTableRowElement).cells[2].textContent)),
    );
    for (const n of iterations) expect(n).toBeGreaterThan(0);
    expect(box.height).toBeGreaterThan(250); // the title, the table and its plot, not a strip
    // Every row of the table is on screen.
    const last = (await page.locator('#compare .compare-table tbody tr').last().boundingBox())!;
    expect(last.y + last.height).toBeLessThanOrEqual(844);
    expect(last.y).toBeGreaterThanOrEqual(0);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'phone-compare.png') });
    // The compare's iteration cap reads whole in its box: 100000, not 10000.
    const cap = (await panelControl(page, /^compare: iterations$/)).locator('input').first();
    await cap.scrollIntoViewIfNeeded();
    expect(await cap.inputValue()).toBe('100000');
    const fits = await cap.evaluate((input) => [
      (input as HTMLInputElement).scrollWidth,
      (input as HTMLInputElement).clientWidth,
    ]);
    console.log(`[student] the iteration box: ${fits[0]} px of text in ${fits[1]} px`);
    expect(fits[0]).toBeLessThanOrEqual(fits[1]);
    expect(errors).toEqual([]);
  });

  for (const where of ['desktop', 'phone']) {
    it(`a long note is one line (${where}), its details behind a click, and goes with a drag`, async (ctx) => {
      const { page, errors } = await openPage(where === 'phone' ? phone : env.browser, ctx);
      await gotoRig(page, env.url, 'character');
      const note = page.locator('#message');
      const text = (await note.textContent()) ?? '';
      expect(text.length).toBeGreaterThan(150); // the recognition message and its details
      expect(await note.getAttribute('data-kind')).toBe('info');
      const oneLine = (await note.boundingBox())!.height;
      console.log(`[student] ${where}: the note is ${oneLine.toFixed(0)} px tall, ${text.length} characters`);
      expect(oneLine).toBeLessThan(36); // padding and one line of 14 px text
      await note.click();
      expect(await note.getAttribute('data-expanded')).toBe('true');
      expect((await note.boundingBox())!.height).toBeGreaterThan(2 * oneLine);
      expect(await note.textContent()).toBe(text);
      await note.click();
      expect((await note.boundingBox())!.height).toBe(oneLine);
      // A drag of a target: the note goes.
      if (where === 'phone') {
        // A finger drags the target that holds the gizmo from the start (a tap on a hand's target may
        // land on another on this small view).
        const cdp = await phone.context.newCDPSession(page);
        const from = await targetScreen(
          page,
          (await page.evaluate(() => window.ikPage?.selectedTarget() ?? null)) ?? 0,
        );
        await swipe(cdp, from.x, from.y, 8, -20);
      } else {
        await dragTowardsRoot(page, await selectTarget(page, await effectorNamed(page, /hand/i)), 0.2);
      }
      await page.waitForFunction(() => document.getElementById('message')?.dataset.dismissed === 'true');
      expect(await note.isVisible()).toBe(false);
      expect((await note.boundingBox())?.height ?? oneLine).toBe(oneLine); // its line stays: the view did not move
      expect(errors).toEqual([]);
    });
  }

  it("the first view: the lamp's target shows, the plot says what comes, the first time is a solve's", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    await renderedFrames(page, 3);
    // The first solve (0 iterations: the target sits on the tip) is timed warm.
    const first = Number(await stat(page, 'ms'));
    console.log(`[student] the lamp's first solve: ${first} ms, ${await statText(page, 'iterations')} iterations`);
    expect(await statText(page, 'iterations')).toBe('0');
    expect(first).toBeLessThan(3); // warmed: 0.07 ms here, 1.3 ms with the cores busy; cold it read 6.7 ms
    // The selected target (yellow) is seen at its place, inside the lamp's shade, under the gizmo.
    const t = (await page.evaluate(() => window.ikPage?.targetScreen(0) ?? null))!;
    const png = await page.screenshot({ clip: { x: t.x - 10, y: t.y - 10, width: 20, height: 20 } });
    const yellow = await page.evaluate(async (b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      [c.width, c.height] = [img.width, img.height];
      const g = c.getContext('2d')!;
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      // The selected target's yellow, lit (209,184,123 .. 160,141,96): green well above blue, red near
      // green. Not the lamp's salmon shade (239,154,147) nor the gizmo's orange (255,179,109).
      let n = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] > 150 && d[i + 1] - d[i + 2] > 40 && d[i] - d[i + 1] < 60) n++;
      return n;
    }, png.toString('base64'));
    console.log(`[student] target-coloured pixels around the lamp's target: ${yellow}`);
    expect(yellow).toBeGreaterThan(40);
    // The side plot: a line saying what will show, no empty frame.
    const plot = page.locator('#side > .plot');
    expect(await plot.getAttribute('data-empty')).toBe('true');
    expect(await plot.locator('.plot-note').textContent()).toMatch(/^Nothing solved yet: drag a target/);
    expect(await plot.locator('.uplot').isVisible()).toBe(false);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'lamp-first-view.png') });
    // After a drag the plot draws (the lamp's one target holds the gizmo from the start).
    const before = await targetAt(page, 0);
    await dragTargetAlongY(page, 0, -60 / (await page.evaluate(() => window.ikPage?.pixelsPerUnit() ?? NaN)));
    await waitForConvergence(page);
    expect((await targetAt(page, 0))[1]).toBeLessThan(before[1]); // the target went down
    await plot.scrollIntoViewIfNeeded();
    await page.waitForFunction(
      () => document.querySelector<HTMLElement>('#side > .plot')?.dataset.empty === 'false',
      null,
      { timeout: 10_000 },
    );
    expect(await plot.locator('.uplot').isVisible()).toBe(true);
    expect(errors).toEqual([]);
  });

  it('a compare on a busy machine: the still view draws a frame a second, not one per animation frame', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const hand = await selectTarget(page, await effectorNamed(page, /LeftHand$/));
    await dragTowardsRoot(page, hand, 0.4);
    await waitForConvergence(page);
    // Two workers keep the machine's cores busy while the page is measured.
    await page.evaluate(() => {
      const busy = URL.createObjectURL(new Blob(['for (;;) {}'], { type: 'text/javascript' }));
      (window as unknown as { busy: Worker[] }).busy = [new Worker(busy), new Worker(busy)];
      const w = window as unknown as { longTasks: number[]; gaps: number[] };
      w.longTasks = [];
      w.gaps = [];
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) w.longTasks.push(e.duration);
      }).observe({ type: 'longtask' });
      let last = performance.now();
      const tick = (): void => {
        const now = performance.now();
        w.gaps.push(now - last);
        last = now;
        requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    });
    // A still view: after a second without input, a few frames a second.
    await page.waitForTimeout(1200);
    const idle0 = await page.evaluate(() => window.ikPage!.drawnFrames());
    await page.waitForTimeout(2000);
    const idleDrawn = (await page.evaluate(() => window.ikPage!.drawnFrames())) - idle0;
    // A compare meanwhile.
    await page.evaluate(() => {
      const w = window as unknown as { longTasks: number[]; gaps: number[] };
      w.longTasks = [];
      w.gaps = [];
    });
    const t0 = Date.now();
    const drawn0 = await page.evaluate(() => window.ikPage!.drawnFrames());
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
      timeout: 120_000,
    });
    const ms = Date.now() - t0;
    const m = await page.evaluate(() => {
      const w = window as unknown as { longTasks: number[]; gaps: number[]; busy: Worker[] };
      for (const b of w.busy) b.terminate();
      return {
        longest: Math.max(0, ...w.longTasks),
        count: w.longTasks.length,
        gap: Math.max(0, ...w.gaps),
        drawn: window.ikPage!.drawnFrames(),
      };
    });
    const compareDrawn = m.drawn - drawn0;
    console.log(
      `[student] busy machine: a still view drew ${idleDrawn} frames in 2 s; a compare of ${ms} ms drew ${compareDrawn} frames and had ${m.count} long tasks, the longest ${m.longest.toFixed(0)} ms, the largest frame gap ${m.gap.toFixed(0)} ms`,
    );
    expect(idleDrawn).toBeLessThanOrEqual(4); // one a second (IDLE_FRAME_MS), and a margin
    expect(idleDrawn).toBeGreaterThan(0); // it still draws: what changed unannounced shows
    // The compare's key draws one frame (its own shortcut might change the picture), then one a second.
    expect(compareDrawn).toBeLessThanOrEqual(2 + ms / 1000);
    expect(errors).toEqual([]);
  });
});
