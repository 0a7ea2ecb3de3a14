// The page in headless Chromium: every project rig loads cleanly, dragging a target with real
// mouse events solves onto it, methods switch, step mode steps, a broken file is refused while
// the previous rig stays, and the README screenshot. Also prints the per-solve time on the
// largest rig (never asserted: wall-clock limits do not belong in tests).
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { launchBrowser, openPage, renderedFrames, repoRoot } from './harness.js';
import {
  dragBy,
  dragTowardsRoot,
  effectorNamed,
  gotoRig as openRig,
  panelControl,
  selectTarget,
  stat,
  statText,
  targetScreen,
  usePageServer,
  waitForConvergence,
  waitForSettled,
} from './page_helpers.js';

const RIGS = ['lamp', 'robot-arm', 'knight', 'hand', 'beast', 'character'];

const env = usePageServer();

const gotoRig = (page: Page, rig: string, query = ''): Promise<void> => openRig(page, env.url, rig, query);

describe('the page', () => {
  it('loads each project rig with no console errors', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    for (const rig of RIGS) {
      await gotoRig(page, rig);
      expect(await page.evaluate(() => window.ikPage?.rigName())).toBe(rig);
      expect((await page.evaluate(() => window.ikPage?.effectors() ?? [])).length).toBeGreaterThan(0);
      expect(await page.textContent('#rig-name')).toContain(rig);
      // The canvas is drawn at the viewport's size.
      const size = await page.$eval('#viewport canvas', (c) => [
        (c as HTMLCanvasElement).width,
        (c as HTMLCanvasElement).height,
      ]);
      expect(size[0]).toBeGreaterThan(100);
      expect(size[1]).toBeGreaterThan(100);
    }
    expect(errors).toEqual([]);
  });

  it('dragging a target with the mouse moves the effector onto it, the camera stays still', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'lamp');
    const camera = await page.evaluate(() => window.ikPage?.cameraPosition());
    const { to } = await dragTowardsRoot(page, 0, 0.2);
    await waitForConvergence(page);
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    expect(await page.evaluate(() => window.ikPage?.effectorError(0))).toBeLessThan(tolerance);
    const now = await targetScreen(page, 0);
    expect(Math.hypot(now.x - to.x, now.y - to.y)).toBeLessThan(3); // the target followed the mouse
    expect(await page.evaluate(() => window.ikPage?.cameraPosition())).toEqual(camera);
    expect(Number(await stat(page, 'iterations'))).toBeGreaterThanOrEqual(0);
    expect(errors).toEqual([]);
  });

  it('switching methods works (panel select, stats and URL follow)', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'robot-arm');
    const select = (await panelControl(page, /^method$/)).locator('select');
    // The menu lists the core's registry in its order, the default (lm) first.
    const methods = await select.locator('option').allTextContents();
    expect(methods[0]).toBe('lm');
    expect([...methods].sort()).toEqual(['bfgs', 'gd', 'gn', 'lm', 'newton']);
    for (const method of [...methods.slice(1), 'lm']) {
      await select.selectOption(method);
      expect(new URL(page.url()).searchParams.get('method')).toBe(method);
      await dragTowardsRoot(page, 0, 0.08, 6);
      await page.waitForFunction(
        (m) =>
          document.querySelector('[data-stat="method"]')?.textContent === m &&
          Number(document.querySelector<HTMLElement>('[data-stat="iterations"]')?.dataset.value) >= 0 &&
          (document.querySelector('[data-stat="status"]')?.textContent ?? '–') !== '–',
        method,
      );
    }
    // The URL reproduces the view.
    await page.goto(`${env.url}?rig=robot-arm&method=gn`);
    await page.waitForFunction(() => document.getElementById('app')?.dataset.state === 'ready');
    expect(await select.inputValue()).toBe('gn');
    expect(errors).toEqual([]);
  });

  it('step mode advances one iteration per S', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'lamp', '&method=gd');
    await (await panelControl(page, /^step mode$/)).locator('input').check();
    await dragTowardsRoot(page, 0, 0.3);
    await page.waitForFunction(() => document.getElementById('app')?.dataset.dragging === 'false');
    await page.keyboard.press('s');
    await page.waitForFunction(() => document.getElementById('step-info')?.dataset.iterations === '1');
    const E1 = Number(await stat(page, 'E'));
    await page.keyboard.press('s');
    await page.waitForFunction(() => document.getElementById('step-info')?.dataset.iterations === '2');
    expect(await stat(page, 'iterations')).toBe('2');
    expect(Number(await stat(page, 'E'))).toBeLessThan(E1);
    expect(await page.textContent('#step-info')).toContain('iteration 2');
    expect(errors).toEqual([]);
  });

  it('clicking a bone makes its tip an effector and clicking again removes it; R resets', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'robot-arm');
    const before = await page.evaluate(() => window.ikPage?.effectors() ?? []);
    const bone = await longestNonEffector(page, before);
    expect(bone).toBeGreaterThanOrEqual(0);
    const at = await page.evaluate((i) => window.ikPage?.boneScreen(i) ?? null, bone);
    if (!at) throw new Error('bone off screen');
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction((n) => (window.ikPage?.effectors().length ?? 0) === n + 1, before.length);
    expect(await page.evaluate(() => window.ikPage?.effectors())).toEqual([...before, bone]);
    expect(await page.textContent('#selection')).toContain('(end effector)');
    // Its limits are listed as text.
    expect(await page.$$eval('#selection li', (li) => li.length)).toBe(3);
    // The new effector's target can be dragged (it got the gizmo).
    expect(await page.evaluate(() => window.ikPage?.selectedTarget())).toBe(before.length);
    await dragTowardsRoot(page, before.length, 0.1);
    await waitForSettled(page);
    await selectTarget(page, 0); // take the gizmo off the bone
    const moved = await page.evaluate((i) => window.ikPage?.boneScreen(i) ?? null, bone);
    if (!moved) throw new Error('bone off screen');
    await page.mouse.click(moved.x, moved.y);
    await page.waitForFunction((n) => (window.ikPage?.effectors().length ?? 0) === n, before.length);
    expect(await page.evaluate(() => window.ikPage?.effectors())).toEqual(before);
    // R puts the rig back at rest with its targets on the tips.
    await page.keyboard.press('r');
    await page.waitForFunction(() => window.ikPage?.effectorError(0) === 0);
    expect(await stat(page, 'E')).toBe('0');
    expect(errors).toEqual([]);
  });

  it('a click a few pixels beside a bone, where its glyph tapers to a point, still selects it', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'robot-arm');
    const effectors = await page.evaluate(() => window.ikPage?.effectors() ?? []);
    const names = await page.evaluate(() => window.ikPage?.boneNames() ?? []);
    // No target or gizmo on it.
    const bone = await longestNonEffector(page, effectors);
    // 4 px to the side of its axis, a tenth of the way from its base to its glyph's middle (a
    // twentieth of the glyph, whose half-width grows from 0 to 10% of its length at 18%).
    const at = await page.evaluate((i) => {
      const p = window.ikPage;
      const base = p?.boneBase(i),
        middle = p?.boneScreen(i);
      const from = base ? p?.worldToScreen(base) : null;
      if (!from || !middle) return null;
      const dx = middle.x - from.x,
        dy = middle.y - from.y,
        length = Math.hypot(dx, dy);
      return { x: from.x + 0.1 * dx - (4 * dy) / length, y: from.y + 0.1 * dy + (4 * dx) / length, length };
    }, bone);
    if (!at) throw new Error('bone off screen');
    expect(at.length).toBeGreaterThan(40); // the glyph is 4 px wide at most where the click lands
    await page.keyboard.down('Shift'); // select only
    await page.mouse.click(at.x, at.y);
    await page.keyboard.up('Shift');
    expect(await page.textContent('#selection')).toMatch(new RegExp(`^${names[bone]}`));
    expect(await page.evaluate(() => window.ikPage?.effectors())).toEqual(effectors);
    expect(errors).toEqual([]);
  });

  it('works with touch on a phone-sized screen', async (ctx) => {
    const phone = await launchBrowser(true);
    try {
      const { page, errors } = await openPage(phone, ctx);
      await gotoRig(page, 'lamp');
      const from = await targetScreen(page, 0);
      const cdp = await phone.context.newCDPSession(page);
      const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', x = 0, y = 0) =>
        cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y }] });
      await touch('touchStart', from.x, from.y);
      for (let i = 1; i <= 10; i++) await touch('touchMove', from.x - 2 * i, from.y + 2 * i);
      await touch('touchEnd');
      const to = await targetScreen(page, 0);
      expect(Math.hypot(to.x - from.x + 20, to.y - from.y - 20)).toBeLessThan(3);
      await waitForConvergence(page);
      // The side column sits below the view on a narrow screen.
      const view = await page.$eval('#viewport', (e) => e.getBoundingClientRect().bottom);
      const side = await page.$eval('#side', (e) => e.getBoundingClientRect().top);
      expect(side).toBeGreaterThanOrEqual(view - 1);
      expect(errors).toEqual([]);
    } finally {
      await phone.close();
    }
  });

  it('a broken file shows the error and keeps the previous rig', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'knight');
    const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
    await page.evaluate(() => {
      const dt = new DataTransfer();
      dt.items.add(new File([new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0, 99, 0, 0, 0])], 'broken<b>.glb'));
      window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before);
    expect(await page.getAttribute('#message', 'data-kind')).toBe('error');
    const message = (await page.textContent('#message')) ?? '';
    expect(message).toContain('broken<b>.glb'); // shown as text: the markup is not interpreted
    expect(await page.$$('#message b')).toHaveLength(0);
    expect(await page.evaluate(() => window.ikPage?.rigName())).toBe('knight');
    expect(await page.getAttribute('#app', 'data-state')).toBe('ready');
    // The kept rig still solves.
    await dragTowardsRoot(page, 0, 0.1);
    await waitForSettled(page);
    // Only the page's own failure report may be an error; the browser logged nothing else.
    expect(errors).toEqual([]);
  });

  it('loading another rig frees the previous one (WebAssembly and three.js objects)', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'lamp');
    await dragTowardsRoot(page, 0, 0.1);
    await waitForConvergence(page);
    await renderedFrames(page);
    const first = await page.evaluate(() => window.ikPage?.alive());
    const select = page
      .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^project rig$/ }) })
      .locator('select');
    for (const [rig, label] of [
      ['knight', 'knight'],
      ['character', 'character (60+ joints)'],
      ['lamp', 'lamp'],
    ]) {
      const n = await page.evaluate(() => window.ikPage?.loads() ?? 0);
      await select.selectOption({ label });
      await page.waitForFunction((k) => (window.ikPage?.loads() ?? 0) > k, n);
      expect(await page.evaluate(() => window.ikPage?.rigName())).toBe(rig);
      await page.keyboard.press('c'); // every method solves (in the compare worker, which frees its own session)
      await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
        timeout: 30_000,
      });
      expect(await page.evaluate(() => window.ikPage?.alive().sessions)).toBe(1);
      // From the rest pose every method starts with E = 0: the plot says there is nothing to plot.
      await page.waitForFunction(
        () => document.querySelector<HTMLElement>('#compare .plot')?.dataset.state === 'drawn',
      );
      expect(await page.locator('#compare .plot-note').isVisible()).toBe(true);
    }
    await dragTowardsRoot(page, 0, 0.1);
    await waitForConvergence(page);
    await renderedFrames(page);
    const last = await page.evaluate(() => window.ikPage?.alive());
    expect(last?.sessions).toBe(1);
    expect(await page.$$eval('#compare .compare-table tbody tr', (rows) => rows.length)).toBe(5);
    expect(last?.solvers).toBe(1); // the live method's: compare's solvers live in its worker
    // Same rig, same GPU objects as before the round trip (the compare plot made none).
    expect(last?.geometries).toBe(first?.geometries);
    expect(last?.textures).toBe(first?.textures);
    expect(errors).toEqual([]);
  });

  // Writes docs/screenshot.png (the README's picture) when UPDATE_SCREENSHOT=1, else test-results/.
  it('shows the knight for the README (docs/screenshot.png)', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /hand/i));
    await dragBy(page, hand, 30, -70);
    await waitForSettled(page);
    // Compare every method from the rest pose to these targets.
    await (await panelControl(page, /^compare: start from$/)).locator('select').selectOption('rest pose');
    // Show one joint's limits (shift-click: select without toggling the effector).
    const bone = await page.evaluate(() => {
      const p = window.ikPage;
      const i = p?.boneNames().findIndex((n) => /forearm\.R/i.test(n)) ?? -1;
      return p && i >= 0 ? p.boneScreen(i) : null;
    });
    if (bone) {
      await page.keyboard.down('Shift');
      await page.mouse.click(bone.x, bone.y);
      await page.keyboard.up('Shift');
    }
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
      timeout: 30_000,
    });
    // The compare's plot has drawn what it was given (the side column's own plot is below it, off
    // screen, and draws when scrolled to), and the page has rendered since.
    await page.waitForFunction(() => document.querySelector<HTMLElement>('#compare .plot')?.dataset.state === 'drawn');
    await renderedFrames(page);
    const shot = process.env.UPDATE_SCREENSHOT === '1' ? 'docs/screenshot.png' : 'test-results/knight.png';
    mkdirSync(join(repoRoot, shot, '..'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, shot) });
    // One row per method, in the menu's order.
    expect(
      await page.$$eval('#compare .compare-table tbody tr', (rows) =>
        rows.map((r) => (r as HTMLElement).dataset.method),
      ),
    ).toEqual(
      await page
        .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^method$/ }) })
        .locator('option')
        .allTextContents(),
    );
    expect(errors).toEqual([]);
  });

  it('measures the main-thread time per solve while dragging on the largest rig', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await page.setViewportSize({ width: 800, height: 500 }); // software WebGL draws more frames per second
    await gotoRig(page, 'character');
    const bones = await page.evaluate(() => document.getElementById('rig-name')?.textContent ?? '');
    const hand = await selectTarget(page, await effectorNamed(page, /hand|wrist/i));
    const solves = async (): Promise<number> => (await page.evaluate(() => window.ikPage?.solveMs().total)) ?? 0;
    // A first drag warms up (WebAssembly functions compile on first call), then drag until the
    // 121-solve window holds only later solves: one solve per animation frame.
    await dragTowardsRoot(page, hand, 0.1, 10, false);
    const warm = await solves();
    for (let round = 0; round < 8 && (await solves()) < warm + 121; round++)
      await dragTowardsRoot(page, hand, round % 2 ? 0.15 : -0.15, 30, false);
    // The last solve has stopped for a reason other than its budget, and the stats show it.
    await waitForSettled(page);
    await page.waitForFunction(
      () =>
        Number(document.querySelector<HTMLElement>('[data-stat="median"]')?.dataset.value) ===
        window.ikPage?.solveMs().median,
    );
    const ms = await page.evaluate(() => window.ikPage?.solveMs());
    const isolated = await page.evaluate(() => crossOriginIsolated);
    const f = (x: number | undefined): string => (x ?? NaN).toFixed(3);
    console.log(
      `[perf] ${bones}: main-thread ms per solve while dragging (method ${await statText(page, 'method')}), ` +
        `last ${ms?.n} of ${ms?.total} solves: median ${f(ms?.median)}, p95 ${f(ms?.p95)}, max ${f(ms?.max)} ms ` +
        `(timer resolution ${isolated ? '5 us, cross-origin isolated' : '100 us'}); ` +
        `slowest since load: ${JSON.stringify(await page.evaluate(() => window.ikPage?.slowestSolve()))}`,
    );
    expect(Number(await stat(page, 'median'))).toBe(ms?.median);
    expect(ms?.total).toBeGreaterThan(warm);
    expect(errors).toEqual([]);
  });
});

/** The longest bone that is not one of `effectors`, or -1. */
async function longestNonEffector(page: Page, effectors: number[]): Promise<number> {
  return page.evaluate((eff) => {
    const lengths = window.ikPage?.boneLengths() ?? [];
    let best = -1;
    lengths.forEach((l, i) => {
      if (!eff.includes(i) && (best < 0 || l > lengths[best])) best = i;
    });
    return best;
  }, effectors);
}
