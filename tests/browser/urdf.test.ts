// A URDF robot on the page: a small 6-joint arm written here (revolute joints with
// limits, a bent elbow at the zero pose, a fixed joint to an off-axis tool tip, a camera branch and
// a package:// mesh) opened through the file input. Its longest chain is shown as bones, the tool tip
// the one end effector, with a warning that meshes are not drawn; the tip is dragged with the mouse
// to within the page's tip tolerance, then turned with an orientation goal (O, the rotate gizmo)
// while its position holds; a bone's joint limits show. The camera chain is chosen in the panel's
// chain menu and with ?chain= (track mode and pole handles, made for humanoids and limbs, do no
// harm); a URDF the importer refuses (a limit upside down, a prismatic joint
// in the chosen chain) is reported naming the joint and the rig shown stays. With the shared robots
// (../shared/robots), Panda is opened and its tip dragged. Writes test-results/urdf-arm.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';

import { a7Required } from '../../scripts/a7_folder.js';
import { robotsDir, robotsMissingMessage, robotsPresent } from '../helpers/robots_folder.js';
import { armUrdf, revolute } from '../helpers/test_arm_urdf.js';
import { openPage, renderedFrames, resultsDir } from './harness.js';
import {
  dragTargetAlongY,
  gotoRig,
  panelControl,
  selectTarget,
  targetAt,
  tipAt,
  usePageServer,
  waitForConvergence,
} from './page_helpers.js';

const env = usePageServer();

type Point = [number, number, number];
const distance = (a: Point, b: Point): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** An ASCII STL box of half-size `h` (metres) centred on its origin: 12 triangles. */
function boxStl(h: number): Uint8Array {
  const c = [
    [-h, -h, -h],
    [h, -h, -h],
    [h, h, -h],
    [-h, h, -h],
    [-h, -h, h],
    [h, -h, h],
    [h, h, h],
    [-h, h, h],
  ];
  const faces = [
    [0, 2, 1],
    [0, 3, 2],
    [4, 5, 6],
    [4, 6, 7],
    [0, 1, 5],
    [0, 5, 4],
    [2, 3, 7],
    [2, 7, 6],
    [1, 2, 6],
    [1, 6, 5],
    [0, 4, 7],
    [0, 7, 3],
  ];
  const facet = (f: number[]): string => {
    const [a, b, d] = f.map((i) => c[i]);
    const u = [0, 1, 2].map((k) => b[k] - a[k]),
      v = [0, 1, 2].map((k) => d[k] - a[k]);
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const len = Math.hypot(n[0], n[1], n[2]);
    return `facet normal ${n.map((x) => x / len).join(' ')}\nouter loop\n${f.map((i) => `vertex ${c[i].join(' ')}`).join('\n')}\nendloop\nendfacet`;
  };
  return new TextEncoder().encode(`solid box\n${faces.map(facet).join('\n')}\nendsolid box\n`);
}

/** A robot whose only chain base:tip runs through the prismatic joint "slider". */
const sliderUrdf = `<robot name="slider_arm">
  <link name="base"/><link name="carriage"/><link name="tip"/>
  <joint name="slider" type="prismatic"><parent link="base"/><child link="carriage"/><axis xyz="1 0 0"/><limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
  ${revolute('turn', 'carriage', 'tip', '0 0 0.2', '0 0 1', -1, 1)}
</robot>`;

const text = (s: string): Uint8Array => new TextEncoder().encode(s);

/** Chooses `bytes` as the rig file `name` and waits until the page has dealt with it; returns the message shown. */
async function openFile(page: Page, name: string, bytes: Uint8Array): Promise<string> {
  const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
  await page.setInputFiles('#rig-file', { name, mimeType: 'application/xml', buffer: Buffer.from(bytes) });
  await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before, { timeout: 20_000 });
  return (await page.textContent('#message')) ?? '';
}

/** The page's rig line ("name — format, N bones, M end effectors"). */
async function rigLine(page: Page): Promise<string> {
  return (await page.textContent('#rig-name')) ?? '';
}

/** Opens `name` and expects it shown without an error; returns the message line. */
async function openRig(page: Page, name: string, bytes: Uint8Array): Promise<string> {
  const message = await openFile(page, name, bytes);
  expect(await page.getAttribute('#message', 'data-kind'), message).toBe('info');
  expect(await page.evaluate(() => window.ikPage?.rigName())).toBe(name.replace(/\.urdf$/, ''));
  return message;
}

