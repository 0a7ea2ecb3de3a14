// The deployable site: `npm run build` (scripts/build-site.sh) writes dist/site/, which a plain
// static file server hosts with no dev server and no special headers: the page loads a rig and
// solves a drag onto its target (saying that its timer is coarse without cross-origin isolation),
// and the embed example's widgets load from ik-widget.js.
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { launchBrowser, openPage, repoRoot, startStatic, type BrowserSession } from './harness.js';
import { dragBy, effectorNamed, gotoRig, selectTarget, waitForConvergence } from './page_helpers.js';

const site = join(repoRoot, 'dist/site');
let server: { url: string; close: () => Promise<void> };
let browser: BrowserSession;

beforeAll(async () => {
  execFileSync('bash', ['scripts/build-site.sh'], { cwd: repoRoot, stdio: ['ignore', 'ignore', 'inherit'] });
  server = await startStatic([['/', site]]);
  browser = await launchBrowser();
}, 300_000);

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

describe('the static build (dist/site/)', () => {
  it('holds the page, the embed example, the widget script, the models and the WebAssembly', () => {
    for (const file of ['index.html', 'embed-example.html', 'ik-widget.js', 'models/knight.glb'])
      expect(existsSync(join(site, file)), file).toBe(true);
    const assets = execFileSync('ls', [join(site, 'assets')], { encoding: 'utf8' });
    expect(assets).toMatch(/\.wasm/);
  });

  it("keeps the test probes out of the page's bundle: a chunk of their own, fetched only under automation or with ?probe", () => {
    const html = readFileSync(join(site, 'index.html'), 'utf8');
    const entry = html.match(/src="\/?(assets\/index-[^"]+\.js)"/)?.[1];
    if (!entry) throw new Error('index.html names no entry script');
    const scripts = readdirSync(join(site, 'assets')).filter((f) => f.endsWith('.js'));
    const withProbe = scripts.filter((f) => readFileSync(join(site, 'assets', f), 'utf8').includes('gizmoAxis')); // a probe's method
    expect(withProbe).toHaveLength(1);
    expect(withProbe[0]).toMatch(/^probe-/);
    expect(readFileSync(join(site, entry), 'utf8')).not.toContain('gizmoAxis');
  });

  it('served by a plain static server, the page loads a rig and solves a drag', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await gotoRig(page, server.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragBy(page, hand, 30, -70);
    await waitForConvergence(page);
    // No isolation headers here: the stats say the timer is coarse, and why.
    expect(await page.evaluate(() => window.crossOriginIsolated)).toBe(false);
    expect(await page.textContent('[data-stat="timer"]')).toMatch(/coarse, 0\.1 ms/);
    expect(await page.getAttribute('[data-stat="timer"]', 'title')).toMatch(/cross-origin isolated/);
    expect(errors).toEqual([]);
  });

  it('served by a plain static server, the embed example shows its widgets ready', async (ctx) => {
    const { page, errors } = await openPage(browser, ctx);
    await page.goto(`${server.url}embed-example.html`);
    await page.waitForFunction(
      () => {
        const widgets = [...document.querySelectorAll('ik-widget')];
        return (
          widgets.length > 0 &&
          widgets.every((w) => ['ready', 'error'].includes((w as HTMLElement).dataset.state ?? ''))
        );
      },
      null,
      { timeout: 30_000 },
    );
    const states = await page.$$eval('ik-widget', (ws) => ws.map((w) => (w as HTMLElement).dataset.state));
    expect(states.every((s) => s === 'ready')).toBe(true);
    expect(errors).toEqual([]);
  });
});
