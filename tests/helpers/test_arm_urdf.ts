// The test arm of the URDF tests: six revolute joints with limits (a bent elbow at the zero pose),
// a fixed joint to an off-axis tool tip tool0, a camera branch on link2, and box meshes on link1
// and link3 named as package:// files. Lengths in metres, +z up, as URDF has them.
/** A revolute joint of the test arm. */
export const revolute = (
  name: string,
  parent: string,
  child: string,
  xyz: string,
  axis: string,
  lower: number,
  upper: number,
  rpy = '0 0 0',
): string =>
  `<joint name="${name}" type="revolute"><parent link="${parent}"/><child link="${child}"/><origin xyz="${xyz}" rpy="${rpy}"/>` +
  `<axis xyz="${axis}"/><limit lower="${lower}" upper="${upper}" effort="10" velocity="1"/></joint>`;

/** The arm's visuals: a box mesh on link1 at the link's origin, one on link3 off its origin (0.1 along its z), both package:// files. */
export const VISUALS: Record<string, string> = {
  link1: '<visual><geometry><mesh filename="package://test_arm/meshes/link1.stl"/></geometry></visual>',
  link3:
    '<visual><origin xyz="0 0 0.1"/><geometry><mesh filename="package://test_arm/meshes/link3.stl"/></geometry><material name="orange"><color rgba="1 0.5 0 1"/></material></visual>',
};

/** The test arm: base_link -> six revolute joints -> flange, a fixed joint to the off-axis tool0; a camera on link2. */
export function armUrdf(cameraLimits: [number, number] = [-1.0, 1.0]): string {
  const links = [
    'base_link',
    'link1',
    'link2',
    'link3',
    'link4',
    'link5',
    'flange',
    'tool0',
    'camera_link',
    'camera_optical_frame',
  ];
  return `<?xml version="1.0"?>
<robot name="test_arm">
  ${links.map((l) => (VISUALS[l] ? `<link name="${l}">${VISUALS[l]}</link>` : `<link name="${l}"/>`)).join('\n  ')}
  ${revolute('shoulder_pan', 'base_link', 'link1', '0 0 0.1', '0 0 1', -2.9, 2.9)}
  ${revolute('shoulder_lift', 'link1', 'link2', '0 0.08 0.05', '0 1 0', -2.0, 2.0, '0 0.3 0')}
  ${revolute('elbow', 'link2', 'link3', '0 -0.06 0.35', '0 1 0', -2.6, 2.6, '0 1.0 0')}
  ${revolute('wrist_1', 'link3', 'link4', '0 0 0.3', '0 1 0', -3.0, 3.0, '0 0.5 0')}
  ${revolute('wrist_2', 'link4', 'link5', '0 0.05 0.05', '0 0 1', -3.0, 3.0)}
  ${revolute('wrist_3', 'link5', 'flange', '0 0 0.06', '0 1 0', -3.0, 3.0)}
  <joint name="tool_mount" type="fixed"><parent link="flange"/><child link="tool0"/><origin xyz="0.03 0.08 0.02" rpy="0.3 -0.5 0.2"/></joint>
  ${revolute('camera_tilt', 'link2', 'camera_link', '0 0.06 0.2', '0 1 0', ...cameraLimits)}
  <joint name="camera_optical" type="fixed"><parent link="camera_link"/><child link="camera_optical_frame"/><origin xyz="0.04 0 0.03" rpy="-1.5708 0 -1.5708"/></joint>
</robot>
`;
}
