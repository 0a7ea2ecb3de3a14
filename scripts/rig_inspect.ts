// `npm run rig -- FILE [--chain BASE:TIP] [--json]`: what the rig importer makes of a file (bone
// count, end effectors, humanoid mapping, a URDF's chain, limits, warnings), as a short summary or as JSON. The command as a
// function, runRigInspect (scripts/rig.ts calls it on process.argv). A file that does not load
// gives one line `rig: ...` on stderr and exit code 1; a usage error exit code 2.
import { Command, CommanderError } from 'commander';

import { HUMANOID_ROLES, type HumanoidRole } from '#rig/humanoid/humanoid_roles.js';
import { RigFormatError, type LoadedRig } from '#rig/load_rig.js';
import { loadRigFromPath } from '#rig/load_rig_node.js';

/** Limits of one bone, degrees per XZX angle; null = unbounded. */
export interface BoneLimits {
  min: (number | null)[];
  max: (number | null)[];
}

/** The `--json` output. Bones are named by their rig names (a repeated name gets " (bone K)"). */
export interface RigReport {
  bones: number;
  effectors: string[];
  humanoid: Partial<Record<HumanoidRole, string>> | null;
  limits: Record<string, BoneLimits>;
  warnings: string[];
}

/** One label per bone: its name, or "name (bone K)" for a name several bones share. */
function boneLabels(names: readonly string[]): string[] {
  const count = new Map<string, number>();
  for (const n of names) count.set(n, (count.get(n) ?? 0) + 1);
  return names.map((n, k) => (count.get(n)! > 1 ? `${n} (bone ${k})` : n));
}

/** Bone b's 3 limits of `values` (degrees), null for an unbounded one. */
/** Bone b's three limits in degrees to 1e-6 (derived limits carry rounding noise), null when unbounded. */
const boneLimit = (values: Float64Array, b: number): (number | null)[] =>
  Array.from(values.subarray(3 * b, 3 * b + 3), (v) => (Number.isFinite(v) ? Math.round(v * 1e6) / 1e6 + 0 : null));

/** What the importer made of `rig`, in the shape of the `--json` output. Angles in degrees. */
export function rigReport(rig: LoadedRig): RigReport {
  const { spec } = rig;
  const label = boneLabels(spec.names);
  const map = rig.gltf?.humanoid;
  const roles = map ? HUMANOID_ROLES.filter((r) => map.bones[r] !== undefined) : [];
  return {
    bones: spec.parents.length,
    effectors: Array.from(spec.effectors, (b) => label[b]),
    humanoid: map ? Object.fromEntries(roles.map((r) => [r, label[map.bones[r]!]])) : null,
    // fromEntries defines own properties, so a bone named "__proto__" stays a plain key.
    limits: Object.fromEntries(
      label.map((l, b) => [l, { min: boneLimit(spec.lower, b), max: boneLimit(spec.upper, b) }]),
    ),
    warnings: rig.warnings,
  };
}

/**
 * The report as JSON text: one key per line, and each bone's limits on one line
 * ("hand.L": {"min": [-20, -60, -20], "max": [20, 60, 20]}), so that a diff shows what changed.
 */
export function reportJson(r: RigReport): string {
  const list = (v: unknown[]): string => `[${v.map((x) => JSON.stringify(x)).join(', ')}]`;
  const block = (lines: string[], open: string, close: string): string =>
    lines.length ? `${open}\n${lines.join(',\n')}\n  ${close}` : `${open}${close}`;
  const key = JSON.stringify;
  const humanoid =
    r.humanoid &&
    block(
      Object.entries(r.humanoid).map(([role, bone]) => `    ${key(role)}: ${key(bone)}`),
      '{',
      '}',
    );
  const limits = block(
    Object.entries(r.limits).map(([bone, l]) => `    ${key(bone)}: {"min": ${list(l.min)}, "max": ${list(l.max)}}`),
    '{',
    '}',
  );
  const warnings = block(
    r.warnings.map((w) => `    ${key(w)}`),
    '[',
    ']',
  );
  return `{\n  "bones": ${r.bones},\n  "effectors": ${list(r.effectors)},\n  "humanoid": ${humanoid ?? 'null'},\n  "limits": ${limits},\n  "warnings": ${warnings}\n}\n`;
}

const FORMATS = { a7: 'A7 rig', glb: 'glTF binary', gltf: 'glTF', urdf: 'URDF' } as const;

const REGIONS: [string, HumanoidRole[]][] = [
  ['torso', ['hips', 'spine', 'chest', 'upperChest', 'neck', 'head']],
  ['left arm', ['leftShoulder', 'leftUpperArm', 'leftLowerArm', 'leftHand']],
  ['right arm', ['rightShoulder', 'rightUpperArm', 'rightLowerArm', 'rightHand']],
  ['left leg', ['leftUpperLeg', 'leftLowerLeg', 'leftFoot', 'leftToes']],
  ['right leg', ['rightUpperLeg', 'rightLowerLeg', 'rightFoot', 'rightToes']],
];

const angles = (v: (number | null)[], unbounded: string): string =>
  `[${v.map((x) => (x === null ? unbounded : Number(x.toFixed(2)))).join(', ')}]`;
