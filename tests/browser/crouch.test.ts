// The crouch: on a recognised humanoid the hips float, so pulling the
// head's target straight down by 25% of the height with the mouse crouches: the hips lower by at
// least 15% of the height, both knees bend forward (each knee ahead of the line from its hip to
// its ankle, in the way the character faces), the feet stay within δ of where they stood and the
// head reaches its target. Run on the project's character (Mixamo names, with its mesh: a
// screenshot) and on skeletons made for the test in the generic convention's naming styles. Then
// the hips' own target dragged down lowers the body with the feet planted and the head coming along.
// The character's head is flicked down in 3 mouse moves, with the page's frame budget shorter than
// any step (a loaded machine, where a frame's solve is cut after its first step): the crouch must
// follow the same (cut at a step a frame, the head did not move at all; cut at a few, the body
// bowed and stayed bowed; a flick ended 40-80 px off, bowed, its drag over before the body).
// Writes test-results/crouch.png.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { skeletonGlb } from '../helpers/skeleton_glb.js';
import { type NamingStyle, styledHumanoid, styledRoles } from '../rig/synthetic_rigs.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragTargetAlongY,
  effectorNamed,
  gotoRig,
  selectTarget,
  statText,
  targetAt,
  tipAt,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type Point = [number, number, number];

const sub = (a: Point, b: Point): Point => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const distance = (a: Point, b: Point): number => Math.hypot(...sub(a, b));
/** A pattern matching exactly `name` (every character taken literally). */
const exactly = (name: string): RegExp => new RegExp(`^${name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}$`);

async function boneTip(page: Page, bone: number): Promise<Point> {
  const p = await page.evaluate((i) => window.ikPage?.boneTip(i) ?? null, bone);
  if (!p) throw new Error(`no bone ${bone}`);
  return p;
}

/** The bone named `name` exactly (an error naming it when the rig has none). */
async function boneNamed(page: Page, name: string): Promise<number> {
  const i = (await page.evaluate(() => window.ikPage?.boneNames() ?? [])).indexOf(name);
  if (i < 0) throw new Error(`no bone ${name}`);
  return i;
}

/** Bone names of a humanoid's hips, legs and head (the upper leg's tip is the knee, the lower leg's the ankle). */
interface Body {
  hips: string;
  head: string;
  legs: { upper: string; lower: string; foot: string }[];
}

