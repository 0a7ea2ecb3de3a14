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
      const perFrame: number[] = [];
      let onTarget = 0,
        samples = 0;
      for (let f = 0; f < warmUp + frames; f++) {
        let spent = 0;
        avatars.forEach((avatar, k) => {
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
          const at = (e: number) => ({
            position: tips.subarray(3 * e, 3 * e + 3),
            orientation: turns.subarray(4 * e, 4 * e + 4),
          });
          const t0 = performance.now();
          avatar.update({ head: at(0), leftHand: at(1), rightHand: at(2) });
          spent += performance.now() - t0;
          if (f >= warmUp) {
            const mine = avatar.tips();
            samples++;
            if (
              [0, 1, 2].every(
                (e) =>
                  Math.hypot(
                    mine[3 * e] - tips[3 * e],
                    mine[3 * e + 1] - tips[3 * e + 1],
                    mine[3 * e + 2] - tips[3 * e + 2],
                  ) < delta,
              )
            )
              onTarget++;
          }
        });
        if (f >= warmUp) perFrame.push(spent);
      }
      avatars.forEach((avatar) => avatar.dispose());
      truth.dispose();
      perFrame.sort((x, y) => x - y);
      return {
        onTarget: onTarget / samples,
        median: perFrame[Math.floor((perFrame.length - 1) / 2)],
        p95: perFrame[Math.floor(0.95 * perFrame.length)],
        max: perFrame[perFrame.length - 1],
        over2: perFrame.filter((ms) => ms > 2).length,
        isolated: crossOriginIsolated,
      };
    });
    console.log(
      `[perf] 10 avatars (the character, 3 tracked points each): main-thread ms per frame for all ten, ` +
        `median ${result.median.toFixed(3)}, p95 ${result.p95.toFixed(3)}, max ${result.max.toFixed(3)}, ` +
        `${result.over2} over 2 ms ` +
        `(240 frames after 60 of warm-up; timer resolution ${result.isolated ? '5 us, cross-origin isolated' : '100 us'})`,
    );
    // Measured 98.75% of the frames: on the others an arm that has drifted into its shoulder's and
    // wrist's limits trails its tracked hand by a few δ for a few frames (the avatar's hips move
    // as little as a body's, avatar_solver.ts ROOT_UNIT_SHARE; with their move nearly free, every frame).
    expect(result.onTarget).toBeGreaterThanOrEqual(0.98);
    expect(errors).toEqual([]);
  });
});
