// Pole handles on the page, from the project character's rest pose (straight limbs), with real
// mouse drags: P or the panel's box shows one yellow handle per arm and leg, each placed where its
// elbow or knee bends (elbows back, knees forward) and sent to the solve as goals.poles; with the
// handles off no poles are sent. After a hand target is pulled in (the arm bends), dragging that
// arm's pole handle far to one side turns the elbow to that side of the shoulder-wrist line while
// the hand stays on its target. Reset re-places the poles; changing the effectors rebuilds them.
// On the knight, whose arms hang straight, the elbow pole starts behind the elbow (the way it
// bends); after the hand is pulled in a little, the pole dragged 0.4 units sideways carries the
// elbow along while the hand stays on target. Shortcuts work after clicking a panel checkbox, not while typing in a
// number field.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { openPage, renderedFrames } from './harness.js';
import {
  dragPoleBy,
  dragTowardsRoot,
  effectorNamed,
  gotoRig,
  panelControl,
  selectPole,
  selectTarget,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type V3 = [number, number, number];
const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** The part of `p - root` across the line from `root` to `tip`, made unit length. */
function across(root: V3, tip: V3, p: V3): V3 {
  const line = sub(tip, root);
  const d = sub(p, root);
  const t = dot(d, line) / dot(line, line);
  const r: V3 = [d[0] - t * line[0], d[1] - t * line[1], d[2] - t * line[2]];
  const n = Math.hypot(...r);
  return [r[0] / n, r[1] / n, r[2] / n];
}

/** Cosine between the elbow's (knee's) and `p`'s directions off the limb's root-tip line: 1 on the same side. */
async function sideOf(page: Page, pole: number, p?: V3): Promise<number> {
  const h = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
  if (!h) throw new Error(`no pole handle ${pole}`);
  return dot(across(h.root, h.tip, h.joint), across(h.root, h.tip, p ?? h.point));
}

async function poleCount(page: Page): Promise<{ shown: number; sent: number }> {
  return page.evaluate(() => ({
    shown: window.ikPage?.poleHandles().length ?? -1,
    sent: window.ikPage?.solvePoles().length ?? -1,
  }));
}

/** The pole handle on the limb whose lower bone's name matches `pattern`. */
async function poleNamed(page: Page, pattern: RegExp): Promise<number> {
  const j = await page.evaluate((source) => {
    const p = window.ikPage;
    const names = p?.boneNames() ?? [];
    return (p?.poleHandles() ?? []).findIndex((h) => new RegExp(source).test(names[h.bone]));
  }, pattern.source);
  if (j < 0) throw new Error(`no pole handle on ${pattern}`);
  return j;
}

/**
 * Drags the selected pole handle j with the mouse the way `towards` (rig units) looks on the
 * screen until its pole has moved `distance` rig units: the gizmo moves it in the plane facing
 * the camera, so a second drag along the same line makes up what the first fell short.
 */
async function dragPoleAcross(page: Page, j: number, towards: V3, distance: number): Promise<void> {
  const pole = async (): Promise<V3> => {
    const p = await page.evaluate((i) => window.ikPage?.poleHandles()[i]?.point ?? null, j);
    if (!p) throw new Error(`no pole handle ${j}`);
    return p;
  };
  const start = await pole();
  const pixels = await page.evaluate(
    ([p, q]) => {
      const a = window.ikPage?.worldToScreen(p),
        b = window.ikPage?.worldToScreen(q);
      return a && b ? { x: b.x - a.x, y: b.y - a.y } : null;
    },
    [start, [start[0] + towards[0], start[1] + towards[1], start[2] + towards[2]]] as [V3, V3],
  );
  if (!pixels) throw new Error('no screen position');
  await dragPoleBy(page, j, pixels.x, pixels.y, 20);
  const moved = Math.hypot(...sub(await pole(), start));
  const more = distance / moved - 1;
  if (moved > 0 && Math.abs(more) > 0.01) await dragPoleBy(page, j, pixels.x * more, pixels.y * more, 10);
}

function poleBox(page: Page) {
  return page
    .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^pole handles/ }) })
    .locator('input');
}

