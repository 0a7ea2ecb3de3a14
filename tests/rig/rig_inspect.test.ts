// `npm run rig -- FILE [--json]`: on every project model the JSON matches the checked-in
// expectation (tests/rig/expected/<name>.rig.json; after a deliberate change to a model or the
// importer, remake one with `npx tsx scripts/rig.ts web/public/models/<name>.glb --json >
// tests/rig/expected/<name>.rig.json` and review the diff). The command runs in this process
// through runRigInspect, what scripts/rig.ts calls; one case runs the real command for its exit
// code and stderr.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { reportJson, rigReport, runRigInspect } from '../../scripts/rig_inspect.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { a7Path, needsA7 } from '../helpers/a7.js';
import { packGlb } from '../../scripts/rig_files/glb.js';
import { treeGltf } from '../../scripts/rig_files/tree_rigs.js';

const root = resolve(import.meta.dirname, '../..');
const modelsDir = resolve(root, 'web/public/models');
const expectedDir = resolve(import.meta.dirname, 'expected');
const dir = mkdtempSync(join(tmpdir(), 'rig-inspect-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

interface Outcome {
  code: number;
  stdout: string;
  stderr: string;
}

async function inspect(...args: string[]): Promise<Outcome> {
  const out = { stdout: '', stderr: '' };
  const code = await runRigInspect(args, { out: (t) => (out.stdout += t), err: (t) => (out.stderr += t) });
  return { code, ...out };
}

/** Exit code `code`, nothing on stdout, one line `rig: ...` matching `pattern` on stderr. */
function expectOneLineError(r: Outcome, code: number, pattern: RegExp): void {
  expect(r.stdout).toBe('');
  expect(r.stderr).not.toContain('    at ');
  const lines = r.stderr.trimEnd().split('\n');
  expect(lines).toHaveLength(1);
  expect(lines[0]).toMatch(/^rig: /);
  expect(lines[0]).toMatch(pattern);
  expect(r.code).toBe(code);
}

const models = readdirSync(modelsDir)
  .filter((f) => f.endsWith('.glb'))
  .map((f) => f.slice(0, -'.glb'.length));

describe('rig inspector on the project models', () => {
  it('has an expectation for every model and none for a model that is gone', () => {
    expect(models.length).toBeGreaterThanOrEqual(6);
    expect(readdirSync(expectedDir).sort()).toEqual(models.map((m) => `${m}.rig.json`).sort());
  });

  it.each(models)('--json on %s.glb matches tests/rig/expected', async (name) => {
    const r = await inspect(join(modelsDir, `${name}.glb`), '--json');
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toEqual(JSON.parse(readFileSync(join(expectedDir, `${name}.rig.json`), 'utf8')));
  });

  it('prints a short summary without --json', async () => {
    const file = join(modelsDir, 'knight.glb');
    const r = await inspect(file);
    expect(r.code).toBe(0);
    const lines = r.stdout.split('\n');
    expect(lines.slice(0, 4)).toEqual([
      `${file}: glTF binary, 19 bones`,
      'end effectors (5): head, hand.L, hand.R, foot.L, foot.R',
      'humanoid (rigify): 19 of 22 roles',
      '  torso: hips=hips, spine=spine, chest=chest, neck=neck, head=head',
    ]);
    expect(lines).toContain('  forearm.L: [0, 0, -60] .. [0, 145, 60]');
    expect(r.stdout.endsWith('warnings:\n  - humanoid (rigify): 14 of 14 core roles\n')).toBe(true);
  });

  it('reads an A7 rig too', needsA7, async () => {
    const r = await inspect(a7Path('knight'), '--json');
    expect(r.code).toBe(0);
    const report = JSON.parse(r.stdout);
    expect(report.bones).toBeGreaterThan(0);
    expect(report.humanoid).toBeNull();
    expect(Object.keys(report.limits)).toHaveLength(report.bones);
  });
});

describe('rig inspector output', () => {
  it('names bones that share a name by index, keeps odd names as keys, and writes JSON that reads back the same', async () => {
    const json = treeGltf([-1, 0, 1, 1]);
    ['__proto__', 'a "b"\nc', 'x', 'x'].forEach((name, k) => (json.nodes[k].name = name));
    json.nodes[1].extras = { ik: { xzx_min: [null, -10, 0], xzx_max: [null, 90, 0] } };
    const rig = await loadRig(packGlb(json), 'odd.glb');
    const report = rigReport(rig);
    expect(Object.keys(report.limits)).toEqual(['__proto__', 'a "b"\nc', 'x (bone 2)', 'x (bone 3)']);
    expect(report.limits['a "b"\nc']).toEqual({ min: [null, -10, 0], max: [null, 90, 0] });
    expect(report.effectors).toEqual(['x (bone 2)', 'x (bone 3)']);
    expect(JSON.parse(reportJson(report))).toEqual(report);
  });

  it('escapes control characters in the summary', async () => {
    const json = treeGltf([-1, 0]);
    json.nodes[1].name = 'evil\u001b[2Jname\nnext';
    const file = join(dir, 'odd.glb');
    writeFileSync(file, packGlb(json));
    const r = await inspect(file);
    expect(r.stdout).not.toContain('\u001b');
    expect(r.stdout).toContain('end effectors (1): evil\\u001b[2Jname\\nnext');
  });
});

describe('rig inspector errors: one line on stderr, non-zero exit', () => {
  it.each([
    [[], 2, /^rig: missing required argument 'file'$/],
    [['a.glb', 'b.glb'], 2, /^rig: too many arguments/],
    [['--frobnicate', 'a.glb'], 2, /^rig: unknown option '--frobnicate'$/],
    [[join(dir, 'missing.glb')], 1, /missing\.glb: cannot read the file: ENOENT/],
  ] as [string[], number, RegExp][])('%j', async (args, code, pattern) => {
    expectOneLineError(await inspect(...args), code, pattern);
  });

  it('a bad file, as the real command: exit code 1, one line naming the file', () => {
    const bad = join(dir, 'bad.glb');
    writeFileSync(bad, new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0]));
    const r = spawnSync(process.execPath, ['--import', 'tsx', 'scripts/rig.ts', bad, '--json'], {
      cwd: root,
      encoding: 'utf8',
    });
    expectOneLineError(
      { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr },
      1,
      /bad\.glb: truncated GLB: 8 bytes/,
    );
  });
});
