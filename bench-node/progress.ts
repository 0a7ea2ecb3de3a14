// The progress bar: cli-progress on stderr when it is a terminal, nothing otherwise.
import { SingleBar } from 'cli-progress';

export interface Progress {
  /** Names what is running now. */
  label(text: string): void;
  /** Adds finished solves. */
  advance(solves: number): void;
  stop(): void;
}

export function makeProgress(enabled: boolean, total: number): Progress {
  if (!enabled) return { label() {}, advance() {}, stop() {} };
  const bar = new SingleBar({
    format: '{bar} {percentage}% | {value}/{total} solves | {task} | ETA {eta_formatted}',
    stream: process.stderr,
    hideCursor: true,
    clearOnComplete: true,
    etaBuffer: 200,
  });
  bar.start(total, 0, { task: '' });
  return {
    label: (text) => bar.update({ task: text }),
    advance: (solves) => bar.increment(solves),
    stop: () => bar.stop(),
  };
}
