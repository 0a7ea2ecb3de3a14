// What the page's browser tests share: opening a rig, reading the stats, and dragging a target's
// gizmo with real mouse events (screen positions come from window.ikPage, web/src/page/probe.ts).
import type { CDPSession, Page } from 'playwright-core';
import { afterAll, beforeAll, expect } from 'vitest';

import type { ScreenPoint } from '../../web/src/view/stage.js';
import { launchBrowser, nextFrame, startVite, type BrowserSession } from './harness.js';

/** The page's vite server and a browser for one test file: started before its tests, closed after. */
export interface PageServer {
  /** The page's URL (ends with /). */
  readonly url: string;
  readonly browser: BrowserSession;
}

/** Starts the page's server and Chromium for the calling test file (beforeAll / afterAll). */
export function usePageServer(): PageServer {
  let server: { url: string; close: () => Promise<void> } | undefined;
  let browser: BrowserSession | undefined;
  beforeAll(async () => {
    server = await startVite();
    browser = await launchBrowser();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });
  return {
    get url() {
      if (!server) throw new Error('the page server has not started');
      return server.url;
    },
    get browser() {
      if (!browser) throw new Error('the browser has not started');
      return browser;
    },
  };
}

/** Opens the page at `url` with `?rig=NAME` (and `query`) and waits until the rig is ready. */
export async function gotoRig(page: Page, url: string, rig: string, query = ''): Promise<void> {
  await page.goto(`${url}?rig=${rig}${query}`);
  await page.waitForFunction(() => {
    const s = document.getElementById('app')?.dataset.state;
    return s === 'ready' || s === 'error';
  });
  expect(await page.getAttribute('#app', 'data-state'), (await page.textContent('#message')) ?? '').toBe('ready');
}

export async function stat(page: Page, key: string): Promise<string> {
  return (await page.getAttribute(`[data-stat="${key}"]`, 'data-value')) ?? '';
}

export async function statText(page: Page, key: string): Promise<string> {
  return (await page.textContent(`[data-stat="${key}"]`)) ?? '';
}

export async function targetScreen(page: Page, k: number): Promise<ScreenPoint> {
  const p = await page.evaluate((i) => window.ikPage?.targetScreen(i) ?? null, k);
  if (!p) throw new Error(`no target ${k}`);
  return p;
}

/**
 * Drags the gizmo of the selected target with the mouse by a fraction of the way towards the root
 * joint; `perFrame`: wait for an animation frame after each of the `steps` moves.
 */
export async function dragTowardsRoot(
  page: Page,
  k: number,
  fraction: number,
  steps = 12,
  perFrame = true,
): Promise<{ from: ScreenPoint; to: ScreenPoint }> {
  const from = await targetScreen(page, k);
  const root = await page.evaluate(() => window.ikPage?.boneScreen(0) ?? null);
  if (!root) throw new Error('no root bone');
  let dx = (root.x - from.x) * fraction,
    dy = (root.y - from.y) * fraction;
  const len = Math.hypot(dx, dy);
  if (len < 25) [dx, dy] = len > 0 ? [(dx / len) * 25, (dy / len) * 25] : [25, 0];
  return dragBy(page, k, dx, dy, steps, perFrame);
}

/** Drags the mouse from `from` by (dx, dy) pixels in `steps` equal moves, waiting a frame after each when `perFrame`. */
export async function dragMouse(
  page: Page,
  from: ScreenPoint,
  dx: number,
  dy: number,
  steps = 12,
  perFrame = true,
): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await page.mouse.move(from.x + (dx * i) / steps, from.y + (dy * i) / steps);
    if (perFrame) await nextFrame(page);
  }
  await page.mouse.up();
}

/** Drags the gizmo of the selected target k by (dx, dy) pixels with the mouse; `perFrame` as in dragTowardsRoot. */
export async function dragBy(
  page: Page,
  k: number,
  dx: number,
  dy: number,
  steps = 12,
  perFrame = true,
): Promise<{ from: ScreenPoint; to: ScreenPoint }> {
  const from = await targetScreen(page, k);
  await dragMouse(page, from, dx, dy, steps, perFrame);
  return { from, to: { x: from.x + dx, y: from.y + dy } };
}

/** Puts the gizmo on target k by clicking it; returns k. */
export async function selectTarget(page: Page, k: number): Promise<number> {
  if ((await page.evaluate(() => window.ikPage?.selectedTarget())) === k) return k;
  const p = await targetScreen(page, k);
  await page.mouse.click(p.x, p.y);
  await page.waitForFunction((i) => window.ikPage?.selectedTarget() === i, k);
  return k;
}

/** The effector (index in effector order) on a bone whose name matches `pattern`, else 0. */
export async function effectorNamed(page: Page, pattern: RegExp): Promise<number> {
  const { effectors, names } = await page.evaluate(() => ({
    effectors: window.ikPage?.effectors() ?? [],
    names: window.ikPage?.boneNames() ?? [],
  }));
  const k = effectors.findIndex((b) => pattern.test(names[b]));
  return k < 0 ? 0 : k;
}

/** Waits until the per-frame solve has stopped for a reason other than its budget; returns the stop reason. */
export async function waitForSettled(page: Page): Promise<string> {
  await page.waitForFunction(
    () => {
      const r = document.querySelector<HTMLElement>('[data-stat="status"]')?.dataset.reason ?? '';
      return ['converged_E', 'converged_grad', 'zero_step'].includes(r);
    },
    null,
    { timeout: 20_000 },
  );
  return (await page.getAttribute('[data-stat="status"]', 'data-reason')) ?? '';
}