/** Drags the head's target down by 25% of the height in `moves` mouse moves and checks the crouch; then the hips' target down by a further 5%, the feet planted. */
async function crouch(page: Page, body: Body, label: string, moves = 25): Promise<void> {
  const delta = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
  const height = await page.evaluate(() => {
    const b = window.ikPage?.bounds();
    return b ? b.max[1] - b.min[1] : NaN;
  });
  const hipsBone = await boneNamed(page, body.hips);
  const legs = await Promise.all(
    body.legs.map(async (l) => ({
      upper: await boneNamed(page, l.upper),
      lower: await boneNamed(page, l.lower),
      foot: await effectorNamed(page, exactly(l.foot)),
    })),
  );
  const head = await effectorNamed(page, exactly(body.head));
  const hips = await effectorNamed(page, exactly(body.hips)); // the hips are a target of their own
  const hipsStood = await boneTip(page, hipsBone);
  const feetStood = await Promise.all(legs.map((l) => tipAt(page, l.foot)));
  // The way the character faces: from the hips, the toes' side of the feet (the ankle's tip is
  // ahead of its base on every rig here), level.
  const ankle = await boneTip(page, legs[0].lower);
  const ahead = sub(feetStood[0], ankle);
  const forward: Point = [ahead[0], 0, ahead[2]].map((c) => c / Math.hypot(ahead[0], ahead[2])) as Point;

  await selectTarget(page, head);
  await dragTargetAlongY(page, head, -0.25 * height, moves);
  await waitForConvergence(page);
  const hipsNow = await boneTip(page, hipsBone);
  const lowered = (hipsStood[1] - hipsNow[1]) / height;
  // Each knee ahead of its hip-ankle line by how far, in the facing direction (rig units).
  const kneeAhead = await Promise.all(
    legs.map(async (l) => {
      const hipJoint = await page.evaluate((i) => window.ikPage?.boneBase(i) ?? null, l.upper);
      const knee = await boneTip(page, l.upper),
        ankleNow = await boneTip(page, l.lower);
      if (!hipJoint) throw new Error('no hip joint');
      const along = sub(ankleNow, hipJoint as Point),
        rel = sub(knee, hipJoint as Point);
      const t =
        (rel[0] * along[0] + rel[1] * along[1] + rel[2] * along[2]) / (along[0] ** 2 + along[1] ** 2 + along[2] ** 2);
      const off: Point = [rel[0] - t * along[0], rel[1] - t * along[1], rel[2] - t * along[2]];
      return off[0] * forward[0] + off[2] * forward[2];
    }),
  );
  const feetOff = await Promise.all(legs.map(async (l, i) => distance(await tipAt(page, l.foot), feetStood[i])));
  const headOff = distance(await tipAt(page, head), await targetAt(page, head));
  console.log(
    `[crouch ${label}] head down 25% of the height: hips lowered ${(100 * lowered).toFixed(1)}% of the height; knees ahead of their hip-ankle lines by ${kneeAhead.map((a) => ((100 * a) / height).toFixed(1)).join(', ')}% of the height; ` +
      `feet ${feetOff.map((d) => (d / delta).toFixed(3)).join(', ')} δ from where they stood; head ${(headOff / delta).toFixed(3)} δ from its target; status "${await statText(page, 'status')}"`,
  );
  expect(lowered).toBeGreaterThan(0.15);
  for (const a of kneeAhead) expect(a).toBeGreaterThan(0.02 * height);
  for (const d of feetOff) expect(d).toBeLessThan(delta);
  expect(headOff).toBeLessThan(delta);

  // The hips' own target, down a further 5%: the body follows, the feet stay planted.
  await selectTarget(page, hips);
  const headBefore = await tipAt(page, head),
    hipsBefore = await targetAt(page, hips);
  await dragTargetAlongY(page, hips, -0.05 * height, 10);
  await waitForConvergence(page);
  const hipsTip = await tipAt(page, hips),
    headAfter = await tipAt(page, head);
  const feetAfter = await Promise.all(legs.map(async (l, i) => distance(await tipAt(page, l.foot), feetStood[i])));
  console.log(
    `[crouch ${label}] hips dragged down 5%: hips ${(distance(hipsTip, await targetAt(page, hips)) / delta).toFixed(3)} δ from their target, ${((100 * (hipsBefore[1] - hipsTip[1])) / height).toFixed(1)}% lower; ` +
      `head ${((100 * (headBefore[1] - headAfter[1])) / height).toFixed(1)}% lower; feet ${feetAfter.map((d) => (d / delta).toFixed(3)).join(', ')} δ`,
  );
  expect(distance(hipsTip, await targetAt(page, hips))).toBeLessThan(delta);
  expect(hipsBefore[1] - hipsTip[1]).toBeGreaterThan(0.045 * height);
  expect(headBefore[1] - headAfter[1]).toBeGreaterThan(0.02 * height); // the head came along
  for (const d of feetAfter) expect(d).toBeLessThan(delta);
}

describe('the crouch', () => {
  it('the character: the head flicked down crouches, the hips lower, the knees bend forward, the feet stay', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    await page.evaluate(() => {
      const settings = window.ikPage?.settings();
      if (settings) settings.timeBudgetMs = 1e-6; // 1 ns: every frame's budget runs out in its first step
    });
    const m = (s: string): string => `mixamorig:${s}`;
    await crouch(
      page,
      {
        hips: m('Hips'),
        head: m('Head'),
        legs: ['Left', 'Right'].map((s) => ({ upper: m(`${s}UpLeg`), lower: m(`${s}Leg`), foot: m(`${s}Foot`) })),
      },
      'character',
      3,
    );
    await renderedFrames(page);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'crouch.png') });
    expect(errors).toEqual([]);
  });

  it.for(['CamelSuffix', 'dotSuffix', 'lowerSnake', 'sidePrefix'] as NamingStyle[])(
    'a %s skeleton crouches the same way',
    async (style, ctx) => {
      const { page, errors } = await openPage(env.browser, ctx);
      await gotoRig(page, env.url, 'character');
      const file = join(resultsDir, `crouch-${style}.glb`);
      mkdirSync(resultsDir, { recursive: true });
      writeFileSync(file, await skeletonGlb(styledHumanoid(style)));
      await page.setInputFiles('#rig-file', file);
      await page.waitForFunction(
        (name) => window.ikPage?.rigName() === name && document.getElementById('app')?.dataset.state === 'ready',
        `crouch-${style}`,
      );
      await renderedFrames(page, 3);
      const r = styledRoles(style);
      await crouch(
        page,
        {
          hips: r.hips!,
          head: r.head!,
          legs: [
            ['leftUpperLeg', 'leftLowerLeg', 'leftFoot'],
            ['rightUpperLeg', 'rightLowerLeg', 'rightFoot'],
          ].map(([u, l, f]) => ({
            upper: r[u as 'leftUpperLeg']!,
            lower: r[l as 'leftLowerLeg']!,
            foot: r[f as 'leftFoot']!,
          })),
        },
        style,
      );
      expect(errors).toEqual([]);
    },
  );
});
