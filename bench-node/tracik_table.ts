// The published anchor of --experiment tracik: KDL's and TRAC-IK's solve rates and average times
// (over all queries, successes and failures) under TRAC-IK's protocol (tracik.ts), from the
// TRAC-IK README, v1.4.6 (https://bitbucket.org/traclabs/trac_ik, trac_ik/README.md; copied in
// ../shared/robots/README.md). A run's row is matched by its rig's file base name and its
// --chain (BASE:TIP), against the URDF files of ../shared/robots (example-robot-data 6.0.0).
import type { Row } from './metrics.js';
import { formatNumber, formatStopReasons, type Table } from './table.js';

export interface PublishedRow {
  /** The chain as the TRAC-IK README names it. */
  chain: string;
  dof: number;
  kdlRate: number;
  /** Seconds. */
  kdlAvg: number;
  tracikRate: number;
  tracikAvg: number;
  /** The runs that match: rig file base name and --chain BASE:TIP (none: no such robot in ../shared/robots). */
  matches: ReadonlyArray<{ rig: string; chain: string }>;
}

/** TRAC-IK v1.4.6's README table, the rows of the robots we have and of two we do not. */
export const TRACIK_PUBLISHED: readonly PublishedRow[] = [
  // The README of ../shared/robots names the tip left_hand; the file's link is left_hand_link
  // (fixed to left_wrist).
  {
    chain: 'Baxter arm',
    dof: 7,
    kdlRate: 0.6107,
    kdlAvg: 2.21e-3,
    tracikRate: 0.9962,
    tracikAvg: 0.43e-3,
    matches: [
      { rig: 'baxter', chain: 'base:left_hand' },
      { rig: 'baxter', chain: 'base:left_hand_link' },
      { rig: 'baxter', chain: 'base:left_wrist' },
    ],
  },
  // TRAC-IK's Jaco2 may differ from j2s6s200 in its wrist geometry.
  {
    chain: 'Jaco2',
    dof: 6,
    kdlRate: 0.2623,
    kdlAvg: 3.79e-3,
    tracikRate: 0.9978,
    tracikAvg: 0.41e-3,
    matches: [{ rig: 'kinova', chain: 'j2s6s200_link_base:j2s6s200_end_effector' }],
  },
  {
    chain: 'Franka Emika Panda',
    dof: 7,
    kdlRate: 0.6177,
    kdlAvg: 2.14e-3,
    tracikRate: 0.997,
    tracikAvg: 0.38e-3,
    matches: [{ rig: 'panda', chain: 'panda_link0:panda_link8' }],
  },
  {
    chain: 'PR2 arm',
    dof: 7,
    kdlRate: 0.8318,
    kdlAvg: 1.37e-3,
    tracikRate: 0.9995,
    tracikAvg: 0.38e-3,
    matches: [{ rig: 'pr2', chain: 'torso_lift_link:r_wrist_roll_link' }],
  },
  {
    chain: 'KUKA LBR iiwa 14',
    dof: 7,
    kdlRate: 0.3764,
    kdlAvg: 3.38e-3,
    tracikRate: 0.9984,
    tracikAvg: 0.31e-3,
    matches: [],
  },
  { chain: 'Fetch arm', dof: 7, kdlRate: 0.9246, kdlAvg: 0.73e-3, tracikRate: 0.9999, tracikAvg: 0.26e-3, matches: [] },
];

/** The published row of a run on `rig` (file base name) with `chain` (--chain; undefined: none), or undefined. */
export function publishedRow(
  rig: string,
  chain: string | undefined,
  table: readonly PublishedRow[] = TRACIK_PUBLISHED,
): PublishedRow | undefined {
  return chain === undefined ? undefined : table.find((p) => p.matches.some((m) => m.rig === rig && m.chain === chain));
}

/** A tracik row: ours, the chain it ran on, and the published figures of that chain (null: not in the table). */
export interface TracikRow extends Row {
  chain: string | null;
  published_chain: string | null;
  published_kdl_rate: number | null;
  published_kdl_avg_s: number | null;
  published_tracik_rate: number | null;
  published_tracik_avg_s: number | null;
}

/** `row` with its chain and the published figures that match it. */
export function withPublished(
  row: Row,
  chain: string | undefined,
  table: readonly PublishedRow[] = TRACIK_PUBLISHED,
): TracikRow {
  const p = publishedRow(row.rig, chain, table);
  return {
    ...row,
    chain: chain ?? null,
    published_chain: p?.chain ?? null,
    published_kdl_rate: p?.kdlRate ?? null,
    published_kdl_avg_s: p?.kdlAvg ?? null,
    published_tracik_rate: p?.tracikRate ?? null,
    published_tracik_avg_s: p?.tracikAvg ?? null,
  };
}

/** A share as a percentage with two decimals (the published table's precision); '-' for null. */
function percent(x: number | null): string {
  return x === null || !Number.isFinite(x) ? '-' : `${(100 * x).toFixed(2)}%`;
}

/** The CSV columns of a tracik run. */
export const tracikCsvColumns = [
  'rig',
  'chain',
  'experiment',
  'method',
  'engine',
  'goals',
  'samples',
  'restarts',
  'success_rate',
  't_avg_s',
  't_median_s',
  't_p95_s',
  't_max_s',
  'iter_avg',
  'E_max',
  'rot_err_avg_deg',
  'rot_err_max_deg',
  'twist_rate',
  'published_chain',
  'published_kdl_rate',
  'published_kdl_avg_s',
  'published_tracik_rate',
  'published_tracik_avg_s',
  'stop_reasons',
] as const satisfies ReadonlyArray<keyof TracikRow>;

/**
 * The table of one rig's tracik rows: solve rate (distance and angle within 1e-5), the rate by
 * TRAC-IK's own test (each twist component within 1e-5: what its table counts), average time over all queries (TRAC-IK's way),
 * median, and the published KDL and TRAC-IK figures of the chain beside ours ('-' when the
 * chain is not in the table).
 */
export function tracikTable(rows: readonly TracikRow[]): Table {
  const first = rows[0];
  const headers = [
    'method',
    'engine',
    'samples',
    'restarts',
    'solve rate',
    "rate (TRAC-IK's test)",
    't_avg',
    't_median',
    't_p95',
    't_max',
    'rot_err_max_deg',
    'KDL rate (published)',
    'KDL t_avg (published)',
    'TRAC-IK rate (published)',
    'TRAC-IK t_avg (published)',
    'stop reasons',
  ];
  const chain = first.chain ? ` ${first.chain}` : '';
  const published = first.published_chain ? `; published: ${first.published_chain}, TRAC-IK v1.4.6 README` : '';
  return {
    title: `${first.rig}${chain}, tracik protocol (pose within 1e-5, 5 ms budget by default${published})`,
    headers,
    numeric: headers.map((h) => !['method', 'engine', 'stop reasons'].includes(h)),
    rows: rows.map((r) => [
      r.method,
      r.engine,
      String(r.samples),
      String(r.restarts),
      percent(r.success_rate),
      percent(r.twist_rate),
      formatNumber(r.t_avg_s),
      formatNumber(r.t_median_s),
      formatNumber(r.t_p95_s),
      formatNumber(r.t_max_s),
      formatNumber(r.rot_err_max_deg),
      percent(r.published_kdl_rate),
      formatNumber(r.published_kdl_avg_s),
      percent(r.published_tracik_rate),
      formatNumber(r.published_tracik_avg_s),
      formatStopReasons(r.stop_reasons),
    ]),
  };
}
