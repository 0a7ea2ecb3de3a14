// bench:report's section 4 (bench-node/report/sections.ts): lm beside each peer with and without
// restarts, and its target judged with restarts on both: success at least the peer's and a lower
// median time to success.
import { describe, expect, it } from 'vitest';

import type { Row } from '../../bench-node/metrics.js';
import type { Measurements } from '../../bench-node/report/measure.js';
import { peersSection } from '../../bench-node/report/sections.js';
import { Verdicts } from '../../bench-node/report/verdicts.js';

/** A row with only what section 4 reads. */
function row(method: string, engine: string, restarts: number, success: number, toSuccess: number | null): Row {
  return {
    rig: 'knight',
    experiment: 'random',
    method,
    engine,
    restarts,
    success_rate: success,
    t_success_median_s: toSuccess,
    success_within_1ms: 0.5,
    success_within_10ms: 0.75,
    success_within_100ms: 1,
  } as Row;
}

function section(peers: Row[]): { text: string; verdicts: Verdicts } {
  const verdicts = new Verdicts();
  const text = peersSection({ peers } as Measurements, ['knight'], verdicts).join('\n');
  return { text, verdicts };
}

const ours = [
  row('lm', 'wasm', 1000, 1, 50e-6),
  row('lm', 'wasm', 0, 0.56, 40e-6),
  row('lm', 'native', 1000, 1, 30e-6),
  row('lm', 'native', 0, 0.56, 25e-6),
];

describe('section 4: lm against the peers', () => {
  it('shows every peer with and without restarts, time to success included', () => {
    const { text, verdicts } = section([
      ...ours,
      row('three-ccd', 'js', 1000, 0.55, 2e-3),
      row('three-ccd', 'js', 0, 0.2, 1e-3),
      row('closed-chain-ik', 'js', 1000, 0.92, 23e-3),
      row('closed-chain-ik', 'js', 0, 0.3, 5e-3),
      row('kdl', 'native', 1000, 0.9, 45e-3),
      row('kdl', 'native', 0, 0.3, 40e-3),
    ]);
    expect(verdicts.missed).toEqual([]);
    const lines = text.split('\n').filter((l) => l.startsWith('| knight'));
    expect(lines).toHaveLength(3);
    expect(lines[0]).toContain('three-ccd (JavaScript)');
    expect(lines[0]).toContain('55.0%; 2000.0 us median to success; 50.0% / 75.0% / 100.0%');
    expect(lines[2]).toContain('kdl (native)');
    expect(lines[2]).toContain('100.0%; 30.0 us median to success');
  });

  it('marks a peer that succeeds more often, or reaches its targets sooner, as a miss', () => {
    const { verdicts } = section([
      ...ours,
      row('three-ccd', 'js', 1000, 1, 20e-6),
      row('three-ccd', 'js', 0, 1, 20e-6),
      row('closed-chain-ik', 'js', 1000, 0.92, 23e-3),
      row('closed-chain-ik', 'js', 0, 0.3, 5e-3),
    ]);
    expect(verdicts.missed).toEqual([
      '4. knight random: lm does not beat three-ccd with restarts on both',
      '4. knight random: lm does not beat kdl with restarts on both', // no kdl row measured
    ]);
  });
});
