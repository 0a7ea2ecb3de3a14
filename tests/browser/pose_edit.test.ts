// Undo, redo and pose files on the page, from the knight's rest pose as a user starts: a drag, a
// reset and a rig load are undone and redone with Ctrl+Z / Ctrl+Shift+Z, each step giving back the
// exact angles and targets; a pose saved as .json (the panel's button, a real download) and loaded
// back after a reset gives the same angles bit for bit, and undo takes the load back; the posed
// model saved as .glb and opened as a rig shows the same joints at its rest pose to 1e-6 of the
// rig's size; a bad pose file changes nothing and says why.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { treeA7 } from '../../scripts/rig_files/tree_rigs.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragBy,
  effectorNamed,
  gotoRig,
  panelControl,
  selectTarget,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

interface Snapshot {
  rig: string | null;
  angles: number[];
  targets: number[];
}

async function snapshot(page: Page): Promise<Snapshot> {
  return page.evaluate(() => {
    const p = window.ikPage;
    return { rig: p?.rigName() ?? null, angles: p?.angles() ?? [], targets: p?.targets() ?? [] };
  });
}

/** A panel button by its label's start. */
async function panelButton(page: Page, label: RegExp) {
  return (await panelControl(page, label)).locator('button');
}

/** Presses a key (combination) with the page's focus on the view, and waits for what it starts to be drawn. */
async function press(page: Page, keys: string): Promise<void> {
  await page.keyboard.press(keys);
  await page.waitForFunction(() => document.getElementById('app')?.dataset.state === 'ready');
  await renderedFrames(page, 3);
}

/** Every bone's tip by bone name, world coordinates. */
async function boneTips(page: Page): Promise<Record<string, number[]>> {
  return page.evaluate(() => {
    const p = window.ikPage;
    const names = p?.boneNames() ?? [];
    return Object.fromEntries(names.map((n, i) => [n, p?.boneTip(i) ?? []]));
  });
}

describe('undo and redo', () => {
  it('a drag, a reset and a rig load are undone and redone step by step, exactly', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const rest = await snapshot(page);
    expect(await page.evaluate(() => window.ikPage?.undoSteps())).toBe(0);

    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragBy(page, hand, 30, -70);
    await waitForConvergence(page);
    const dragged = await snapshot(page);
    expect(dragged.targets).not.toEqual(rest.targets);
    expect(await page.evaluate(() => window.ikPage?.undoSteps())).toBe(1);

    await press(page, 'r');
    expect((await snapshot(page)).angles).toEqual(rest.angles);
    await page
      .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^project rig/ }) })
      .locator('select')
      .selectOption({ label: 'lamp' });
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'lamp' && document.getElementById('app')?.dataset.state === 'ready',
    );
    expect(await page.evaluate(() => window.ikPage?.undoSteps())).toBe(3);

    await press(page, 'Control+z'); // the lamp's load
    expect(await snapshot(page)).toEqual(rest);
    expect(
      await page
        .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^project rig/ }) })
        .locator('select')
        .inputValue(),
    ).not.toBe('');
    await press(page, 'Control+z'); // the reset
    expect(await snapshot(page)).toEqual(dragged);
    await press(page, 'Control+z'); // the drag
    expect(await snapshot(page)).toEqual(rest);
    await press(page, 'Control+z'); // nothing left: nothing changes
    expect(await snapshot(page)).toEqual(rest);

    await press(page, 'Control+Shift+z');
    expect(await snapshot(page)).toEqual(dragged);
    await press(page, 'Control+Shift+z');
    expect(await snapshot(page)).toEqual(rest);
    await press(page, 'Control+Shift+z');
    expect((await snapshot(page)).rig).toBe('lamp');

    // The panel's buttons do the same, and a new edit after an undo clears the redo.
    await (await panelButton(page, /^undo/)).click();
    await page.waitForFunction(() => window.ikPage?.rigName() === 'knight');
    await renderedFrames(page, 3);
    expect(await snapshot(page)).toEqual(rest);
    await selectTarget(page, hand); // the knight was built anew: no target holds the gizmo
    await dragBy(page, hand, 15, -30);
    await waitForConvergence(page);
    expect(await (await panelButton(page, /^redo/)).isDisabled()).toBe(true);
    expect(errors).toEqual([]);
  });
});