async function worstTipError(page: Page): Promise<number> {
  return page.evaluate(() => {
    const p = window.ikPage;
    return Math.max(...(p?.effectors() ?? []).map((_, k) => p?.effectorError(k) ?? Infinity));
  });
}

describe('pole handles', () => {
  it('off: no poles are sent; P shows one per arm and leg where the joint bends, sent with the solve', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    expect(await poleCount(page)).toEqual({ shown: 0, sent: 0 });
    // A drag with the handles off: plain goals (no poles) all the way.
    const hand = await selectTarget(page, await effectorNamed(page, /LeftHand$/));
    await dragTowardsRoot(page, hand, 0.2);
    await waitForConvergence(page);
    expect(await poleCount(page)).toEqual({ shown: 0, sent: 0 });

    await page.keyboard.press('p');
    await renderedFrames(page);
    expect(await poleBox(page).isChecked()).toBe(true);
    const poles = await page.evaluate(() => window.ikPage?.poleHandles() ?? []);
    const names = await page.evaluate(() => window.ikPage?.boneNames() ?? []);
    expect(poles.map((p) => names[p.bone]).sort()).toEqual([
      'mixamorig:LeftForeArm',
      'mixamorig:LeftLeg',
      'mixamorig:RightForeArm',
      'mixamorig:RightLeg',
    ]);
    expect(await page.evaluate(() => window.ikPage?.solvePoles().map((p) => p.bone))).toEqual(poles.map((p) => p.bone));
    for (const p of poles) {
      // About one limb length from the joint, on the side the joint bends to (the character faces +Z).
      const length = Math.hypot(...sub(p.joint, p.root)) + Math.hypot(...sub(p.tip, p.joint));
      expect(Math.hypot(...sub(p.point, p.joint)) / length).toBeCloseTo(1, 1);
      const z = (p.point[2] - p.joint[2]) / length;
      if (/Leg$/.test(names[p.bone]))
        expect(z).toBeGreaterThan(0.9); // knees forward
      else expect(z).toBeLessThan(-0.9); // elbows back
    }
    await page.keyboard.press('p');
    await renderedFrames(page);
    expect(await poleCount(page)).toEqual({ shown: 0, sent: 0 });
    expect(await poleBox(page).isChecked()).toBe(false);
    expect(errors).toEqual([]);
  });

  it('dragging an arm’s pole handle far to one side turns the elbow to that side; the hand stays on target', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    await poleBox(page).click();
    expect(await poleCount(page)).toEqual({ shown: 4, sent: 4 });
    // Bend the left arm: pull its hand a little towards the body.
    const hand = await selectTarget(page, await effectorNamed(page, /LeftHand$/));
    await dragTowardsRoot(page, hand, 0.2);
    await waitForConvergence(page);
    const pole = await poleNamed(page, /LeftForeArm$/);
    const bent = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!bent) throw new Error('no pole');
    expect(await sideOf(page, pole)).toBeGreaterThan(0.9); // the elbow bends towards its (unmoved) pole

    // The hand's gizmo lies over the elbow's pole handle: hand the gizmo to the head first, as a user would.
    await selectTarget(page, await effectorNamed(page, /Head$/));
    await selectPole(page, pole);
    expect(await page.evaluate(() => window.ikPage?.selectedTarget())).toBeNull();
    await dragPoleBy(page, pole, 0, 260); // far down the screen
    await renderedFrames(page);
    const moved = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!moved) throw new Error('no pole');
    expect(moved.point[1]).toBeLessThan(bent.point[1] - 0.3); // the pole went down, rig units
    const sent = await page.evaluate(() => window.ikPage?.solvePoles() ?? []);
    expect(sent.find((p) => p.bone === moved.bone)?.point).toEqual(moved.point);
    // Before the drag, the elbow was well off the side the pole is on now.
    expect(dot(across(bent.root, bent.tip, bent.joint), across(bent.root, bent.tip, moved.point))).toBeLessThan(0.5);
    await waitForConvergence(page);
    expect(await sideOf(page, pole)).toBeGreaterThan(0.8);
    const after = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!after) throw new Error('no pole');
    expect(after.joint[1]).toBeLessThan(bent.joint[1]); // the elbow went down
    expect(await worstTipError(page)).toBeLessThan(await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0));
    expect(errors).toEqual([]);
  });

  it('changing the effectors rebuilds the poles (a limb kept keeps its pole); reset and another rig place them anew', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    await page.keyboard.press('p');
    await selectTarget(page, await effectorNamed(page, /Head$/)); // the gizmo away from the limbs
    const leg = await poleNamed(page, /RightLeg$/);
    const placed = (await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, leg))?.point;
    if (!placed) throw new Error('no pole');
    await selectPole(page, leg);
    await dragPoleBy(page, leg, 80, 0);
    await waitForConvergence(page);
    const dragged = (await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, leg))?.point;
    if (!dragged) throw new Error('no pole');
    expect(Math.hypot(...sub(dragged, placed))).toBeGreaterThan(0.1);

    // Clicking the left hand's bone takes its tip off the end effectors: the left arm's pole goes.
    await selectTarget(page, await effectorNamed(page, /Head$/));
    const names = await page.evaluate(() => window.ikPage?.boneNames() ?? []);
    const handBone = names.findIndex((n) => /LeftHand$/.test(n));
    // A quarter of the way along the hand bone: off its target sphere (at the bone's tip).
    const at = await page.evaluate((i) => {
      const p = window.ikPage;
      const wrist = p?.poleHandles().find((h) => p.boneNames()[h.bone].endsWith('LeftForeArm'))?.tip;
      const middle = p?.boneScreen(i);
      const head = wrist ? p?.worldToScreen(wrist) : null;
      return middle && head ? { x: (middle.x + head.x) / 2, y: (middle.y + head.y) / 2 } : null;
    }, handBone);
    if (!at) throw new Error('no hand bone');
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction((b) => !window.ikPage?.effectors().includes(b), handBone);
    const after = await page.evaluate(() => window.ikPage?.poleHandles() ?? []);
    expect(after.map((p) => names[p.bone]).sort()).toEqual([
      'mixamorig:LeftLeg',
      'mixamorig:RightForeArm',
      'mixamorig:RightLeg',
    ]);
    expect(after.find((p) => /RightLeg$/.test(names[p.bone]))?.point).toEqual(dragged);
    expect((await poleCount(page)).sent).toBe(3);

    // Reset (R): the poles start again where the rest pose bends.
    await page.keyboard.press('r');
    await renderedFrames(page);
    const reset = await page.evaluate(() => window.ikPage?.poleHandles() ?? []);
    const resetLeg = reset.find((p) => /RightLeg$/.test(names[p.bone]));
    if (!resetLeg) throw new Error('no leg pole after the reset');
    expect(Math.hypot(...sub(resetLeg.point, placed))).toBeLessThan(1e-6);
    expect((await poleCount(page)).sent).toBe(3);

    // Another rig: its own limbs get poles (the knight's forearms and shins).
    await page
      .locator('.lil-controller', { has: page.locator('.lil-name', { hasText: /^project rig/ }) })
      .locator('select')
      .selectOption('knight');
    await page.waitForFunction(
      () => window.ikPage?.rigName() === 'knight' && document.getElementById('app')?.dataset.state === 'ready',
    );
    await renderedFrames(page);
    const knight = await page.evaluate(() =>
      (window.ikPage?.poleHandles() ?? []).map((p) => window.ikPage?.boneNames()[p.bone]),
    );
    expect(knight.sort()).toEqual(['forearm.L', 'forearm.R', 'shin.L', 'shin.R']);
    expect(await poleCount(page)).toEqual({ shown: 4, sent: 4 });
    expect(errors).toEqual([]);
  });

  it('the knight’s elbow pole starts behind its straight arm; dragged 0.4 units sideways it carries the elbow along, the hand within δ', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'knight');
    await poleBox(page).click();
    const pole = await poleNamed(page, /^forearm\.L$/);
    const rest = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!rest) throw new Error('no pole');
    // The arm hangs straight (its elbow 1.2 cm off the shoulder-wrist line, sideways): the pole
    // goes the way the elbow bends, behind it (the knight faces +Z), one arm's length away.
    const length = Math.hypot(...sub(rest.joint, rest.root)) + Math.hypot(...sub(rest.tip, rest.joint));
    expect((rest.point[2] - rest.joint[2]) / length).toBeLessThan(-0.9);
    // Bend the arm as a user starts: its hand a little towards the body. The elbow bends back, to its pole.
    const hand = await selectTarget(page, await effectorNamed(page, /^hand\.L$/));
    await dragTowardsRoot(page, hand, 0.2);
    await waitForConvergence(page);
    expect(await sideOf(page, pole)).toBeGreaterThan(0.9);
    const bent = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!bent) throw new Error('no pole');

    // The pole dragged 0.4 units towards the body's middle (-X on the screen).
    await selectTarget(page, await effectorNamed(page, /^head$/)); // the gizmo off the arm first
    await selectPole(page, pole);
    await dragPoleAcross(page, pole, [-0.4, 0, 0], 0.4);
    await waitForConvergence(page);
    const after = await page.evaluate((j) => window.ikPage?.poleHandles()[j] ?? null, pole);
    if (!after) throw new Error('no pole');
    const dragged = sub(after.point, bent.point);
    expect(Math.abs(Math.hypot(...dragged) - 0.4)).toBeLessThan(0.02);
    // The elbow follows the pole: it moves at least 0.1 the way the pole went (0.01 before poles
    // were placed where the elbow bends and pulled it within reach of the pole).
    const followed = dot(sub(after.joint, bent.joint), dragged) / Math.hypot(...dragged);
    console.log(
      `knight elbow pole dragged ${Math.hypot(...dragged).toFixed(3)}: the elbow moved ${Math.hypot(...sub(after.joint, bent.joint)).toFixed(4)}, ${followed.toFixed(4)} the pole's way, ${(Math.hypot(...sub(after.point, bent.joint)) - Math.hypot(...sub(after.point, after.joint))).toFixed(4)} nearer it; hand error ${(await worstTipError(page)).toExponential(2)}`,
    );
    expect(followed).toBeGreaterThan(0.1);
    expect(await sideOf(page, pole)).toBeGreaterThan(0.9);
    expect(await worstTipError(page)).toBeLessThan(await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0));
    expect(errors).toEqual([]);
  });

  it('shortcuts work after clicking a panel checkbox, not while typing in a number field', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    await poleBox(page).click();
    expect(await page.evaluate(() => (document.activeElement as HTMLInputElement | null)?.type)).toBe('checkbox');
    expect((await poleCount(page)).shown).toBe(4);
    await page.keyboard.press('p'); // the box still has the focus
    await renderedFrames(page);
    expect(await poleBox(page).isChecked()).toBe(false);
    expect((await poleCount(page)).shown).toBe(0);
    await page.keyboard.press('e');
    expect(await page.evaluate(() => window.ikPage?.gizmoMode())).toBe('rotate');

    // Typing in a number field is typing, not shortcuts.
    const field = (await panelControl(page, /^on target within/)).locator('input');
    await field.click();
    await page.keyboard.press('p');
    await page.keyboard.press('w');
    await renderedFrames(page);
    expect((await poleCount(page)).shown).toBe(0);
    expect(await poleBox(page).isChecked()).toBe(false);
    expect(await page.evaluate(() => window.ikPage?.gizmoMode())).toBe('rotate');
    expect(await field.inputValue()).toMatch(/pw$/);
    expect(errors).toEqual([]);
  });
});
