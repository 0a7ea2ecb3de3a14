// The three.js package (web/src/lib/, built into dist/lib/ by vite.lib.config.ts) as an app gets
// it: packed with npm pack, installed with npm install --offline into an empty folder together
// with three (this repository's copy, by path), then
// - used from Node (tests/package/reach_check.mjs): attached to the character, whose head and hands
//   then follow the poses of a moving copy, every tracked bone on its target within 0.1% of the height;
// - its example page (avatar-example.html) opened from node_modules/ik-web-avatar/ on a plain static
//   server: dragging the left hand's gizmo moves the left hand bone after it.
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import type { Camera } from 'three';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { AvatarIK } from '../../web/src/lib/index.js';
import {
  launchBrowser,
  openPage,
  renderedFrames,
  repoRoot,
  resultsDir,
  startStatic,
  type BrowserSession,
} from './harness.js';

/** What the example page leaves on window for the console (and this test). */
interface ExampleWindow {
  avatarExample: { avatar: AvatarIK; camera: Camera };
}

const character = join(repoRoot, 'web/public/models/character.glb');
let folder: string;
/** The app folder: package.json and node_modules with ik-web-avatar and three. */
let app: string;
let packedFiles: string[];

beforeAll(() => {
  execFileSync('npx', ['vite', 'build', '--config', 'vite.lib.config.ts', '--logLevel', 'warn'], {
    cwd: repoRoot,
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  folder = mkdtempSync(join(tmpdir(), 'ik-package-'));
  const [packed] = JSON.parse(
    execFileSync('npm', ['pack', join(repoRoot, 'dist/lib'), '--pack-destination', folder, '--json'], {
      cwd: folder,
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'pipe'],
    }),
  ) as [{ filename: string; files: { path: string }[] }];
  packedFiles = packed.files.map((f) => f.path);
  app = join(folder, 'app');
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
  execFileSync(
    'npm',
    [
      'install',
      '--offline',
      '--no-audit',
      '--no-fund',
      join(folder, packed.filename),
      join(repoRoot, 'node_modules/three'),
    ],
    { cwd: app, stdio: ['ignore', 'ignore', 'inherit'] },
  );
}, 120_000);

afterAll(() => {
  if (folder) rmSync(folder, { recursive: true, force: true });
});

describe('the ik-web-avatar package', () => {
  it('packs the module, its types, the WebAssembly, the example and a package.json with three as a peer', () => {
    for (const file of [
      'index.js',
      'index.d.ts',
      'avatar_ik.d.ts',
      'ik_core.wasm',
      'package.json',
      'avatar-example.html',
      'models/character.glb',
    ])
      expect(packedFiles, file).toContain(file);
    const manifest = JSON.parse(readFileSync(join(app, 'node_modules/ik-web-avatar/package.json'), 'utf8'));
    const root = JSON.parse(readFileSync(join(repoRoot, 'package.json'), 'utf8'));
    expect(manifest).toMatchObject({
      name: 'ik-web-avatar',
      version: root.version,
      type: 'module',
      types: './index.d.ts',
    });
    expect(manifest.peerDependencies).toHaveProperty('three');
    expect(manifest.dependencies).toBeUndefined();
  });

  it('in Node, attached to the moved, turned and scaled character, brings the head and hands onto tracked poses within 0.1% of the height', () => {
    copyFileSync(join(repoRoot, 'tests/package/reach_check.mjs'), join(app, 'reach_check.mjs'));
    const run = JSON.parse(execFileSync('node', ['reach_check.mjs', character], { cwd: app, encoding: 'utf8' }));
    const h = run.height;
    expect(h).toBeCloseTo(1.4 * 1.89, 6); // the character's 1.89 height, scaled by 1.4
    expect(run.humanoid).toBe('mixamo');
    for (const moved of run.moved) expect(moved).toBeGreaterThan(0.1 * h); // measured 21% of the height
    for (const role of ['head', 'leftHand', 'rightHand']) expect(run.miss[role], role).toBeLessThan(1e-3 * h);
    expect(run.onTarget).toBe(true);
    for (const off of run.restoredOff) expect(off).toBeLessThan(1e-9 * h); // dispose() puts the bones back
    expect(run.afterDispose).toBe('AvatarIK.update: the avatar was disposed');
  });

  describe('the example page, served from the installed package', () => {
    let server: { url: string; close: () => Promise<void> };
    let browser: BrowserSession;
    beforeAll(async () => {
      server = await startStatic([['/', app]]);
      browser = await launchBrowser();
    });
    afterAll(async () => {
      await browser?.close();
      await server?.close();
    });

    /** The left hand's target on the screen (CSS pixels), its world position and the left hand bone's. */
    async function leftHand(
      page: Page,
    ): Promise<{ screen: { x: number; y: number }; target: number[]; bone: number[] }> {
      return page.evaluate(() => {
        const { avatar, camera } = (window as unknown as ExampleWindow).avatarExample;
        const ndc = avatar.leftHand.position.clone().project(camera);
        const e = avatar.bones.leftHand.matrixWorld.elements;
        return {
          screen: { x: ((ndc.x + 1) / 2) * window.innerWidth, y: ((1 - ndc.y) / 2) * window.innerHeight },
          target: avatar.leftHand.position.toArray(),
          bone: [e[12], e[13], e[14]],
        };
      });
    }

    it('loads the character, and its left hand follows the left hand gizmo dragged with the mouse', async (ctx) => {
      const { page, errors } = await openPage(browser, ctx);
      await page.goto(`${server.url}node_modules/ik-web-avatar/avatar-example.html`);
      await page.waitForFunction(() => document.body.dataset.state !== 'loading', null, { timeout: 30_000 });
      expect(await page.getAttribute('body', 'data-state'), (await page.textContent('#status')) ?? '').toBe('ready');
      await renderedFrames(page);
      const h = await page.evaluate(() => (window as unknown as ExampleWindow).avatarExample.avatar.height);
      const before = await leftHand(page);
      // Grab the gizmo's centre (it moves the target in the screen's plane) and drag it 48 pixels down.
      await page.mouse.move(before.screen.x, before.screen.y);
      await page.mouse.down();
      for (let i = 1; i <= 12; i++) {
        await page.mouse.move(before.screen.x, before.screen.y + 4 * i);
        await renderedFrames(page, 2);
      }
      await page.mouse.up();
      await renderedFrames(page, 30);
      const after = await leftHand(page);
      const distance = (a: number[], b: number[]) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      expect(distance(after.target, before.target)).toBeGreaterThan(0.05 * h); // the gizmo moved the target (measured 8.1% of the height)
      expect(distance(after.bone, before.bone)).toBeGreaterThan(0.05 * h); // and the hand went after it
      expect(distance(after.bone, after.target)).toBeLessThan(0.25 * distance(before.bone, after.target)); // measured 7.7%
      mkdirSync(resultsDir, { recursive: true });
      await page.screenshot({ path: join(resultsDir, 'package-example.png') });
      expect(errors).toEqual([]);
    });
  });
});
