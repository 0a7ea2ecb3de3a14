// Section 7 of docs/benchmarks.md (bench:report): the default method as the page runs it while a
// user drags, on the drag and reach experiments of every rig.
import type { Row } from '../metrics.js';
import { formatStopReasons } from '../table.js';
import { pct, table, us } from './markdown.js';
import type { Verdicts } from './verdicts.js';

/** Target: on target at this share of the reachable steps, on every rig. */
export const DRAG_SUCCESS_TARGET = 0.999;

/** The section's Markdown lines from the rows of `--experiment drag,reach --methods lm`; each row's target goes to `verdicts`. */
export function draggingSection(rows: readonly Row[], verdicts: Verdicts): string[] {
  const length = (x: number | null): string => (x === null ? '-' : x.toPrecision(3));
  // Two decimals, so that a rate just under the target does not print as the target.
  const success = (x: number): string => (Number.isFinite(x) ? `${(100 * x).toFixed(2)}%` : '-');
  return [
    '## 7. Dragging: drag and reach',
    '',
    '`lm` as the page runs it while a user drags (`--experiment drag,reach --methods lm`, WebAssembly): no restarts, ' +
      'the drag tolerances (on target: every tip within 0.1% of the rig size of its target), each step starting from the ' +
      "previous step's solution. `drag`: one effector's own angles follow a sine from a random pose, the others pinned " +
      '(reachable by construction). `reach`: from the rest pose, one target moves in 40 steps towards its chain root and ' +
      'along two perpendicular directions, 40% of the distance, the others pinned; steps an untimed reference solve ' +
      '(`lm` with restarts, 1 s) cannot reach are counted as unreachable and left out of success. Wobble: the largest ' +
      'distance of a pinned effector from its target (rig units) over the iterates and at the solution; jump max: the largest ' +
      'change of one angle in one step; jumps: steps where a joint moved more than 5% of the rig size while the dragged ' +
      'target moved less than 1%; flips: steps where an elbow or knee bent against its anatomical direction or its bend ' +
      `plane turned more than 90 degrees (bench-node/README.md). Target: on target at >= ${pct(DRAG_SUCCESS_TARGET)} of the reachable steps on every rig.`,
    '',
    table(
      [
        'rig',
        'experiment',
        'steps',
        'success (reachable)',
        'unreachable',
        'wobble during max',
        'wobble after max',
        'jump max (deg)',
        'jumps',
        'flips',
        'median per step (us)',
        'stop reasons',
        'met',
      ],
      rows.map((r) => [
        r.rig,
        r.experiment,
        String(r.samples),
        success(r.success_rate),
        String(r.unreachable),
        length(r.wobble_during_max),
        length(r.wobble_after_max),
        length(r.jump_max_deg),
        r.jumps === null ? '-' : String(r.jumps),
        r.flips === null ? '-' : String(r.flips),
        us(r.t_median_s),
        formatStopReasons(r.stop_reasons),
        // Nothing reachable: nothing missed.
        verdicts.mark(
          !(r.success_rate < DRAG_SUCCESS_TARGET),
          `7. ${r.rig} ${r.experiment}: on target at ${success(r.success_rate)} of the reachable steps, under ${pct(DRAG_SUCCESS_TARGET)}`,
        ),
      ]),
    ),
    '',
  ];
}
