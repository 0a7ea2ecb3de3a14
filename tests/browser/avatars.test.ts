// Ten avatars on one page: the character loaded ten times into AvatarSolver, each driven
// by its own upper-body motion (the spine, neck, arms swaying on sines within their limits, as the
// avatar test's sway), every update() on the main thread. The test checks that the avatars keep
// their heads and hands on their tracked poses (98% of the frames), and prints the main-thread time per frame for all
// ten (it should stay within 2 ms), measured after a warm-up; it asserts no time.
import { describe, expect, it } from 'vitest';

import { openPage } from './harness.js';
import { gotoRig, usePageServer } from './page_helpers.js';

const env = usePageServer();

describe('ten avatars on one page', () => {
  it('track their head and hands every frame; the main-thread time per frame is printed', async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await gotoRig(page, env.url, 'character');
    const result = await page.evaluate(async () => {
      // The page's own modules, as vite serves them (an import() written here would be rewritten by
      // vitest's transform of this file, which the page does not have).
      // eslint-disable-next-line @typescript-eslint/no-explicit-any -- the page's modules, untyped on this side
      const load = new Function('path', 'return import(path)') as (path: string) => Promise<any>;
      const { loadIk } = await load('/src/ik/module.ts');
      const { loadRig } = await load('/src/rig/load_rig.ts');
      const { AvatarSolver } = await load('/src/avatar/avatar_solver.ts');
      const { IkRig } = await load('/src/ik/rig.ts');
      const ik = await loadIk();
      const bytes = new Uint8Array(await (await fetch('/models/character.glb')).arrayBuffer());
      const rig = await loadRig(bytes, 'character.glb');
      const humanoid = rig.gltf.humanoid;
      const roles = [
        'spine',
        'chest',
        'upperChest',
        'neck',
        'head',
        'leftShoulder',
        'leftUpperArm',
        'leftLowerArm',
        'leftHand',
        'rightShoulder',
        'rightUpperArm',
        'rightLowerArm',
        'rightHand',
      ];
      const moving: number[] = roles.map((r) => humanoid.bones[r]).filter((b: number | undefined) => b !== undefined);
      const count = 10,
        frames = 240,
        warmUp = 60;
      const avatars = Array.from({ length: count }, () => new AvatarSolver(ik, rig.spec, humanoid));
      const truth = new IkRig(ik, avatars[0].rig.spec);
      const a = new Float64Array(truth.numAngles);
      const delta = 1e-3 * avatars[0].height;
      // Every frame's tracked poses first, into one flat array (7 numbers per point: position,
      // orientation), copied into one input per avatar before its update: the loop below then
      // allocates only what update() does. (Made in the loop, 3 arrays per avatar and frame, they put
      // garbage collections into the timed updates; kept as 9,000 small arrays, their promotion out
      // of the young generation took 4 ms a scavenge.)
      const total = warmUp + frames;
      const tracked = new Float64Array(total * count * 3 * 7);
      for (let f = 0; f < total; f++)
        for (let k = 0; k < count; k++) {
          // Avatar k's motion: each angle of the moving bones on its own sine, within its limits.
          const t = f / 60 + k;
          a.fill(0);
          moving.forEach((b, i) => {
            for (let c = 0; c < 3; c++) {
              const j = 3 * b + c,
                lo = truth.lower[j],
                hi = truth.upper[j];
              const mid = Math.max(lo, Math.min(hi, 0)),
                span = Math.min(hi - mid, mid - lo, 60);
              a[j] = mid + 0.6 * span * Math.sin(2 * Math.PI * (0.15 + 0.05 * ((i + c) % 5)) * t + i + 2 * c);
            }
          });
          const pose = truth.project(a),
            tips = truth.tips(pose),
            turns = truth.tipRotations(pose);
          for (let e = 0; e < 3; e++) {
            const at = 7 * (3 * (f * count + k) + e);
            tracked.set(tips.subarray(3 * e, 3 * e + 3), at);
            tracked.set(turns.subarray(4 * e, 4 * e + 4), at + 3);
          }
        }
      const point = () => ({ position: new Float64Array(3), orientation: new Float64Array(4) });
      const inputs = avatars.map(() => ({ head: point(), leftHand: point(), rightHand: point() }));
      const points = inputs.map((input) => [input.head, input.leftHand, input.rightHand]);
      const mine = new Float64Array(3 * avatars[0].bones.length);
      const perFrame = new Float64Array(frames);
      // A fixed loop of plain JavaScript, timed after each frame (ms): where it too takes
      // milliseconds, the main thread was held by something else (this machine's other processes
      // and threads). A function of its own: written inline, it slowed the timed loop's updates.
      const control = new Float64Array(total);
      let sink = 0;
      const fixedLoop = (seed: number): number => {
        const t0 = performance.now();
        for (let i = 0; i < 20000; i++) sink += Math.sqrt(i + seed);
        return performance.now() - t0;
      };
      let onTarget = 0,
        samples = 0;
      for (let f = 0; f < total; f++) {
        let spent = 0;
        for (let k = 0; k < count; k++) {
          for (let e = 0; e < 3; e++) {
            const at = 7 * (3 * (f * count + k) + e),
              p = points[k][e];
            for (let i = 0; i < 3; i++) p.position[i] = tracked[at + i];
            for (let i = 0; i < 4; i++) p.orientation[i] = tracked[at + 3 + i];
          }
          const t0 = performance.now();
          avatars[k].update(inputs[k]);
          spent += performance.now() - t0;
          if (f < warmUp) continue;
          avatars[k].tips(mine);
          samples++;
          let met = true;
          for (let e = 0; e < 3; e++) {
            const p = points[k][e].position;
            if (!(Math.hypot(mine[3 * e] - p[0], mine[3 * e + 1] - p[1], mine[3 * e + 2] - p[2]) < delta)) met = false;
          }
          if (met) onTarget++;
        }
        control[f] = fixedLoop(f);
        if (f >= warmUp) perFrame[f - warmUp] = spent;
      }
      avatars.forEach((avatar) => avatar.dispose());
      truth.dispose();
      perFrame.sort();
      const controlTimes = Array.from(control.subarray(warmUp)).sort((x, y) => x - y);
      return {
        onTarget: onTarget / samples,
        median: perFrame[Math.floor((perFrame.length - 1) / 2)],
        p95: perFrame[Math.floor(0.95 * perFrame.length)],
        max: perFrame[perFrame.length - 1],
        over2: perFrame.filter((ms) => ms > 2).length,
        isolated: crossOriginIsolated,
        sink,
        control: { median: controlTimes[(controlTimes.length - 1) >> 1], max: controlTimes[controlTimes.length - 1] },
      };
    });
    console.log(
      `[perf] 10 avatars (the character, 3 tracked points each): main-thread ms per frame for all ten, ` +
        `median ${result.median.toFixed(3)}, p95 ${result.p95.toFixed(3)}, max ${result.max.toFixed(3)}, ` +
        `${result.over2} over 2 ms; a fixed JavaScript loop after each frame: median ` +
        `${result.control.median.toFixed(3)}, max ${result.control.max.toFixed(3)} ` +
        `(240 frames after 60 of warm-up; timer resolution ${result.isolated ? '5 us, cross-origin isolated' : '100 us'})`,
    );
    // Measured 98.75% of the frames: on the others an arm that has drifted into its shoulder's and
    // wrist's limits trails its tracked hand by a few δ for a few frames (the avatar's hips move
    // as little as a body's, avatar_solver.ts ROOT_UNIT_SHARE; with their move nearly free, every frame).
    expect(result.onTarget).toBeGreaterThanOrEqual(0.98);
    expect(errors).toEqual([]);
  });
});
