// The track experiment (bench-node/track.ts) on the project's character with a clip made here:
// seven joints (spine, neck, both arms and forearms) turning 5 degrees back and forth about their
// own axes for two seconds at 30 frames per second. A clip that holds the rest pose is tracked on
// every frame with the joints where the clip has them; the moving one within δ on every
// frame with the feet planted and no flip; the rows reach the JSON and CSV; a clip the file lacks,
// a file without clips and a rig without a humanoid are refused by name.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { NodeIO } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { runCommand } from '../../bench-node/command.js';

const dir = mkdtempSync(join(tmpdir(), 'ik-track-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));
const character = resolve(import.meta.dirname, '../../web/public/models/character.glb');

/** The character with clips `amplitudes` (name -> degrees) instead of its own: the seven joints on sines about their local X or Z. */
async function characterWithClips(file: string, amplitudes: Record<string, number>): Promise<string> {
  const io = new NodeIO().registerExtensions(ALL_EXTENSIONS);
  const doc = await io.read(character);
  const root = doc.getRoot(),
    buffer = root.listBuffers()[0];
  for (const clip of root.listAnimations()) clip.dispose();
  const joints = ['Spine', 'Spine1', 'Neck', 'LeftArm', 'RightArm', 'LeftForeArm', 'RightForeArm'].map((n) =>
    root.listNodes().find((node) => node.getName() === `mixamorig:${n}`)!,
  );
  const times = Float32Array.from({ length: 61 }, (_, i) => i / 30);
  for (const [name, degrees] of Object.entries(amplitudes)) {
    const clip = doc.createAnimation(name);
    joints.forEach((node, j) => {
      const [x1, y1, z1, w1] = node.getRotation();
      const axis = j % 3 === 1 ? [0, 0, 1] : [1, 0, 0];
      const values = new Float32Array(4 * times.length);
      times.forEach((t, i) => {
        const half = ((degrees * Math.PI) / 360) * Math.sin(Math.PI * t + j);
        const [x2, y2, z2, w2] = [
          axis[0] * Math.sin(half),
          axis[1] * Math.sin(half),
          axis[2] * Math.sin(half),
          Math.cos(half),
        ];
        values.set(
          [
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
          ],
          4 * i,
        );
      });
      const sampler = doc
        .createAnimationSampler()
        .setInput(doc.createAccessor().setType('SCALAR').setArray(times).setBuffer(buffer))
        .setOutput(doc.createAccessor().setType('VEC4').setArray(values).setBuffer(buffer))
        .setInterpolation('LINEAR');
      clip
        .addSampler(sampler)
        .addChannel(doc.createAnimationChannel().setTargetNode(node).setTargetPath('rotation').setSampler(sampler));
    });
  }
  const path = join(dir, file);
  await io.write(path, doc);
  return path;
}

async function bench(...args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  const out = { stdout: '', stderr: '' };
  const code = await runCommand(args, { out: (t) => (out.stdout += t), err: (t) => (out.stderr += t), isTTY: false });
  return { code, ...out };
}

let clips: string, none: string;
beforeAll(async () => {
  clips = await characterWithClips('clips.glb', { still: 0, sway: 5 });
  none = await characterWithClips('none.glb', {});
});

describe('the track experiment', () => {
  it('tracks a still clip exactly and a swaying one within δ, feet planted, no flips; JSON and CSV rows', async () => {
    const json = join(dir, 'track.json'),
      csv = join(dir, 'track.csv');
    const r = await bench('--rig', clips, '--experiment', 'track', '--json', json, '--csv', csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(
      /clip +frames +points +noise +success +reachable +success_reachable +mpjpe +mpjpe_upper +jitter_ratio +flips +foot_slide +median_us +p99_us/,
    );
    const rows = JSON.parse(readFileSync(json, 'utf8')).rows;
    expect(rows.map((row: { clip: string }) => row.clip)).toEqual(['still', 'sway']);
    const [still, sway] = rows;
    expect(still).toMatchObject({
      rig: 'clips',
      experiment: 'track',
      method: 'avatar',
      frames: 61,
      points: 3,
      noise: 0,
      success_rate: 1,
      reachable: 1,
      success_reachable: 1,
      flips: 0,
      jitter_ratio: null,
    });
    // The clip's joints and the rig's agree (the tracked points are met at 0 iterations); the knees'
    // poles bend the straight legs a little (0.04% of the height).
    expect(still.mpjpe).toBeLessThan(1e-3);
    expect(sway).toMatchObject({ frames: 61, points: 3, success_rate: 1, flips: 0 });
    expect(sway.mpjpe).toBeGreaterThan(0);
    expect(sway.mpjpe_upper).toBeLessThan(0.02);
    expect(sway.foot_slide).toBeLessThan(1e-3);
    expect(sway.median_us).toBeGreaterThan(0);
    const lines = readFileSync(csv, 'utf8').trim().split('\n');
    expect(lines[0]).toBe(
      'rig,experiment,method,clip,frames,points,noise,success_rate,reachable,success_reachable,mpjpe,mpjpe_upper,jitter_ratio,flips,foot_slide,median_us,p99_us',
    );
    expect(lines.length).toBe(3);
  });

  it('tracks six points (the hips and feet as well): nearly every frame within δ and 0.5°, nearer the clip than three', async () => {
    const json = join(dir, 'track6.json'),
      three = join(dir, 'track3.json');
    expect(
      (await bench('--rig', clips, '--experiment', 'track', '--clips', 'sway', '--points', '6', '--json', json)).code,
    ).toBe(0);
    expect((await bench('--rig', clips, '--experiment', 'track', '--clips', 'sway', '--json', three)).code).toBe(0);
    const [six] = JSON.parse(readFileSync(json, 'utf8')).rows,
      [threeRow] = JSON.parse(readFileSync(three, 'utf8')).rows;
    expect(six).toMatchObject({ clip: 'sway', points: 6, flips: 0 });
    // Measured 59 of 61 frames: on two the head ends 1.03 δ off, lm creeping where the spine's XZX
    // angles sit at their singular point (the rest pose), which turns a bone about its third axis
    // only at second order.
    expect(six.success_rate).toBeGreaterThan(0.95);
    expect(six.mpjpe).toBeLessThanOrEqual(threeRow.mpjpe);
    expect(six.foot_slide).toBeLessThan(1e-3);
    expect((await bench('--rig', clips, '--experiment', 'track', '--points', '4')).stderr).toBe(
      'bench: --points: 3 (head and hands) or 6 (and the hips and feet)\n',
    );
  });

  it("jitters the tracked positions with --noise (a tracker's noise, seeded): the same rows from the same seed, others from another, within δ of the positions given", async () => {
    const run = async (seed: string) => {
      const json = join(dir, `noise${seed}.json`);
      const r = await bench(
        '--rig',
        clips,
        '--experiment',
        'track',
        '--clips',
        'sway',
        '--noise',
        '0.001',
        '--seed',
        seed,
        '--json',
        json,
      );
      expect(r.code).toBe(0);
      return JSON.parse(readFileSync(json, 'utf8')).rows[0];
    };
    const [a, again, other] = [await run('1'), await run('1'), await run('2')];
    expect(a).toMatchObject({ clip: 'sway', noise: 0.001, success_rate: 1, flips: 0 });
    expect(again.mpjpe).toBe(a.mpjpe);
    expect(again.jitter_ratio).toBe(a.jitter_ratio);
    expect(other.mpjpe).not.toBe(a.mpjpe);
    // The jitter moves the targets: the joints' acceleration grows beyond the clip's.
    expect(a.jitter_ratio).toBeGreaterThan(1.5);
    expect((await bench('--rig', clips, '--experiment', 'track', '--noise', '-1')).stderr).toBe(
      'bench: --noise: "-1" is not a positive number of at most 0.1\n',
    );
    expect((await bench('--rig', clips, '--experiment', 'drag', '--noise', '0.001')).stderr).toBe(
      'bench: --noise goes with --experiment track only\n',
    );
  });

  it('refuses a clip the file lacks, a file without clips, a rig without a humanoid, and track beside other experiments', async () => {
    expect(await bench('--rig', clips, '--experiment', 'track', '--clips', 'wave')).toMatchObject({
      code: 2,
      stderr: 'bench: track: clips has no clip "wave" (it has: still, sway)\n',
    });
    expect(await bench('--rig', none, '--experiment', 'track')).toMatchObject({
      code: 2,
      stderr: 'bench: track: none has no animation clips\n',
    });
    expect((await bench('--rig', 'lamp', '--experiment', 'track')).stderr).toMatch(
      /^bench: lamp: the track experiment needs a glTF humanoid/,
    );
    expect((await bench('--rig', clips, '--experiment', 'track,drag')).stderr).toBe(
      'bench: --experiment: track runs alone, not with drag\n',
    );
    expect((await bench('--rig', clips, '--experiment', 'drag', '--clips', 'sway')).stderr).toBe(
      'bench: --clips goes with --experiment track only\n',
    );
  });
});