describe('pose files', () => {
  it('a pose saved as .json and loaded back after a reset gives the same angles and targets; undo takes the load back', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragBy(page, hand, 40, -60);
    await waitForConvergence(page);
    const posed = await snapshot(page);

    const save = await panelButton(page, /^save pose \(/);
    const [saved] = await Promise.all([page.waitForEvent('download'), save.click()]);
    expect(saved.suggestedFilename()).toBe('knight-pose.json');
    const file = join(resultsDir, 'knight-pose.json');
    await saved.saveAs(file);
    expect(JSON.parse(readFileSync(file, 'utf8')).format).toBe('ik-pose');

    await press(page, 'r');
    const rest = await snapshot(page);
    expect(rest.angles).not.toEqual(posed.angles);
    await page.setInputFiles('#pose-file', file);
    await page.waitForFunction(() => /pose loaded/.test(document.getElementById('message')?.textContent ?? ''));
    await renderedFrames(page, 3);
    expect(await snapshot(page)).toEqual(posed);

    await press(page, 'Control+z');
    expect(await snapshot(page)).toEqual(rest);

    // A pose file for another rig: refused by name, nothing changes.
    const bad = join(resultsDir, 'bad-pose.json');
    writeFileSync(
      bad,
      JSON.stringify({ format: 'ik-pose', version: 1, rig: 'x', bones: { 'no such bone': [0, 0, 0] }, effectors: [] }),
    );
    await page.setInputFiles('#pose-file', bad);
    await page.waitForFunction(() => document.getElementById('message')?.dataset.kind === 'error');
    expect(await page.textContent('#message')).toMatch(/bad-pose\.json.*no such bone/);
    expect(await snapshot(page)).toEqual(rest);
    expect(errors).toEqual([]);
  });

  it('the posed model saved as .glb and opened as a rig shows the same joints at its rest pose (1e-6 of size)', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragBy(page, hand, 40, -60);
    await waitForConvergence(page);
    const tips = await boneTips(page);
    const size = await page.evaluate(() => {
      const b = window.ikPage?.bounds();
      return b ? Math.hypot(b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]) : NaN;
    });

    const save = await panelButton(page, /^save posed model/);
    const [saved] = await Promise.all([page.waitForEvent('download'), save.click()]);
    expect(saved.suggestedFilename()).toBe('knight-posed.glb');
    const file = join(resultsDir, 'knight-posed.glb');
    await saved.saveAs(file);

    await page.setInputFiles('#rig-file', file);
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'knight-posed' && document.getElementById('app')?.dataset.state === 'ready',
    );
    await renderedFrames(page, 3);
    const again = await boneTips(page);
    expect(Object.keys(again)).toEqual(Object.keys(tips));
    let worst = 0;
    for (const [name, p] of Object.entries(tips))
      worst = Math.max(worst, Math.hypot(p[0] - again[name][0], p[1] - again[name][1], p[2] - again[name][2]));
    expect(worst / size).toBeLessThan(1e-6);
    expect(errors).toEqual([]);
  });

  it('an A7 rig cannot be saved as .glb: the button is disabled and says why', async (ctx) => {
    const { page } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    expect(await (await panelButton(page, /^save posed model/)).isDisabled()).toBe(false);
    await page.setInputFiles('#rig-file', {
      name: 'two.json',
      mimeType: 'application/json',
      buffer: Buffer.from(treeA7([-1, 0, 1])),
    });
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'two' || document.getElementById('message')?.dataset.kind === 'error',
    );
    expect(await page.textContent('#message')).not.toMatch(/Could not/);
    const button = await panelButton(page, /^save posed model/);
    expect(await button.isDisabled()).toBe(true);
    expect(
      await page
        .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^save posed model/ }) })
        .getAttribute('title'),
    ).toMatch(/A7/);
  });
});