const isDefault = (l: BoneLimits): boolean => l.min.every((v) => v === -180) && l.max.every((v) => v === 180);

/** A short human-readable summary of `rig` loaded from `file`, lines ending in '\n'. */
export function rigSummary(rig: LoadedRig, file: string): string {
  const r = rigReport(rig);
  const lines = [
    `${file}: ${FORMATS[rig.format]}, ${r.bones} bones`,
    `end effectors (${r.effectors.length}): ${r.effectors.join(', ')}`,
  ];
  const map = rig.gltf?.humanoid;
  const urdf = rig.urdf;
  if (urdf)
    lines.push(
      `chain: ${urdf.base}:${urdf.tip}, ${urdf.joints.length} moving joints (${urdf.joints.join(', ')}); the end effector's frame is ${urdf.tip}'s`,
    );
  else if (!map || !r.humanoid) lines.push('humanoid: not recognised');
  else {
    const missing = map.missing.length ? `; missing the core roles ${map.missing.join(', ')}` : '';
    lines.push(
      `humanoid (${map.source}): ${Object.keys(r.humanoid).length} of ${HUMANOID_ROLES.length} roles${missing}`,
    );
    for (const [region, roles] of REGIONS) {
      const named = roles
        .filter((role) => r.humanoid![role] !== undefined)
        .map((role) => `${role}=${r.humanoid![role]}`);
      if (named.length) lines.push(`  ${region}: ${named.join(', ')}`);
    }
  }
  const limited = Object.entries(r.limits).filter(([, l]) => !isDefault(l));
  const atDefault = r.bones - limited.length;
  if (!limited.length) lines.push('limits: every angle of every bone in -180 .. 180 degrees (the default)');
  else {
    lines.push('limits (degrees, XZX min .. max):');
    for (const [bone, l] of limited) lines.push(`  ${bone}: ${angles(l.min, '-inf')} .. ${angles(l.max, 'inf')}`);
    if (atDefault) lines.push(`  ${atDefault} other bones: -180 .. 180 (the default)`);
  }
  lines.push(r.warnings.length ? 'warnings:' : 'warnings: none', ...r.warnings.map((w) => `  - ${w}`));
  return lines.map(printable).join('\n') + '\n';
}

/** Control characters (line breaks, terminal escapes) of a line escaped, so that it prints as one line. */
function printable(line: string): string {
  // eslint-disable-next-line no-control-regex -- the control characters are what it escapes
  return line.replace(/[\u0000-\u001f\u007f]/g, (c) => JSON.stringify(c).slice(1, -1));
}

/** Where the command writes: results (stdout), errors (stderr). */
export interface InspectIo {
  out: (text: string) => void;
  err: (text: string) => void;
}

const processIo: InspectIo = {
  out: (text) => process.stdout.write(text),
  err: (text) => process.stderr.write(text),
};

class UsageError extends Error {}

/** Parses argv: the file, --chain and --json; undefined after printing the help. */
function parseArgs(argv: string[], io: InspectIo): { file: string; json: boolean; chain?: string } | undefined {
  const cmd = new Command('npm run rig --')
    .description(
      'Prints what the rig importer makes of a file: bone count, end effectors, humanoid mapping, limits and warnings.',
    )
    .argument('<file>', 'a rig file: .glb, .gltf, .urdf or A7 .json')
    .option(
      '--chain <BASE:TIP>',
      "a URDF file's chain, from the BASE link down to the TIP link (default: the longest serial chain)",
    )
    .option(
      '--json',
      'print {"bones", "effectors", "humanoid", "limits", "warnings"} as JSON (limits in degrees, null = unbounded)',
      false,
    )
    .allowExcessArguments(false)
    .exitOverride()
    .configureOutput({ writeOut: io.out, writeErr: () => {}, outputError: () => {} });
  try {
    cmd.parse(argv, { from: 'user' });
  } catch (e) {
    if (e instanceof CommanderError && (e.code === 'commander.helpDisplayed' || e.code === 'commander.help'))
      return undefined;
    throw new UsageError((e as Error).message.replace(/^error: /, '').split('\n')[0]);
  }
  const { json, chain } = cmd.opts<{ json: boolean; chain?: string }>();
  return { file: cmd.args[0], json, chain };
}

/**
 * Runs the inspector on `argv` (without node and the script) and returns the exit code: 0, 1 for
 * a file that does not load, 2 for a usage error; each error is one line `rig: ...` on `io.err`.
 */
export async function runRigInspect(argv: string[], io: InspectIo = processIo): Promise<number> {
  try {
    const args = parseArgs(argv, io);
    if (!args) return 0;
    const rig = await loadRigFromPath(args.file, { chain: args.chain });
    io.out(args.json ? reportJson(rigReport(rig)) : rigSummary(rig, args.file));
    return 0;
  } catch (e) {
    if (!(e instanceof UsageError || e instanceof RigFormatError)) throw e;
    io.err(`rig: ${printable(e.message)}\n`);
    return e instanceof UsageError ? 2 : 1;
  }
}
