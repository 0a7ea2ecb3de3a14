// The page on a phone (390x844, touch): the side column is a bottom sheet under the view, so the
// stats' status is on screen from the start without scrolling the page; its handle expands it to
// most of the screen, where the panel's Teaching folder is reached by scrolling inside the sheet
// (the page itself never scrolls), and collapses it again. A touch drag on a target still moves it
// and the hand follows; the compare table fits the screen's width; vertical swipes on the view
// cannot take the camera under the floor.
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { launchBrowser, openPage, startVite, type BrowserSession } from './harness.js';
import { effectorNamed, gotoRig, swipe, targetScreen, waitForConvergence } from './page_helpers.js';

let server: { url: string; close: () => Promise<void> };
let phone: BrowserSession;
beforeAll(async () => {
  server = await startVite();
  phone = await launchBrowser(true);
});
afterAll(async () => {
  await phone?.close();
  await server?.close();
});

const HEIGHT = 844;

async function rect(page: Page, selector: string): Promise<{ top: number; bottom: number; height: number }> {
  return page.$eval(selector, (e) => {
    const r = e.getBoundingClientRect();
    return { top: r.top, bottom: r.bottom, height: r.height };
  });
}

describe('the page on a phone', () => {
  it('shows the stats in a bottom sheet that expands to the panel and collapses, the page never scrolling', async (ctx) => {
    const { page, errors } = await openPage(phone, ctx);
    await gotoRig(page, server.url, 'knight');
    const handle = page.locator('#sheet-handle');
    expect(await handle.getAttribute('aria-expanded')).toBe('false');
    const status = await rect(page, '[data-stat="status"]');
    expect(status.top).toBeGreaterThan(0);
    expect(status.bottom).toBeLessThanOrEqual(HEIGHT);
    const side = await rect(page, '#side');
    expect(side.bottom).toBeLessThanOrEqual(HEIGHT + 1);
    expect((await rect(page, '#viewport')).bottom).toBeLessThanOrEqual(side.top + 1);
    expect((await rect(page, '#viewport')).height).toBeGreaterThan(HEIGHT * 0.45);
    expect(await page.evaluate(() => document.documentElement.scrollHeight)).toBeLessThanOrEqual(HEIGHT + 1);
    await page.screenshot({ path: 'test-results/phone-collapsed.png' });

    await handle.tap();
    expect(await handle.getAttribute('aria-expanded')).toBe('true');
    await page.waitForFunction(() => document.getElementById('side')!.getBoundingClientRect().height > 0.7 * 844);
    const teaching = page.locator('.lil-gui .lil-gui > .lil-title', { hasText: 'Teaching' });
    await teaching.scrollIntoViewIfNeeded();
    const t = await teaching.boundingBox();
    const open = await rect(page, '#side');
    expect(t!.y).toBeGreaterThanOrEqual(open.top);
    expect(t!.y + t!.height).toBeLessThanOrEqual(HEIGHT);
    await teaching.tap();
    const compare = page.locator('.lil-controller', {
      has: page.locator('.lil-name', { hasText: /^compare all methods/ }),
    });
    await compare.scrollIntoViewIfNeeded();
    expect(await compare.isVisible()).toBe(true);
    expect(await page.evaluate(() => window.scrollY)).toBe(0);
    await page.screenshot({ path: 'test-results/phone-expanded.png' });

    await handle.tap();
    expect(await handle.getAttribute('aria-expanded')).toBe('false');
    await page.waitForFunction(() => document.getElementById('side')!.getBoundingClientRect().height < 0.5 * 844);
    expect((await rect(page, '[data-stat="status"]')).bottom).toBeLessThanOrEqual(HEIGHT);
    expect(errors).toEqual([]);
  });

  it('a touch drag moves a target and the hand follows; the compare box fits the screen', async (ctx) => {
    const { page, errors } = await openPage(phone, ctx);
    await gotoRig(page, server.url, 'knight');
    const hand = await effectorNamed(page, /^hand\.L$/);
    const cdp = await phone.context.newCDPSession(page);
    const from = await targetScreen(page, hand);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: from.x, y: from.y }] }); // a tap gives it the gizmo
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await page.waitForFunction((k) => window.ikPage?.selectedTarget() === k, hand);
    const start = await page.evaluate((k) => window.ikPage!.targetPosition(k)!, hand);
    await swipe(cdp, from.x, from.y, 12, -30);
    const end = await page.evaluate((k) => window.ikPage!.targetPosition(k)!, hand);
    expect(Math.hypot(end[0] - start[0], end[1] - start[1], end[2] - start[2])).toBeGreaterThan(0);
    const to = await targetScreen(page, hand);
    expect(Math.hypot(to.x - from.x - 12, to.y - from.y + 30)).toBeLessThan(3);
    await waitForConvergence(page);

    // Compare (the Teaching folder's button, or C): its box fits the screen's width, no sideways scrolling.
    await page.keyboard.press('c');
    await page.waitForFunction(() => document.getElementById('compare')?.dataset.state === 'done', null, {
      timeout: 30_000,
    });
    const box = await page.evaluate(() => {
      const c = document.getElementById('compare')!;
      return { scroll: c.scrollWidth, width: c.clientWidth, right: c.getBoundingClientRect().right };
    });
    expect(box.scroll).toBeLessThanOrEqual(box.width);
    expect(box.right).toBeLessThanOrEqual(390);
    expect(errors).toEqual([]);
  });

  it('vertical swipes on the view cannot take the camera under the floor', async (ctx) => {
    const { page, errors } = await openPage(phone, ctx);
    await gotoRig(page, server.url, 'knight');
    const cdp = await phone.context.newCDPSession(page);
    const view = await rect(page, '#viewport');
    const floor = await page.evaluate(() => window.ikPage!.floorY());
    for (const dy of [-600, 600, -600]) {
      await swipe(cdp, 40, view.top + view.height / 2, 0, dy * (view.height / 844), 20); // at the view's edge: no target there
      const camera = await page.evaluate(() => window.ikPage!.cameraPosition());
      expect(camera[1], `after a swipe of ${dy} px`).toBeGreaterThan(floor);
    }
    expect(errors).toEqual([]);
  });
});
