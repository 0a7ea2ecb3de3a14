// Text that changes every frame (solve times, errors) is written a few times a second, not 60:
// a Throttle runs its function at once when it has not run for `intervalMs` milliseconds, else
// once at the end of the interval, so the last request is always honoured.
export class Throttle {
  private last = -Infinity;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private readonly fire = (): void => {
    this.timer = undefined;
    this.last = performance.now();
    this.run();
  };

  constructor(
    private readonly run: () => void,
    private readonly intervalMs = 100,
  ) {}

  /** Asks for a run: now, or at the end of the interval (several requests meanwhile make one run). */
  request(): void {
    if (this.timer !== undefined) return;
    const wait = this.last + this.intervalMs - performance.now();
    if (wait <= 0) this.fire();
    else this.timer = setTimeout(this.fire, wait);
  }

  /** Runs now (a waiting run is dropped: this one replaces it). */
  now(): void {
    clearTimeout(this.timer);
    this.fire();
  }

  /** Drops the waiting run, if any. */
  cancel(): void {
    clearTimeout(this.timer);
    this.timer = undefined;
  }
}
