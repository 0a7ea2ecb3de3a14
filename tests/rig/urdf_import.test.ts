// The URDF importer (web/src/rig/urdf/urdf_model.ts, urdf_rig.ts, docs/urdf.md): the bones, limits and
// rest frames it makes of small robots written here (urdf_samples.ts), the default chain, the
// mesh warning, every refusal with its message (naming the file and the element), the hostile-input
// caps, loadRigFromPath and `npm run rig -- FILE.urdf --chain`. Forward kinematics: urdf_fk.test.ts.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { runRigInspect } from '../../scripts/rig_inspect.js';
import { loadRig, RigFormatError, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { MAX_BONES } from '../../web/src/rig/rig_limits.js';
import { MAX_URDF_BYTES, MAX_URDF_DEPTH, MAX_URDF_TAGS } from '../../web/src/rig/urdf/urdf_model.js';
import { needsRobots, robotPath, sharedRobots } from '../helpers/robots.js';
import { arm2, arm4, branched, urdfText, type SampleJoint } from './urdf_samples.js';

const dir = mkdtempSync(join(tmpdir(), 'urdf-import-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const FILE = 'robots/arm.urdf';
const bytes = (text: string): Uint8Array => new TextEncoder().encode(text);
const load = (text: string, chain?: string): Promise<LoadedRig> =>
  loadRig(bytes(text), FILE, undefined, chain === undefined ? {} : { chain });

/** loadRig refuses `text` with a RigFormatError starting with the file name and matching `pattern`. */
async function expectRefused(text: string | Uint8Array, pattern: RegExp, chain?: string): Promise<void> {
  const promise = loadRig(
    typeof text === 'string' ? bytes(text) : text,
    FILE,
    undefined,
    chain === undefined ? {} : { chain },
  );
  await expect(promise).rejects.toThrow(RigFormatError);
  await expect(promise).rejects.toThrow(new RegExp(`^${FILE}: `));
  await expect(promise).rejects.toThrow(pattern);
}

describe('URDF import', () => {
  it('makes one bone per revolute joint with a0 on its axis and the others locked, then the tip link', async () => {
    const rig = await load(urdfText(arm2.joints), arm2.chain);
    expect(rig.format).toBe('urdf');
    expect(rig.name).toBe('arm');
    expect(rig.spec.names).toEqual(['j1', 'j2', 'tool']);
    expect(Array.from(rig.spec.parents)).toEqual([-1, 0, 1]);
    expect(Array.from(rig.spec.effectors)).toEqual([2]);
    const deg = (r: number): number => (r * 180) / Math.PI;
    expect(Array.from(rig.spec.lower)).toEqual([deg(-2), 0, 0, deg(-1.5), 0, 0, 0, 0, 0]);
    expect(Array.from(rig.spec.upper)).toEqual([deg(2.5), 0, 0, deg(1), 0, 0, 0, 0, 0]);
    // j1's rest frame: at (0, 0, 0.1), x along its axis z.
    const rest = rig.spec.rest;
    expect([rest[3], rest[7], rest[11]]).toEqual([0, 0, 0.1]);
    expect([rest[0], rest[4], rest[8]]).toEqual([0, 0, 1]);
    // Joint bones reach the next bone's origin; the tip bone has length 0 (its tip is the tool's origin).
    expect(rig.spec.lengths[0]).toBeCloseTo(0.4, 12);
    expect(rig.spec.lengths[2]).toBe(0);
    expect(rig.urdf).toMatchObject({
      base: 'base',
      tip: 'tool',
      joints: ['j1', 'j2'],
      path: ['j1', 'j2', 'tool_joint'],
      tipBone: 2,
    });
    expect(rig.warnings).toEqual([]);
  });

  it("narrows a joint's limits to its safety controller's soft limits, as MoveIt and TRAC-IK do", async () => {
    const safe = (extra: string): string => urdfText([{ ...arm2.joints[0], extra }, ...arm2.joints.slice(1)]);
    const deg = (r: number): number => (r * 180) / Math.PI;
    const both = await load(
      safe('<safety_controller k_position="100" k_velocity="3" soft_lower_limit="-1.5" soft_upper_limit="3"/>'),
      'base:tool',
    );
    expect([both.spec.lower[0], both.spec.upper[0]]).toEqual([deg(-1.5), deg(2.5)]); // the hard upper limit is the tighter
    const one = await load(safe('<safety_controller k_velocity="3" soft_upper_limit="0.5"/>'), 'base:tool');
    expect([one.spec.lower[0], one.spec.upper[0]]).toEqual([deg(-2), deg(0.5)]);
    await expectRefused(
      safe('<safety_controller k_velocity="3" soft_lower_limit="2.6"/>'),
      /joint "j1": its <safety_controller> soft limits leave no range within <limit> \(2\.6 > 2\.5 radians\)/,
      'base:tool',
    );
    await expectRefused(
      safe('<safety_controller k_velocity="3" soft_lower_limit="x"/>'),
      /joint "j1": <safety_controller soft_lower_limit> = "x" is not a finite number/,
      'base:tool',
    );
  });

  it('gives a continuous joint -180 .. 180 degrees and folds fixed joints away', async () => {
    const rig = await load(urdfText(arm4.joints), arm4.chain);
    expect(rig.spec.names).toEqual(['j1', 'j2', 'j3', 'j4', 'l4']);
    expect([rig.spec.lower[3], rig.spec.upper[3]]).toEqual([-180, 180]);
    expect(rig.urdf?.path).toEqual(['j1', 'j2', 'mid', 'j3', 'j4']);
  });

  it('takes the longest serial chain by default and says so in a warning', async () => {
    const rig = await load(urdfText(branched.joints));
    expect(rig.urdf).toMatchObject({ base: 'base', tip: 'b4', joints: ['trunk', 'b1', 'b3', 'b4'] });
    expect(rig.warnings).toEqual([
      'no chain given: took the longest serial chain base:b4 (4 moving joints); choose another with --chain BASE:TIP',
    ]);
    // Another chain of the same tree, and one below the prismatic joint (which lies outside it).
    // The tip bone is named after the link, told apart from a joint of the same name.
    expect((await load(urdfText(branched.joints), 'trunk:a2')).spec.names).toEqual(['a1', 'a2', 'a2 (link)']);
    expect((await load(urdfText(branched.joints), 'p1:p3')).spec.names).toEqual(['p2', 'p3', 'p3 (link)']);
    expect((await load(urdfText(branched.joints), 'base:b4')).warnings).toEqual([]);
  });

  it('ignores prismatic, planar, floating and mimic joints outside the chain', async () => {
    const joints: SampleJoint[] = [
      ...arm2.joints,
      { name: 'finger', type: 'prismatic', parent: 'tool', child: 'finger', axis: '0 1 0', lower: 0, upper: 0.04 },
      {
        name: 'finger2',
        type: 'prismatic',
        parent: 'tool',
        child: 'finger2',
        axis: '0 1 0',
        lower: 0,
        upper: 0.04,
        extra: '<mimic joint="finger"/>',
      },
      { name: 'plane', type: 'planar', parent: 'base', child: 'cart' },
      { name: 'world', type: 'floating', parent: 'sky', child: 'drone' },
    ];
    expect((await load(urdfText(joints), arm2.chain)).spec.names).toEqual(['j1', 'j2', 'tool']);
    expect((await load(urdfText(joints))).urdf).toMatchObject({ base: 'base', tip: 'tool' });
  });

  it('warns once about package:// meshes, which it never reads', async () => {
    const rig = await load(urdfText(arm2.joints, { meshes: true }), arm2.chain);
    expect(rig.warnings).toEqual([
      '4 package:// mesh files not read: the rig needs none (a viewer without the ROS package draws the links as bones)',
    ]);
  });

  it('reads the file alone: no sibling reads, even with a reader', async () => {
    const reads: string[] = [];
    const reader = async (uri: string): Promise<Uint8Array> => {
      reads.push(uri);
      throw new Error('no');
    };
    await loadRig(bytes(urdfText(arm2.joints, { meshes: true })), FILE, reader, { chain: arm2.chain });
    expect(reads).toEqual([]);
  });
});

describe('URDF refusals name the file and the element', () => {
  const arm = (change: (j: SampleJoint[]) => SampleJoint[]): string =>
    urdfText(change(arm2.joints.map((j) => ({ ...j }))));
  const cases: [string, string, RegExp, string?][] = [
    ['bad XML', '<robot><link name="a"></robot>', /bad XML at line 1, column \d+: Expected closing tag 'link'/],
    ['a root that is not <robot>', '<sdf><link name="a"/></sdf>', /its root element is not <robot>/],
    ['no link', '<robot name="r"/>', /has no <link>/],
    [
      'a joint without a parent link',
      urdfText(arm2.joints).replace('<parent link="l1"/>', ''),
      /joint "j2" has no <parent> link; it needs one/,
    ],
    [
      'an unknown parent link',
      urdfText(arm2.joints).replace('<parent link="l1"/>', '<parent link="elbow"/>'),
      /joint "j2": its parent link "elbow" is no <link> of the robot/,
    ],
    [
      'a link with two parents',
      arm((j) => [...j, { name: 'again', type: 'fixed', parent: 'base', child: 'l2' }]),
      /the link "l2" is the child of two joints, "j2" and "again"/,
    ],
    [
      'a cycle',
      arm((j) => [...j.slice(1), { name: 'loop', type: 'fixed', parent: 'tool', child: 'l1' }]),
      /the joints form a cycle of links: "l1" -> "l2" -> "tool" -> "l1"/,
    ],
    [
      'two links of one name',
      urdfText(arm2.joints, { links: ['base', 'base'] }).replace('<link name="l1">', '<link name="base">'),
      /two links are named "base"/,
    ],
    [
      'an unknown joint type',
      arm((j) => [{ ...j[0], type: 'hinge' }, ...j.slice(1)]),
      /joint "j1" has the unknown type "hinge"/,
    ],
    [
      'an unknown link in the chain',
      urdfText(arm2.joints),
      /the chain's TIP link "gripper" is no <link> of the robot/,
      'base:gripper',
    ],
    ['a chain that is not BASE:TIP', urdfText(arm2.joints), /the chain "base" is not BASE:TIP/, 'base'],
    [
      'a chain that is not serial',
      urdfText(branched.joints),
      /the chain "a2:b4" is not serial: the link "b4" does not hang below "a2"/,
      'a2:b4',
    ],
    ['a chain upside down', urdfText(arm2.joints), /the chain "tool:base" is not serial/, 'tool:base'],
    [
      'a chain without moving joints',
      urdfText(arm2.joints),
      /the chain l2:tool has no revolute or continuous joint/,
      'l2:tool',
    ],
    [
      'a prismatic joint in the chain',
      urdfText(branched.joints),
      /joint "slide" is prismatic and lies in the chain trunk:p3; only revolute, continuous and fixed joints can be imported/,
      'trunk:p3',
    ],
    [
      'a planar joint in the chain',
      arm((j) => [{ ...j[0], type: 'planar' }, ...j.slice(1)]),
      /joint "j1" is planar and lies in the chain base:tool/,
      'base:tool',
    ],
    [
      'a floating joint in the chain',
      arm((j) => [...j.slice(0, 2), { ...j[2], type: 'floating' }]),
      /joint "tool_joint" is floating and lies in the chain base:tool/,
      'base:tool',
    ],
    [
      'a mimic joint in the chain',
      arm((j) => [j[0], { ...j[1], extra: '<mimic joint="j1"/>' }, j[2]]),
      /joint "j2" \(revolute\) mimics another joint and lies in the chain base:tool/,
      'base:tool',
    ],
    [
      'a non-finite number',
      arm((j) => [{ ...j[0], xyz: '0 1e999 0' }, ...j.slice(1)]),
      /joint "j1": <origin xyz> = "1e999" is not a finite number/,
      'base:tool',
    ],
    [
      'a word for a number',
      arm((j) => [{ ...j[0], rpy: '0 nan 0' }, ...j.slice(1)]),
      /joint "j1": <origin rpy> = "nan" is not a finite number/,
      'base:tool',
    ],
    [
      'two numbers for three',
      arm((j) => [{ ...j[0], axis: '0 1' }, ...j.slice(1)]),
      /joint "j1": <axis xyz="0 1"> must hold 3 numbers/,
      'base:tool',
    ],
    [
      'an axis of zero length',
      arm((j) => [{ ...j[0], axis: '0 0 0' }, ...j.slice(1)]),
      /joint "j1": its <axis xyz="0 0 0"> has zero length/,
      'base:tool',
    ],
    [
      'limits lower > upper',
      arm((j) => [{ ...j[0], lower: 1, upper: -1 }, ...j.slice(1)]),
      /joint "j1": <limit lower="1"> is above upper="-1"/,
      'base:tool',
    ],
    [
      'a revolute joint without limits',
      urdfText(arm2.joints).replace(/<limit[^>]*\/>/, ''),
      /joint "j1" is revolute but has no <limit>/,
      'base:tool',
    ],
    [
      'a limit past 100 turns',
      arm((j) => [{ ...j[0], lower: 1000, upper: 2000 }, ...j.slice(1)]),
      /joint "j1": its <limit> .* leaves no angle/,
      'base:tool',
    ],
    [
      'a joint beyond 1e9 units',
      arm((j) => [{ ...j[0], xyz: '2e9 0 0' }, ...j.slice(1)]),
      /joint "j1" lies beyond \+-1000000000 units/,
      'base:tool',
    ],
  ];
  it.each(cases)('%s', async (_what, text, pattern, chain) => {
    await expectRefused(text, pattern, chain);
  });

  it('a chain only for URDF files', async () => {
    await expect(loadRig(bytes('{}'), 'rig.json', undefined, { chain: 'a:b' })).rejects.toThrow(
      /rig.json: a chain can only be chosen in a URDF file/,
    );
  });

  it('more moving joints than the core takes', async () => {
    const joints: SampleJoint[] = Array.from({ length: MAX_BONES }, (_, k) => ({
      name: `j${k}`,
      type: 'continuous',
      parent: `l${k}`,
      child: `l${k + 1}`,
      xyz: '0 0 0.01',
    }));
    await expectRefused(
      urdfText(joints),
      new RegExp(`the chain l0:l${MAX_BONES} has ${MAX_BONES} moving joints; the core takes at most ${MAX_BONES - 1}`),
      `l0:l${MAX_BONES}`,
    );
  });

  it(`a file past ${MAX_URDF_BYTES} bytes, ${MAX_URDF_TAGS} tags or ${MAX_URDF_DEPTH} levels`, async () => {
    await expectRefused(
      new Uint8Array(MAX_URDF_BYTES + 1).fill(0x20),
      new RegExp(`${MAX_URDF_BYTES + 1} bytes; a URDF file may have at most ${MAX_URDF_BYTES}`),
    );
    await expectRefused(
      `<robot>${'<a/>'.repeat(MAX_URDF_TAGS)}</robot>`,
      new RegExp(`more than ${MAX_URDF_TAGS} XML tags`),
    );
    const deep = MAX_URDF_DEPTH + 1;
    await expectRefused(
      `<robot>${'<a>'.repeat(deep)}${'</a>'.repeat(deep)}</robot>`,
      new RegExp(`the XML nests deeper than ${MAX_URDF_DEPTH} elements`),
    );
  });

  it('does not expand entities', async () => {
    const bomb =
      `<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">]>` +
      urdfText(arm2.joints)
        .replace(/^<\?xml[^>]*>/, '')
        .replace('name="sample"', 'name="&b;"');
    expect((await load(bomb, arm2.chain)).urdf?.robot).toBe('&b;');
  });
});

describe('URDF from disk and `npm run rig`', () => {
  const path = join(dir, 'arm.urdf');
  writeFileSync(path, urdfText(arm2.joints, { meshes: true }));

  it('loadRigFromPath takes the chain', async () => {
    const rig = await loadRigFromPath(path, { chain: 'base:l2' });
    expect(rig.spec.names).toEqual(['j1', 'j2', 'l2']);
  });

  it('prints the chain and its limits, and takes --chain', async () => {
    let out = '',
      err = '';
    const io = { out: (t: string) => (out += t), err: (t: string) => (err += t) };
    expect(await runRigInspect([path, '--chain', 'base:tool'], io)).toBe(0);
    expect(out).toContain(
      `${path}: URDF, 3 bones\nend effectors (1): tool\nchain: base:tool, 2 moving joints (j1, j2); the end effector's frame is tool's\n`,
    );
    expect(out).toContain('  j1: [-114.59, 0, 0] .. [143.24, 0, 0]\n');
    out = '';
    expect(await runRigInspect([path, '--chain', 'base:nowhere', '--json'], io)).toBe(1);
    expect(err).toBe(`rig: ${path}: the chain's TIP link "nowhere" is no <link> of the robot\n`);
  });
});

describe.each(sharedRobots)('`npm run rig -- $name.urdf --chain $chain --json`', needsRobots, (robot) => {
  it('matches tests/rig/expected-urdf', async () => {
    let out = '';
    const code = await runRigInspect([robotPath(robot.name), '--chain', robot.chain, '--json'], {
      out: (t) => (out += t),
      err: (t) => (out += t),
    });
    expect(code).toBe(0);
    const expected = readFileSync(resolve(import.meta.dirname, 'expected-urdf', `${robot.name}.rig.json`), 'utf8');
    expect(JSON.parse(out)).toEqual(JSON.parse(expected));
  });
});
