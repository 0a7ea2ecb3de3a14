// Browser-test harness: a vite server on a free port, headless Chromium through playwright-core
// with flags that give WebGL without a GPU (SwiftShader: CHROMIUM_FLAGS), console-error capture, and a
// screenshot in test-results/ when a test fails; waiting for the page's animation frames.
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { createServer as createHttpServer, type Server } from 'node:http';
import { createServer as createNetServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { chromium, type BrowserContext, type Page } from 'playwright-core';
import { createServer, type ViteDevServer } from 'vite';

export const repoRoot = resolve(import.meta.dirname, '../..');
export const resultsDir = join(repoRoot, 'test-results');

const CHROMIUM_FLAGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
];

export async function freePort(): Promise<number> {
  return new Promise((ok, fail) => {
    const s = createNetServer();
    s.once('error', fail);
    s.listen(0, '127.0.0.1', () => {
      const addr = s.address();
      const port = typeof addr === 'object' && addr ? addr.port : 0;
      s.close(() => ok(port));
    });
  });
}

/** The page's vite dev server (vite.config.ts) on a free port. */
export async function startVite(): Promise<{ url: string; close: () => Promise<void> }> {
  const port = await freePort();
  const server: ViteDevServer = await createServer({
    configFile: join(repoRoot, 'vite.config.ts'),
    logLevel: 'warn',
    // Warm-up: the page's modules are transformed while Chromium starts, not on the first load.
    server: {
      port,
      strictPort: true,
      host: '127.0.0.1',
      hmr: false,
      warmup: { clientFiles: ['./index.html', './src/main.ts'] },
    },
  });
  await server.listen();
  return { url: `http://127.0.0.1:${port}/`, close: () => server.close() };
}

/** A plain static server: `routes` maps URL prefixes to folders (first match wins). */
export async function startStatic(routes: [string, string][]): Promise<{ url: string; close: () => Promise<void> }> {
  const { readFile } = await import('node:fs/promises');
  const types: Record<string, string> = {
    '.html': 'text/html; charset=utf-8',
    '.js': 'text/javascript',
    '.glb': 'model/gltf-binary',
    '.gltf': 'model/gltf+json',
    '.json': 'application/json',
    '.wasm': 'application/wasm',
    '.css': 'text/css',
    '.png': 'image/png',
  };
  const server: Server = createHttpServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    const route = routes.find(([prefix]) => path.startsWith(prefix));
    if (!route || path.includes('..')) {
      res.writeHead(404).end();
      return;
    }
    // As any static server: a folder's URL serves its index.html.
    const file = join(route[1], path.slice(route[0].length), path.endsWith('/') ? 'index.html' : '');
    readFile(file).then(
      (body) => {
        const ext = file.slice(file.lastIndexOf('.'));
        res.writeHead(200, { 'content-type': types[ext] ?? 'application/octet-stream' }).end(body);
      },
      () => res.writeHead(404).end(),
    );
  });
  const port = await freePort();
  await new Promise<void>((ok) => server.listen(port, '127.0.0.1', ok));
  return { url: `http://127.0.0.1:${port}/`, close: () => new Promise((ok) => server.close(() => ok())) };
}

export interface BrowserSession {
  context: BrowserContext;
  close(): Promise<void>;
}

/** Chromium with a fresh profile; `phone` emulates a 390x844 touch screen. */
export async function launchBrowser(phone = false): Promise<BrowserSession> {
  const dir = mkdtempSync(join(tmpdir(), 'ik-chromium-'));
  const context = await chromium.launchPersistentContext(dir, {
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    headless: true,
    args: CHROMIUM_FLAGS,
    ...(phone
      ? { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true }
      : { viewport: { width: 1280, height: 800 } }),
  });
  return {
    context,
    async close() {
      await context.close();
      rmSync(dir, { recursive: true, force: true });
    },
  };
}

export interface WatchedPage {
  page: Page;
  /** Console errors and uncaught exceptions so far. */
  errors: string[];
}

/** A new tab that records console errors; on test failure it saves a screenshot named after the test. */
export async function openPage(
  session: BrowserSession,
  ctx: { task: { name: string }; onTestFailed: (fn: () => Promise<void> | void) => void },
): Promise<WatchedPage> {
  const page = await session.context.newPage();
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(`${e.name}: ${e.message}`));
  ctx.onTestFailed(async () => {
    mkdirSync(resultsDir, { recursive: true });
    const name = ctx.task.name
      .replace(/[^a-z0-9]+/gi, '-')
      .replace(/^-|-$/g, '')
      .slice(0, 80);
    await page.screenshot({ path: join(resultsDir, `${name}.png`) }).catch(() => {});
    if (errors.length) console.error(`console errors in "${ctx.task.name}":\n${errors.join('\n')}`);
  });
  return { page, errors };
}

/** Resolves after the page has run its next animation frame (a per-frame solve; the 3D view draws on demand). */
export async function nextFrame(page: Page): Promise<void> {
  await page.evaluate(() => new Promise<void>((done) => requestAnimationFrame(() => done())));
}

/** Resolves after `n` frames drawn: what the page changed before is on screen. */
export async function renderedFrames(page: Page, n = 2): Promise<void> {
  // The page's 3D view draws on demand: ask it for frames and wait until they are drawn.
  const before = await page.evaluate(() => window.ikPage?.redraw() ?? null);
  if (before === null) {
    for (let i = 0; i < n; i++) await nextFrame(page);
    return;
  }
  await page.waitForFunction((until) => (window.ikPage?.drawnFrames() ?? Infinity) >= until, before + n, {
    timeout: 30_000,
  });
}
