// The widget as a course page uses it: the single-file build (dist/widget/ik-widget.js) served
// as static files next to web/embed-example.html and the project models; no bundler on the page.
// A click or a tap on any target selects it; dragging it solves onto it and the status says so. The
// example's text says what its knight shows: a dragged hand moves no other effector.
// Writes test-results/embed-knight-still.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { build } from 'vite';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkWidget } from '../../web/src/widget/ik_widget.js';
import type { WidgetProbe } from '../../web/src/widget/probe.js';
import {
  launchBrowser,
  nextFrame,
  openPage,
  repoRoot,
  resultsDir,
  startStatic,
  type BrowserSession,
} from './harness.js';

let server: { url: string; close: () => Promise<void> };
let browser: BrowserSession;

beforeAll(async () => {
  await build({ configFile: join(repoRoot, 'vite.widget.config.ts'), logLevel: 'warn' });
  server = await startStatic([
    ['/ik-widget.js', join(repoRoot, 'dist/widget/ik-widget.js')],
    ['/models/', join(repoRoot, 'web/public/models')],
    ['/', join(repoRoot, 'web')],
  ]);
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

/** Opens the example course page, waits for its widgets, and scrolls widget `id` to the middle of the view. */
async function gotoExample(page: Page, id: string): Promise<void> {
  await page.goto(`${server.url}embed-example.html`);
  await page.waitForFunction(
    () => [...document.querySelectorAll('ik-widget')].every((w) => (w as HTMLElement).dataset.state === 'ready'),
    null,
    {
      timeout: 30_000,
    },
  );
  await page.$eval(`#${id}`, (w) => w.scrollIntoView({ block: 'center' }));
  await nextFrame(page);
}

/** The probe of widget `id` (its targets, tips, selection, camera). */
async function probe(page: Page, id: string): Promise<WidgetProbe> {
  const p = await page.$eval(`#${id}`, (w) => (w as IkWidget).probe);
  if (!p) throw new Error(`#${id} has no probe: not ready, or the widget predates it`);
  return p;
}

/** The status line of widget `id`: its text and attributes. */
async function status(
  page: Page,
  id: string,
): Promise<{ text: string; kind?: string; reached?: string; title: string }> {
  return page.$eval(`#${id}`, (w) => {
    const el = w.shadowRoot?.querySelector<HTMLElement>('.stats');
    return {
      text: el?.textContent ?? '',
      kind: el?.dataset.status,
      reached: el?.dataset.reached,
      title: el?.title ?? '',
    };
  });
}

/** Effector k's target, 3 numbers, rig units. */
function target(p: WidgetProbe, k: number): number[] {
  return p.targets.slice(3 * k, 3 * k + 3);
}

/** Distance from effector k's tip to its target, rig units. */
function tipError(p: WidgetProbe, k: number): number {
  const [x, y, z] = target(p, k);
  return Math.hypot(p.tips[3 * k] - x, p.tips[3 * k + 1] - y, p.tips[3 * k + 2] - z);
}

describe('<ik-widget>', () => {
  it('the example course page renders two widgets from the single-file build', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    const requests: string[] = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(`${server.url}embed-example.html`);
    await page.waitForFunction(
      () => {
        const w = [...document.querySelectorAll('ik-widget')];
        return w.length === 2 && w.every((x) => (x as HTMLElement).dataset.state !== 'loading');
      },
      null,
      { timeout: 30_000 },
    );
    const widgets = await page.$$eval('ik-widget', (list) =>
      list.map((w) => {
        const canvas = w.shadowRoot?.querySelector('canvas');
        return {
          state: (w as HTMLElement).dataset.state,
          name: w.shadowRoot?.querySelector('.name')?.textContent,
          canvas: canvas ? [canvas.width, canvas.height] : null,
        };
      }),
    );
    expect(widgets).toEqual([
      { state: 'ready', name: 'lamp', canvas: [expect.any(Number), expect.any(Number)] },
      { state: 'ready', name: 'knight', canvas: [expect.any(Number), expect.any(Number)] },
    ]);
    for (const w of widgets) expect(Math.min(...(w.canvas ?? [0]))).toBeGreaterThan(100);
    // One script, no separate .wasm request: the WebAssembly is inside ik-widget.js.
    expect(requests.filter((u) => u.endsWith('.wasm'))).toEqual([]);
    expect(requests.filter((u) => u.endsWith('.js')).map((u) => new URL(u).pathname)).toEqual(['/ik-widget.js']);
    expect(errors).toEqual([]);
  });

  it('fails soft: a missing file shows a message inside the widget, names as text', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await page.goto(`${server.url}embed-example.html`);
    await page.evaluate(() => {
      const w = document.createElement('ik-widget');
      w.id = 'broken';
      w.setAttribute('src', 'models/<i>missing</i>.glb');
      document.body.append(w);
    });
    await page.waitForFunction(() => document.getElementById('broken')?.dataset.state === 'error', null, {
      timeout: 30_000,
    });
    const text = await page.$eval('#broken', (w) => w.shadowRoot?.querySelector('.message')?.textContent ?? '');
    expect(text).toContain('<i>missing</i>.glb');
    expect(text).toContain('404');
    expect(await page.$eval('#broken', (w) => w.shadowRoot?.querySelectorAll('i').length)).toBe(0);
    // The other widgets are unaffected.
    await page.waitForFunction(() =>
      [...document.querySelectorAll('ik-widget:not(#broken)')].every(
        (w) => (w as HTMLElement).dataset.state === 'ready',
      ),
    );
    // The browser reports the 404 itself; nothing else went wrong.
    expect(errors.filter((e) => !/404/.test(e))).toEqual([]);
  });

  it('clicking the second target selects it; dragging it moves that hand onto it, nothing else moves', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await gotoExample(page, 'knight');
    const before = await probe(page, 'knight');
    expect(before.selected).toBe(0);
    expect(before.targets.length / 3).toBeGreaterThan(1);
    const from = before.targetsOnScreen[1];

    // A click on target 1 gives it the gizmo.
    await page.mouse.click(from.x, from.y);
    expect((await probe(page, 'knight')).selected).toBe(1);

    // Drag it by a few dozen pixels with the gizmo.
    const [dx, dy] = [-24, -40];
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 12; i++) {
      await page.mouse.move(from.x + (dx * i) / 12, from.y + (dy * i) / 12);
      await nextFrame(page); // one per-frame solve per move, as a user's drag gives
    }
    await page.mouse.up();
    // Settled: the last solve stopped for a reason other than its per-frame budget.
    await nextFrame(page);
    await page.waitForFunction(
      () => {
        const kind = document.getElementById('knight')?.shadowRoot?.querySelector<HTMLElement>('.stats')
          ?.dataset.status;
        return kind !== 'solving' && kind !== 'budget';
      },
      null,
      { timeout: 20_000 },
    );
    const after = await probe(page, 'knight');

    // Target 1 moved and followed the mouse; target 0 and the camera stayed.
    const now = after.targetsOnScreen[1];
    expect(Math.hypot(now.x - (from.x + dx), now.y - (from.y + dy))).toBeLessThan(3);
    const moved = Math.hypot(...target(after, 1).map((c, i) => c - target(before, 1)[i]));
    expect(target(after, 0)).toEqual(target(before, 0));
    expect(after.camera).toEqual(before.camera);

    // The hand's tip ends on its target (the tolerance is far below the move), and the status says so.
    expect(after.tipTolerance).toBeLessThan(moved / 20);
    expect(tipError(after, 1)).toBeLessThan(after.tipTolerance);
    const line = await status(page, 'knight');
    expect(line).toMatchObject({ kind: 'on-target', reached: 'true' });
    expect(line.text).toMatch(/^bfgs · \d+ it · tip error [\d.e-]+ · [\d.]+ ms · on target$/);
    expect(line.title).toContain('within the tolerance');
    expect(errors).toEqual([]);
  });

  it("the example's text says what the knight shows: with bfgs, gd and lm a dragged hand moves no other effector", async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await gotoExample(page, 'knight');
    const text = (await page.textContent('#knight-text')) ?? '';
    expect(text).toMatch(/stay exactly where they are, with every method/);
    expect(text).not.toMatch(/leaves them alone/); // the report's wobble is not claimed for this widget
    for (const method of ['bfgs', 'gd', 'lm']) {
      await page.$eval('#knight', (w, m) => w.setAttribute('method', m), method);
      await page.waitForFunction(
        (m) =>
          (document.getElementById('knight')?.shadowRoot?.querySelector('.stats')?.textContent ?? '').startsWith(
            `${m} ·`,
          ),
        method,
      );
      const before = await probe(page, 'knight');
      const from = before.targetsOnScreen[1];
      await page.mouse.click(from.x, from.y);
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      for (let i = 1; i <= 10; i++) {
        await page.mouse.move(from.x - 2 * i, from.y - 4 * i);
        await nextFrame(page);
      }
      await page.mouse.up();
      await nextFrame(page);
      const after = await probe(page, 'knight');
      expect(Math.hypot(...target(after, 1).map((c, i) => c - target(before, 1)[i]))).toBeGreaterThan(0); // the hand's target moved
      for (let k = 0; k < after.tips.length / 3; k++) {
        if (k === 1) continue;
        const moved = Math.hypot(...[0, 1, 2].map((i) => after.tips[3 * k + i] - before.tips[3 * k + i]));
        expect(moved, `${method}: effector ${k} moved`).toBeLessThan(1e-9);
      }
    }
    mkdirSync(resultsDir, { recursive: true });
    await page.locator('#knight').screenshot({ path: join(resultsDir, 'embed-knight-still.png') });
    expect(errors).toEqual([]);
  });

  it(`goals="hand.L:pose": dragging the hand's target keeps the hand's orientation; the turn button rotates it; bad names show an error`, async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await gotoExample(page, 'knight');
    await page.$eval('#knight', (w) => w.setAttribute('goals', 'hand.L:pose'));
    const before = await probe(page, 'knight');
    const hand = before.effectorNames.indexOf('hand.L');
    expect(hand, before.effectorNames.join(', ')).toBeGreaterThanOrEqual(0);
    const goal = before.orientationGoals[hand];
    if (!goal) throw new Error('hand.L got no orientation goal');
    expect(before.orientationErrors[hand]).toBeLessThan(1e-3); // it starts at the hand's frame (the rest pose)
    before.orientationGoals.forEach((g, k) => {
      if (k !== hand) expect(g, before.effectorNames[k]).toBeNull();
    });
    expect(before.positionGoals.every((p) => p)).toBe(true);

    // Select the hand's target: the gizmo moves it (translate) and the turn button appears.
    const from = before.targetsOnScreen[hand];
    await page.mouse.click(from.x, from.y);
    expect((await probe(page, 'knight')).selected).toBe(hand);
    const turn = page.locator('#knight button.turn');
    expect(await turn.isVisible()).toBe(true);
    expect((await probe(page, 'knight')).gizmoMode).toBe('translate');

    // Drag it up and sideways: the hand must reach the new point with its frame still turned as at rest.
    const [dx, dy] = [10, -16];
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 12; i++) {
      await page.mouse.move(from.x + (dx * i) / 12, from.y + (dy * i) / 12);
      await nextFrame(page);
    }
    await page.mouse.up();
    // Wait until the status says on target with the hand on its moved target (not a status from before the drag).
    await page.waitForFunction(
      (k) => {
        const w = document.getElementById('knight') as IkWidget | null;
        const p = w?.probe;
        if (!p || w?.shadowRoot?.querySelector<HTMLElement>('.stats')?.dataset.reached !== 'true') return false;
        const d = Math.hypot(
          p.tips[3 * k] - p.targets[3 * k],
          p.tips[3 * k + 1] - p.targets[3 * k + 1],
          p.tips[3 * k + 2] - p.targets[3 * k + 2],
        );
        return d < p.tipTolerance;
      },
      hand,
      { timeout: 20_000 },
    );
    const after = await probe(page, 'knight');
    expect(Math.hypot(...target(after, hand).map((c, i) => c - target(before, hand)[i]))).toBeGreaterThan(
      20 * after.tipTolerance,
    );
    expect(tipError(after, hand)).toBeLessThan(after.tipTolerance);
    expect(after.orientationGoals[hand]).toEqual(goal);
    expect(after.orientationErrors[hand]).toBeLessThan(0.5);
    const line = await status(page, 'knight');
    expect(line.text).toMatch(
      /^bfgs · \d+ it · tip error [\d.e-]+ · orientation error [\d.e-]+° · [\d.]+ ms · on target$/,
    );

    // The turn button switches the gizmo to rotating the target.
    await turn.click();
    expect((await probe(page, 'knight')).gizmoMode).toBe('rotate');
    expect(await turn.getAttribute('aria-pressed')).toBe('true');

    // An unknown bone and an unknown kind: the status line names them; nothing throws.
    await page.$eval('#knight', (w) => w.setAttribute('goals', 'hand.X:pose, hand.L:twist'));
    // The message stays while the widget goes on solving (the goals changed: it solves again).
    await page.waitForFunction(
      () =>
        document.getElementById('knight')?.shadowRoot?.querySelector<HTMLElement>('.stats')?.dataset.reached !==
        undefined,
    );
    const bad = await page.$eval('#knight', (w) => {
      const el = w.shadowRoot?.querySelector<HTMLElement>('.stats');
      return { text: el?.textContent ?? '', problem: el?.dataset.problem ?? '' };
    });
    expect(bad.text).toMatch(
      /^unknown goal bone "hand.X"; goal kind "twist" of hand.L is not position, orientation, pose — bfgs · /,
    );
    expect(bad.problem).toContain('unknown goal bone "hand.X"');
    expect(await page.$eval('#knight', (w) => (w as HTMLElement).dataset.state)).toBe('ready');
    expect((await probe(page, 'knight')).orientationGoals.every((g) => g === null)).toBe(true);
    // Good goals again: the message goes.
    await page.$eval('#knight', (w) => w.setAttribute('goals', 'hand.L:orientation'));
    expect(
      await page.$eval('#knight', (w) => w.shadowRoot?.querySelector<HTMLElement>('.stats')?.dataset.problem),
    ).toBeUndefined();
    const p = await probe(page, 'knight');
    expect(p.positionGoals[hand]).toBe(false);
    expect(p.orientationGoals[hand]).not.toBeNull();
    expect(p.gizmoMode).toBe('rotate'); // an orientation-only target always rotates
    expect(errors).toEqual([]);
  });

  it('a tap on a touch screen selects a target as a click does', async (ctx) => {
    const phone = await launchBrowser(true);
    try {
      const { page, errors } = await openPage(phone, ctx);
      await gotoExample(page, 'knight');
      const before = await probe(page, 'knight');
      expect(before.selected).toBe(0);
      const at = before.targetsOnScreen[1];
      await page.touchscreen.tap(at.x, at.y);
      const after = await probe(page, 'knight');
      expect(after.selected).toBe(1);
      expect(after.camera).toEqual(before.camera);
      expect(errors).toEqual([]);
    } finally {
      await phone.close();
    }
  });
});
