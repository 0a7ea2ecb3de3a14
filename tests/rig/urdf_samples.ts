// Small URDF robots written for the tests (urdf_import.test.ts, urdf_fk.test.ts): a joint list
// turned into URDF text, and a few arms with their chains.

export interface SampleJoint {
  name: string;
  type: string;
  parent: string;
  child: string;
  xyz?: string;
  rpy?: string;
  axis?: string;
  /** Radians; a revolute joint without them gets -1 .. 1. */
  lower?: number;
  upper?: number;
  /** More XML inside the <joint> element. */
  extra?: string;
}

/** The URDF text of a robot with these joints; its links are the joints' ends (and `links`), each with a package:// mesh when `meshes`. */
export function urdfText(
  joints: readonly SampleJoint[],
  options: { links?: string[]; meshes?: boolean; name?: string } = {},
): string {
  const links = [...new Set([...(options.links ?? []), ...joints.flatMap((j) => [j.parent, j.child])])];
  const mesh = (l: string): string =>
    options.meshes ? `<visual><geometry><mesh filename="package://sample/meshes/${l}.dae"/></geometry></visual>` : '';
  const joint = (j: SampleJoint): string => {
    const origin = j.xyz || j.rpy ? `<origin xyz="${j.xyz ?? '0 0 0'}" rpy="${j.rpy ?? '0 0 0'}"/>` : '';
    const axis = j.axis ? `<axis xyz="${j.axis}"/>` : '';
    const limit =
      j.type === 'revolute' || j.lower !== undefined
        ? `<limit lower="${j.lower ?? -1}" upper="${j.upper ?? 1}" effort="1" velocity="1"/>`
        : '';
    return `  <joint name="${j.name}" type="${j.type}">${origin}<parent link="${j.parent}"/><child link="${j.child}"/>${axis}${limit}${j.extra ?? ''}</joint>`;
  };
  return [
    '<?xml version="1.0"?>',
    `<robot name="${options.name ?? 'sample'}">`,
    ...links.map((l) => `  <link name="${l}">${mesh(l)}</link>`),
    ...joints.map(joint),
    '</robot>',
  ].join('\n');
}

export interface SampleRobot {
  label: string;
  joints: SampleJoint[];
  chain: string;
  dof: number;
}

/** Two revolute joints and a tool off every axis, on a fixed joint. */
export const arm2: SampleRobot = {
  label: 'two joints and an off-axis tool',
  chain: 'base:tool',
  dof: 2,
  joints: [
    { name: 'j1', type: 'revolute', parent: 'base', child: 'l1', axis: '0 0 1', xyz: '0 0 0.1', lower: -2, upper: 2.5 },
    {
      name: 'j2',
      type: 'revolute',
      parent: 'l1',
      child: 'l2',
      axis: '0 1 0',
      xyz: '0 0 0.4',
      rpy: '0.1 0 0',
      lower: -1.5,
      upper: 1,
    },
    { name: 'tool_joint', type: 'fixed', parent: 'l2', child: 'tool', xyz: '0.3 0.05 -0.02', rpy: '0.3 -0.2 0.1' },
  ],
};

/** Four joints: a continuous one on an unnormalised axis, a fixed joint between, a negative axis, a skew axis. */
export const arm4: SampleRobot = {
  label: 'four joints, continuous, fixed and skew axes',
  chain: 'base:l4',
  dof: 4,
  joints: [
    { name: 'j1', type: 'revolute', parent: 'base', child: 'l1', axis: '0 0 1', xyz: '0 0 0.1', lower: -3, upper: 3 },
    { name: 'j2', type: 'continuous', parent: 'l1', child: 'l2', axis: '0 1 1', xyz: '0.05 0 0.3' },
    { name: 'mid', type: 'fixed', parent: 'l2', child: 'l2b', xyz: '0.2 0 0', rpy: '0 1.5707963 0' },
    {
      name: 'j3',
      type: 'revolute',
      parent: 'l2b',
      child: 'l3',
      axis: '-1 0 0',
      xyz: '0 0.1 0.25',
      lower: -2,
      upper: 0.5,
    },
    {
      name: 'j4',
      type: 'revolute',
      parent: 'l3',
      child: 'l4',
      axis: '0.3 -0.4 0.5',
      xyz: '0.1 -0.2 0.15',
      rpy: '2.5 -1.2 0.7',
      lower: -0.7,
      upper: 2.9,
    },
  ],
};

/**
 * A tree: a trunk joint, then a 2-joint branch a, a 3-joint branch b with a fixed joint inside,
 * and a branch below a prismatic joint. The longest serial chain is base:b4 (4 moving joints).
 */
export const branched: SampleRobot = {
  label: 'a branched tree',
  chain: 'base:b4',
  dof: 4,
  joints: [
    { name: 'trunk', type: 'revolute', parent: 'base', child: 'trunk', axis: '0 0 1', xyz: '0 0 0.2' },
    { name: 'a1', type: 'revolute', parent: 'trunk', child: 'a1', axis: '0 1 0', xyz: '0.1 0 0.1' },
    { name: 'a2', type: 'revolute', parent: 'a1', child: 'a2', axis: '0 1 0', xyz: '0.3 0 0' },
    { name: 'b1', type: 'revolute', parent: 'trunk', child: 'b1', axis: '1 0 0', xyz: '-0.1 0 0.1' },
    { name: 'b2', type: 'fixed', parent: 'b1', child: 'b2', xyz: '0 0 0.2', rpy: '0 0 0.5' },
    { name: 'b3', type: 'revolute', parent: 'b2', child: 'b3', axis: '0 1 0', xyz: '0 0 0.2' },
    { name: 'b4', type: 'revolute', parent: 'b3', child: 'b4', axis: '0 0 1', xyz: '0 0.1 0.1' },
    { name: 'slide', type: 'prismatic', parent: 'trunk', child: 'p1', axis: '0 0 1', lower: 0, upper: 0.1 },
    { name: 'p2', type: 'revolute', parent: 'p1', child: 'p2', axis: '0 0 1', xyz: '0 0 0.1' },
    { name: 'p3', type: 'revolute', parent: 'p2', child: 'p3', axis: '0 1 0', xyz: '0 0 0.1' },
  ],
};

export const sampleRobots: readonly SampleRobot[] = [arm2, arm4, branched];
