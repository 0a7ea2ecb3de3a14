// The widget as a course page uses it: the single-file build (dist/widget/ik-widget.js) served
// as static files next to web/embed-example.html and the project models; no bundler on the page.
import { join } from 'node:path';

import { build } from 'vite';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { launchBrowser, openPage, repoRoot, startStatic, type BrowserSession } from './harness.js';

let server: { url: string; close: () => Promise<void> };
let browser: BrowserSession;

beforeAll(async () => {
  await build({ configFile: join(repoRoot, 'vite.widget.config.ts'), logLevel: 'warn' });
  server = await startStatic([
    ['/widget/', join(repoRoot, 'dist/widget')],
    ['/models/', join(repoRoot, 'web/public/models')],
    ['/', join(repoRoot, 'web')],
  ]);
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

describe('<ik-widget>', () => {
  it('the example course page renders two widgets from the single-file build', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    const requests: string[] = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(`${server.url}embed-example.html`);
    await page.waitForFunction(() => {
      const w = [...document.querySelectorAll('ik-widget')];
      return w.length === 2 && w.every((x) => (x as HTMLElement).dataset.state !== 'loading');
    }, null, { timeout: 30_000 });
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
    expect(requests.filter((u) => u.endsWith('.js')).map((u) => new URL(u).pathname)).toEqual(['/widget/ik-widget.js']);
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
    await page.waitForFunction(() => document.getElementById('broken')?.dataset.state === 'error', null, { timeout: 30_000 });
    const text = await page.$eval('#broken', (w) => w.shadowRoot?.querySelector('.message')?.textContent ?? '');
    expect(text).toContain('<i>missing</i>.glb');
    expect(text).toContain('404');
    expect(await page.$eval('#broken', (w) => w.shadowRoot?.querySelectorAll('i').length)).toBe(0);
    // The other widgets are unaffected.
    await page.waitForFunction(() => [...document.querySelectorAll('ik-widget:not(#broken)')].every((w) => (w as HTMLElement).dataset.state === 'ready'));
    // The browser reports the 404 itself; nothing else went wrong.
    expect(errors.filter((e) => !/404/.test(e))).toEqual([]);
  });
});
