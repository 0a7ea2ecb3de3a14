// Hostile files dropped on the page: millions of empty nodes (.gltf) and a few-KB .glb of
// gigabytes of zero-filled accessors are refused with a message naming the file and the limit,
// before three.js's GLTFLoader sees them, and the rig shown stays (and still solves). A pose saved
// from an A7 rig (bones without names, keyed "#index") loads back onto it.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { a7Dir, a7MissingMessage, a7Present, a7Required } from '../../scripts/a7_folder.js';
import { manyNodesGltf, zeroAccessorGlb } from '../rig/hostile_rigs.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragBy,
  dragTowardsRoot,
  gotoRig,
  panelControl,
  selectTarget,
  usePageServer,
  waitForConvergence,
  waitForSettled,
} from './page_helpers.js';

const env = usePageServer();

/** Chooses `buffer` as the rig file `name` and waits until the page has dealt with it; returns the message shown. */
async function openFile(page: Page, name: string, buffer: Uint8Array): Promise<string> {
  const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
  await page.setInputFiles('#rig-file', { name, mimeType: 'application/octet-stream', buffer: Buffer.from(buffer) });
  await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before, { timeout: 20_000 });
  return (await page.textContent('#message')) ?? '';
}

const bombs: [string, () => Uint8Array, RegExp][] = [
  ['nodes-4m.gltf', () => manyNodesGltf(4_000_000), /more than 1000000 arrays and objects/],
  ['nodes-1m.gltf', () => manyNodesGltf(1_000_000), /more than 1000000 arrays and objects/],
  ['nodes-100k.gltf', () => manyNodesGltf(100_001), /100001 nodes; at most 100000 \(the limit on glTF nodes\)/],
  [
    'zeros-40.glb',
    () => zeroAccessorGlb(40),
    /bytes of accessor data in accessors\[0\] .* at most 268435456 bytes \(256 MiB\) in one file/,
  ],
  ['zeros-3.glb', () => zeroAccessorGlb(3), /bytes of accessor data .* at most 268435456 bytes/],
];

describe('hostile files on the page', () => {
  it('refuses memory bombs naming the file and the limit, and keeps the rig shown', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    for (const [name, make, limit] of bombs) {
      const message = await openFile(page, name, make());
      expect(await page.getAttribute('#message', 'data-kind'), message).toBe('error');
      expect(message).toContain(`Could not load ${name}: ${name}: `);
      expect(message).toMatch(limit);
      expect(message).toMatch(/still showing knight$/);
      expect(await page.evaluate(() => window.ikPage?.rigName())).toBe('knight');
      expect(await page.getAttribute('#app', 'data-state')).toBe('ready');
    }
    // The kept rig still solves.
    await dragTowardsRoot(page, 0, 0.1);
    await waitForSettled(page);
    expect(errors).toEqual([]);
  });

  it('saves a pose of an A7 rig as .json and loads it back', async (ctx) => {
    if (!a7Present) {
      if (a7Required) throw new Error(a7MissingMessage);
      ctx.skip(`A7 rigs folder missing: ${a7Dir}`);
    }
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    const message = await openFile(page, 'knight.json', readFileSync(join(a7Dir, 'knight.json')));
    expect(message).not.toMatch(/Could not/);
    expect(await page.evaluate(() => window.ikPage?.rigName())).toBe('knight');
    await dragBy(page, await selectTarget(page, 0), 40, -60);
    await waitForConvergence(page);
    const posed = await page.evaluate(() => window.ikPage?.angles() ?? []);
    expect(posed.some((a) => a !== 0)).toBe(true);

    const save = (await panelControl(page, /^save pose \(/)).locator('button');
    const [saved] = await Promise.all([page.waitForEvent('download'), save.click()]);
    const file = join(resultsDir, 'a7-knight-pose.json');
    await saved.saveAs(file);
    expect(Object.keys(JSON.parse(readFileSync(file, 'utf8')).bones).slice(0, 3)).toEqual(['#0', '#1', '#2']);

    await page.keyboard.press('r');
    await page.waitForFunction(() => (window.ikPage?.angles() ?? [1]).every((a) => a === 0));
    await page.setInputFiles('#pose-file', file);
    await page.waitForFunction(() =>
      /pose loaded|Could not/.test(document.getElementById('message')?.textContent ?? ''),
    );
    expect(await page.textContent('#message')).toMatch(/pose loaded/);
    await renderedFrames(page, 3);
    expect(await page.evaluate(() => window.ikPage?.angles() ?? [])).toEqual(posed);
    expect(errors).toEqual([]);
  });
});