/** Drags effector k's target up by `dy` with the mouse (the gizmo's Y arrow); expects the tip on it within the page's tolerance. */
async function dragTip(page: Page, k: number, dy: number): Promise<void> {
  await selectTarget(page, k);
  const from = await targetAt(page, k);
  await dragTargetAlongY(page, k, dy, 20);
  await waitForConvergence(page);
  const target = await targetAt(page, k),
    tip = await tipAt(page, k);
  const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
  console.log(
    `[urdf] dragged ${(target[1] - from[1]).toFixed(4)} up: tip ${distance(tip, target).toExponential(2)} from its target (tolerance ${tolerance.toPrecision(3)})`,
  );
  expect(Math.abs(target[1] - from[1] - dy)).toBeLessThan(0.02 * Math.abs(dy));
  expect(distance(tip, target)).toBeLessThan(tolerance);
}

describe('a URDF robot on the page', () => {
  it('opens the arm as bones with its tool tip the one effector, drags and turns the tip, shows the limits', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    expect(await page.getAttribute('#rig-file', 'accept')).toContain('.urdf');
    const message = await openRig(page, 'test_arm.urdf', text(armUrdf()));
    console.log(`[urdf] ${await rigLine(page)} | ${message}`);
    expect(await rigLine(page)).toBe('test_arm — URDF chain base_link:tool0, 7 bones, 1 end effector');
    expect(message).toMatch(
      /^test_arm: chain base_link:tool0 \(6 moving joints, the longest; choose another in the panel's chain menu or with \?chain=BASE:TIP\)/,
    );
    expect(message).toMatch(
      /2 mesh files are not beside it \(drop the robot's folder to see them\): the chain's links show as bones/,
    );
    expect(message).not.toMatch(/--chain/);
    const names = await page.evaluate(() => window.ikPage?.boneNames() ?? []);
    expect(names).toEqual(['shoulder_pan', 'shoulder_lift', 'elbow', 'wrist_1', 'wrist_2', 'wrist_3', 'tool0']);
    expect(await page.evaluate(() => window.ikPage?.effectors())).toEqual([6]);
    // The robot's +z is the page's up: the arm stands on the floor, its tool above its base.
    const rest = await tipAt(page, 0);
    expect(rest[1]).toBeGreaterThan(0.5);
    // No humanoid: no humanoid-limits switch, no hips target.
    expect(await page.isVisible('.lil-controller:has(.lil-name:text-is("humanoid limits"))')).toBe(false);
    // The panel's chain menu lists the file's two chains, the longest chosen.
    const chainMenu = (await panelControl(page, /^chain$/)).locator('select');
    expect(await chainMenu.locator('option').allTextContents()).toEqual([
      'base_link:tool0 (longest)',
      'base_link:camera_optical_frame',
    ]);
    expect(await chainMenu.locator('option:checked').textContent()).toBe('base_link:tool0 (longest)');

    // 1. The tool tip's target dragged down 0.15 m with the mouse.
    await dragTip(page, 0, -0.15);

    // 2. Its orientation goal on (O), the rotate gizmo (E) turned 30 degrees about the vertical.
    const held = await targetAt(page, 0);
    await page.keyboard.press('o');
    expect(await page.evaluate(() => window.ikPage?.orientationGoal(0))).not.toBeNull();
    await page.keyboard.press('e');
    await page.evaluate(() => window.ikPage?.turnGizmo([0, 1, 0], 30, 8));
    await waitForConvergence(page);
    const error = await page.evaluate(() => window.ikPage?.orientationError(0) ?? NaN);
    const tolerance = await page.evaluate(() => window.ikPage?.tipTolerance() ?? 0);
    const tip = await tipAt(page, 0);
    console.log(
      `[urdf] turned 30°: orientation error ${error.toExponential(2)}°, tip ${distance(tip, held).toExponential(2)} from where it was held`,
    );
    expect(error).toBeLessThan(0.5);
    expect(distance(await targetAt(page, 0), held)).toBeLessThan(1e-9);
    expect(distance(tip, held)).toBeLessThan(tolerance);

    // 3. The elbow's joint limits: shift-click its bone (select only), a quarter of the way along
    // its glyph: its middle lies under the rotate gizmo's view ring (handle E, hovered there), which
    // takes a click before the bones do.
    const elbow = await page.evaluate(() => {
      const p = window.ikPage;
      const base = p?.boneBase(2),
        middle = p?.boneScreen(2);
      const from = base ? p?.worldToScreen(base) : null;
      return from && middle ? { x: (from.x + middle.x) / 2, y: (from.y + middle.y) / 2 } : null;
    });
    if (!elbow) throw new Error('no elbow on screen');
    await page.keyboard.down('Shift');
    await page.mouse.click(elbow.x, elbow.y);
    await page.keyboard.up('Shift');
    const readout = (await page.textContent('#selection')) ?? '';
    expect(readout).toMatch(/^elbow/);
    // A hinge: one angle about its axis, no bend or twist.
    expect(readout).toMatch(/angle about its axis \(a0\): -?\d+\.\d° in \[-149\.0°, 149\.0°\]/);
    expect(readout).toContain('a hinge: one angle about its axis (a1, a2 fixed at 0)');
    expect(readout).not.toMatch(/twist/);
    expect(await page.evaluate(() => window.ikPage?.effectors())).toEqual([6]);

    // The picture: the arm as bones, the tool's target with its axes, the elbow's limits.
    await page.keyboard.press('w');
    const view = await page.locator('#viewport').boundingBox();
    if (!view) throw new Error('no viewport');
    await page.mouse.move(view.x + 10, view.y + 10);
    await renderedFrames(page, 3);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'urdf-arm.png') });
    expect(errors).toEqual([]);
  });

  it('draws the meshes chosen with it, each moving with its link', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
    // As a user picks the robot's files together: the URDF and its two meshes (plus one it does not name).
    await page.setInputFiles('#rig-file', [
      { name: 'link1.stl', mimeType: 'model/stl', buffer: Buffer.from(boxStl(0.03)) },
      { name: 'test_arm.urdf', mimeType: 'application/xml', buffer: Buffer.from(text(armUrdf())) },
      { name: 'link3.stl', mimeType: 'model/stl', buffer: Buffer.from(boxStl(0.04)) },
      { name: 'notes.txt', mimeType: 'text/plain', buffer: Buffer.from('not a mesh') },
    ]);
    await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before, { timeout: 20_000 });
    const message = (await page.textContent('#message')) ?? '';
    console.log(`[urdf] with meshes: ${await rigLine(page)} | ${message}`);
    expect(await page.getAttribute('#message', 'data-kind'), message).toBe('info');
    expect(message).not.toMatch(/mesh/);
    expect(await page.evaluate(() => window.ikPage?.rigName())).toBe('test_arm');
    // link3's box (half-size 0.04, 0.1 along link3's z from its origin) rides with the elbow's bone:
    // its centre keeps its distances from the elbow's joint and from wrist_1's (both on link3).
    const centre = async (): Promise<Point> => {
      const box = await page.evaluate(() => window.ikPage?.objectBounds('link3') ?? null);
      if (!box) throw new Error('link3 is not drawn');
      expect(box.max[0] - box.min[0]).toBeGreaterThan(0.079); // the whole box, not an empty group
      return [0, 1, 2].map((i) => (box.min[i] + box.max[i]) / 2) as Point;
    };
    const joint = async (bone: number): Promise<Point> =>
      (await page.evaluate((b) => window.ikPage?.boneBase(b) ?? null, bone))!;
    const rest = await centre();
    const restElbow = distance(rest, await joint(2)),
      restWrist = distance(rest, await joint(3));
    expect(restElbow).toBeGreaterThan(0.09);
    expect(await page.evaluate(() => window.ikPage?.objectBounds('link1') ?? null)).not.toBeNull();
    await dragTip(page, 0, 0.1);
    const moved = await centre();
    console.log(
      `[urdf] link3's box moved ${distance(moved, rest).toFixed(4)}; from the elbow ${restElbow.toFixed(5)} -> ${distance(moved, await joint(2)).toFixed(5)}`,
    );
    expect(distance(moved, rest)).toBeGreaterThan(0.01);
    expect(Math.abs(distance(moved, await joint(2)) - restElbow)).toBeLessThan(1e-4);
    expect(Math.abs(distance(moved, await joint(3)) - restWrist)).toBeLessThan(1e-4);
    mkdirSync(resultsDir, { recursive: true });
    await page.screenshot({ path: join(resultsDir, 'urdf-meshes.png') });
    expect(errors).toEqual([]);
  });

  it('chooses the camera chain in the panel and with ?chain=; refused URDFs name the joint and keep the rig', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp');
    await openRig(page, 'test_arm.urdf', text(armUrdf()));
    const toolTip = await tipAt(page, 0);

    // The panel's chain menu: the camera chain, 3 moving joints, its tip the optical frame.
    const chainMenu = (await panelControl(page, /^chain$/)).locator('select');
    const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
    await chainMenu.selectOption({ label: 'base_link:camera_optical_frame' });
    await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before);
    expect(await rigLine(page)).toBe('test_arm — URDF chain base_link:camera_optical_frame, 4 bones, 1 end effector');
    expect(await page.textContent('#message')).toMatch(
      /^test_arm: chain base_link:camera_optical_frame \(3 moving joints\)/,
    );
    expect(await page.evaluate(() => window.ikPage?.boneNames())).toEqual([
      'shoulder_pan',
      'shoulder_lift',
      'camera_tilt',
      'camera_optical_frame',
    ]);
    const cameraTip = await tipAt(page, 0);
    expect(distance(cameraTip, toolTip)).toBeGreaterThan(0.1);
    expect(new URL(page.url()).searchParams.get('chain')).toBe('base_link:camera_optical_frame');
    await dragTip(page, 0, -0.05);
    // Not a humanoid: track mode (T) says why it cannot start, pole handles (P) go on and off, the tip stays on target.
    await page.keyboard.press('t');
    const track = (await page.textContent('#message')) ?? '';
    console.log(`[urdf] T: ${track}`);
    expect(track).toMatch(/^track mode: /);
    await page.keyboard.press('p');
    await renderedFrames(page, 3);
    await page.keyboard.press('p');
    await waitForConvergence(page);

    // A URDF the importer refuses (the camera joint's limits upside down): the message names the joint, the camera chain stays.
    const bad = await openFile(page, 'bad_arm.urdf', text(armUrdf([1, -1])));
    console.log(`[urdf] refused: ${bad}`);
    expect(await page.getAttribute('#message', 'data-kind')).toBe('error');
    expect(bad).toMatch(/^Could not load bad_arm\.urdf: bad_arm\.urdf: .*"camera_tilt".* — still showing test_arm$/);
    expect(await rigLine(page)).toMatch(/chain base_link:camera_optical_frame/);
    expect(await page.getAttribute('#app', 'data-state')).toBe('ready');

    // ?chain= picks the chain of the next URDF opened.
    await gotoRig(page, env.url, 'lamp', '&chain=base_link:camera_optical_frame');
    await openRig(page, 'test_arm.urdf', text(armUrdf()));
    expect(await rigLine(page)).toBe('test_arm — URDF chain base_link:camera_optical_frame, 4 bones, 1 end effector');
    expect(distance(await tipAt(page, 0), cameraTip)).toBeLessThan(1e-9);
    expect(await (await panelControl(page, /^chain$/)).locator('select option:checked').textContent()).toBe(
      'base_link:camera_optical_frame',
    );

    // A ?chain= through a prismatic joint: refused naming the joint, the arm stays.
    await gotoRig(page, env.url, 'lamp', '&chain=base:tip');
    const slider = await openFile(page, 'slider_arm.urdf', text(sliderUrdf));
    console.log(`[urdf] refused: ${slider}`);
    expect(slider).toBe(
      'Could not load slider_arm.urdf: slider_arm.urdf: joint "slider" is prismatic and lies in the chain base:tip; only revolute, continuous and fixed joints can be imported — still showing lamp',
    );
    expect(await page.evaluate(() => window.ikPage?.rigName())).toBe('lamp');
    // A ?chain= whose links the file does not have: the file's longest chain, with a note.
    const other = await openRig(page, 'test_arm.urdf', text(armUrdf()));
    expect(other).toMatch(
      /the chain base:tip is not in this file \(no link "base", "tip"\): took the file's longest chain/,
    );
    expect(await rigLine(page)).toMatch(/chain base_link:tool0/);
    expect(new URL(page.url()).searchParams.get('chain')).toBeNull();
    expect(errors).toEqual([]);
  });

  it('opens the shared Panda and drags its tip', async (ctx) => {
    if (!robotsPresent) {
      if (a7Required) throw new Error(robotsMissingMessage);
      ctx.skip(`robots folder missing: ${robotsDir}`);
    }
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'lamp', '&chain=panda_link0:panda_link8');
    const before = await page.evaluate(() => window.ikPage?.loads() ?? 0);
    await page.setInputFiles('#rig-file', join(robotsDir, 'panda.urdf'));
    await page.waitForFunction((n) => (window.ikPage?.loads() ?? 0) > n, before, { timeout: 20_000 });
    const message = (await page.textContent('#message')) ?? '';
    console.log(`[urdf] ${await rigLine(page)} | ${message}`);
    expect(await page.getAttribute('#message', 'data-kind'), message).toBe('info');
    expect(await rigLine(page)).toBe('panda — URDF chain panda_link0:panda_link8, 8 bones, 1 end effector');
    expect(message).toMatch(/mesh files are not beside it/);
    await dragTip(page, 0, -0.1);
    expect(errors).toEqual([]);
  });
});