/** The stats panel's text on one line (what a failed wait reports). */
async function statsLine(page: Page): Promise<string> {
  return page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('[data-stat]')]
      .map(
        (e) => `${e.dataset.stat}=${(e.textContent ?? '').trim()}${e.dataset.reason ? ` (${e.dataset.reason})` : ''}`,
      )
      .join('; '),
  );
}

/** Waits until the stats say "on target" (every effector within the tip tolerance). */
export async function waitForConvergence(page: Page): Promise<void> {
  try {
    await page.waitForFunction(
      () => document.querySelector<HTMLElement>('[data-stat="status"]')?.dataset.reached === 'true',
      null,
      { timeout: 20_000 },
    );
  } catch (e) {
    throw new Error(`not on target after 20 s; the stats read: ${await statsLine(page)}`, { cause: e });
  }
  expect(await statText(page, 'status')).toBe('on target');
}

/** Where pole handle j is on screen (client pixels); throws when there is none. */
export async function poleScreen(page: Page, j: number): Promise<ScreenPoint> {
  const p = await page.evaluate((i) => window.ikPage?.poleHandles()[i]?.screen ?? null, j);
  if (!p) throw new Error(`no pole handle ${j}`);
  return p;
}

/** Puts the gizmo on pole handle j by clicking it; returns j. */
export async function selectPole(page: Page, j: number): Promise<number> {
  const p = await poleScreen(page, j);
  await page.mouse.click(p.x, p.y);
  await page.waitForFunction((i) => window.ikPage?.selectedPole() === i, j);
  return j;
}

/** Drags the gizmo of the selected pole handle j by (dx, dy) pixels with the mouse, a frame after each of `steps` moves. */
export async function dragPoleBy(page: Page, j: number, dx: number, dy: number, steps = 12): Promise<void> {
  await dragMouse(page, await poleScreen(page, j), dx, dy, steps);
}

/**
 * The panel's control labelled `name` (a lil-gui controller), its folder opened first: the panel
 * opens one folder at a time, so a control in a closed folder is hidden until its title is clicked.
 */
export async function panelControl(page: Page, name: RegExp) {
  const control = page.locator('.lil-controller', { has: page.locator('.lil-name', { hasText: name }) });
  const titles = await control.evaluate((el) => {
    const closed: number[] = [];
    const all = Array.from(document.querySelectorAll('.lil-gui > .lil-title'));
    for (let g = el.closest('.lil-gui.lil-closed'); g; g = g.parentElement?.closest('.lil-gui.lil-closed') ?? null) {
      closed.unshift(all.indexOf(g.querySelector(':scope > .lil-title') as Element));
    }
    return closed;
  });
  for (const i of titles) await page.locator('.lil-gui > .lil-title').nth(i).click();
  return control;
}

/**
 * Drags the selected target k straight up (dy > 0) or down by `dy` rig units with the mouse on the
 * gizmo's world Y arrow: grabbed 35 px along the arrow from the target, each of the `steps` moves
 * to the screen point of a world point on the arrow's line, so the target moves by dy exactly (up
 * to where the mouse can point); a frame after each move.
 */
export async function dragTargetAlongY(page: Page, k: number, dy: number, steps = 20): Promise<void> {
  const start = await page.evaluate((i) => window.ikPage?.targetPosition(i) ?? null, k);
  if (!start) throw new Error(`no target ${k}`);
  const at = async (up: number): Promise<ScreenPoint> => {
    const p = await page.evaluate((q) => window.ikPage?.worldToScreen(q) ?? null, [
      start[0],
      start[1] + up,
      start[2],
    ] as [number, number, number]);
    if (!p) throw new Error('no screen point');
    return p;
  };
  const center = await at(0);
  const probe = Math.abs(dy) / 30 || 0.01;
  const near = await at(probe);
  const grabUp = (35 * probe) / Math.hypot(near.x - center.x, near.y - center.y); // 35 px along the arrow, in rig units
  const grab = await at(grabUp);
  await page.mouse.move(grab.x, grab.y);
  await page.waitForFunction(() => window.ikPage?.gizmoAxis() === 'Y', null, { timeout: 5_000 }); // the mouse is on the up arrow
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    const p = await at(grabUp + (dy * i) / steps);
    await page.mouse.move(p.x, p.y);
    await nextFrame(page);
  }
  await page.mouse.up();
}

/** Effector k's tip (rig units) as the page has it; throws when there is none. */
export async function tipAt(page: Page, k: number): Promise<[number, number, number]> {
  const p = await page.evaluate((i) => window.ikPage?.tipPosition(i) ?? null, k);
  if (!p) throw new Error(`no tip ${k}`);
  return p;
}

/** Target k (rig units) as the page has it; throws when there is none. */
export async function targetAt(page: Page, k: number): Promise<[number, number, number]> {
  const p = await page.evaluate((i) => window.ikPage?.targetPosition(i) ?? null, k);
  if (!p) throw new Error(`no target ${k}`);
  return p;
}

/** A one-finger touch drag from (x, y) by (dx, dy) pixels in `steps` moves (CDP touch events, as a finger makes). */
export async function swipe(cdp: CDPSession, x: number, y: number, dx: number, dy: number, steps = 12): Promise<void> {
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y }] });
  for (let i = 1; i <= steps; i++)
    await cdp.send('Input.dispatchTouchEvent', {
      type: 'touchMove',
      touchPoints: [{ x: x + (dx * i) / steps, y: y + (dy * i) / steps }],
    });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}
