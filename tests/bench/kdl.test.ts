// The native engine's `kdl` method (Orocos KDL, wasm/native/kdl/): refused on the wasm engine with
// a clear line, left out of the --methods default, and on the native engine it solves a few
// samples of a project rig. A native build without KDL must say that kdl needs the package.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { runCommand } from '../../bench-node/command.js';
import { parseOptions } from '../../bench-node/options.js';
import { nativeToolPath } from '../../bench-node/run_native.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { rigsLike } from '../helpers/a7.js';

const methods = IkSolver.methods(await loadIkNode());
const lamp = rigsLike('ikea-lamp')[0].path; // the project's lamp as an A7 file
const dir = mkdtempSync(join(tmpdir(), 'bench-kdl-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** The native tool's methods (--list-methods), [] when it is not built. */
function nativeMethods(): string[] {
  const listed = spawnSync(nativeToolPath, ['--list-methods'], { encoding: 'utf8' });
  return listed.status === 0 ? (JSON.parse(listed.stdout) as string[]) : [];
}

describe('kdl on the command line', () => {
  it('is refused without the native engine, with one clear line', async () => {
    expect(() => parseOptions(['--rig', lamp, '--methods', 'kdl'], false, methods)).toThrow(
      /^kdl runs only on the native engine: add --engine native$/,
    );
    const out = { stdout: '', stderr: '' };
    const code = await runCommand(['--rig', lamp, '--methods', 'lm,kdl', '--engine', 'wasm'], {
      out: (t) => (out.stdout += t),
      err: (t) => (out.stderr += t),
      isTTY: false,
    });
    expect(code).toBe(2);
    expect(out.stdout).toBe('');
    expect(out.stderr.trim()).toBe('bench: kdl runs only on the native engine: add --engine native');
  });

  it('is not in the --methods default, and runs on native alone when both engines are asked for', () => {
    expect(parseOptions(['--rig', lamp], false, methods)!.methods).not.toContain('kdl');
    expect(parseOptions(['--rig', lamp, '--methods', 'kdl', '--engine', 'native'], false, methods)!.methods).toEqual([
      'kdl',
    ]);
    expect(
      parseOptions(['--rig', lamp, '--methods', 'kdl', '--engine', 'wasm,native'], false, methods)!.engines,
    ).toEqual(['wasm', 'native']);
  });
});

describe('kdl on the native engine', () => {
  // npm test's setup installs Orocos KDL (scripts/setup.sh --native), so the native tool has kdl.
  it('is in the native tool', () => {
    expect(nativeMethods()).toContain('kdl');
  });

  it('solves a few random and incremental samples of a project rig', async () => {
    const file = join(dir, 'kdl.json');
    const out = { stdout: '', stderr: '' };
    const code = await runCommand(
      [
        '--rig',
        lamp,
        '--methods',
        'kdl',
        '--engine',
        'wasm,native',
        '--samples',
        '5',
        '--workers',
        '1',
        '--warm-up',
        '0',
        '--json',
        file,
      ],
      { out: (t) => (out.stdout += t), err: (t) => (out.stderr += t), isTTY: false },
    );
    expect(out.stderr).toBe('');
    expect(code).toBe(0);
    const rows = (JSON.parse(readFileSync(file, 'utf8')) as { rows: Record<string, unknown>[] }).rows;
    expect(rows.map((r) => `${r.experiment} ${r.method} ${r.engine}`)).toEqual([
      'random kdl native',
      'incremental kdl native',
    ]);
    for (const row of rows) {
      expect(row.samples).toBe(5);
      expect(row.success_rate).toBe(1);
    }
  });
});
