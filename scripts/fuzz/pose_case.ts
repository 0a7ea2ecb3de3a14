// Pose cases: pose files for rigs whose bones have no usable name ('' as in every A7 rig, a name
// two bones share, a name that looks like an index key "#3"). A pose written for such a rig must
// read back the same, bit for bit; a file keying a bone by a name that cannot tell it apart must
// be refused with a clear error, never read into some other bone.
import type { RigSpec } from '#ik/rig_arrays.js';
import { poseFromJson, poseToJson, POSE_FORMAT, POSE_VERSION } from '#rig/pose_json.js';
import { attempt } from './attempt.js';
import type { Acceptance } from './hostile_args.js';
import { worse, type Outcome } from './outcome.js';
import type { Rand } from './random.js';
import { randomAngles, randomRig } from './random_rig.js';
import { clampToLimits } from './result_checks.js';

/** A random rig of 1 to 40 bones, each bone unnamed, sharing a name or named like an index key by chance. */
function unnamedRig(r: Rand): RigSpec {
  const spec = randomRig(r, r.intIn(1, 40));
  const names = spec.names!.map((name, i) =>
    r.weighted<() => string>([
      [4, () => name],
      [4, () => ''],
      [1, () => `bone ${r.int(i + 1)}`],
      [1, () => `#${r.int(40)}`],
    ])(),
  );
  return { ...spec, names };
}

/** Where `got` differs from `expected` bit for bit, or undefined. */
function sameProblem(name: string, got: ArrayLike<number>, expected: ArrayLike<number>): string | undefined {
  if (got.length !== expected.length) return `${name} has ${got.length} numbers, expected ${expected.length}`;
  for (let k = 0; k < got.length; k++)
    if (!Object.is(got[k], expected[k])) return `${name}[${k}] is ${got[k]}, expected ${expected[k]}`;
  return undefined;
}

/** A written pose read back: the same angles (within the limits), effectors and targets. */
function roundTrip(spec: RigSpec, angles: Float64Array, targets: Float64Array): Outcome {
  const effectors = Array.from(spec.effectors);
  return attempt(
    'must',
    () => poseFromJson(poseToJson({ rigName: 'rig', boneNames: spec.names!, angles, effectors, targets }), spec),
    (read) =>
      sameProblem('angles', read.angles, clampToLimits(spec, angles)) ??
      sameProblem('effectors', read.effectors, effectors) ??
      sameProblem('targets', read.targets, targets),
  );
}

/**
 * A hand-written file giving angles to the bone called `key` (not an index key like "#3"):
 * refused unless exactly one bone has that name and it is not '', else read into that bone.
 */
function keyedBy(spec: RigSpec, key: string, angles: number[]): Outcome {
  const bones = spec.names!.flatMap((n, i) => (n === key ? [i] : []));
  const accept: Acceptance = bones.length === 1 && key !== '' ? 'must' : 'mustNot';
  const text = JSON.stringify({ format: POSE_FORMAT, version: POSE_VERSION, bones: { [key]: angles }, effectors: [] });
  return attempt(
    accept,
    () => poseFromJson(text, spec),
    (read) => {
      const expected = clampToLimits(spec, new Float64Array(3 * spec.names!.length));
      for (let k = 3 * bones[0]; k < 3 * bones[0] + 3; k++)
        expected[k] = Math.min(spec.upper[k], Math.max(spec.lower[k], angles[k % 3]));
      return sameProblem('angles', read.angles, expected);
    },
  );
}

/** Runs one pose case drawn from `r`. */
export function runPoseCase(r: Rand, note: (text: string) => void): Outcome {
  const spec = unnamedRig(r);
  const names = spec.names!;
  note(
    `${names.length}-bone rig named ${JSON.stringify(names).slice(0, 300)}, effectors [${Array.from(spec.effectors)}]`,
  );
  const angles = randomAngles(r, spec);
  const targets = Float64Array.from({ length: 3 * spec.effectors.length }, () => r.range(-5, 5));
  const key = r.pick(names.filter((n) => !/^#\d+$/.test(n)).concat(''));
  const keyAngles = [r.range(-200, 200), r.range(-200, 200), r.range(-200, 200)];
  note(`round trip; then a file keyed ${JSON.stringify(key)}: ${JSON.stringify(keyAngles)}`);
  const written = roundTrip(spec, angles, targets);
  const keyed = keyedBy(spec, key, keyAngles);
  return worse(
    { kind: written.kind, message: `round trip: ${written.message}` },
    { kind: keyed.kind, message: `keyed ${JSON.stringify(key)}: ${keyed.message}` },
  );
}
