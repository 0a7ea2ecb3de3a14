// WebAssembly objects a test file makes and frees at its end, newest first (solvers before their rigs).
import { afterAll } from 'vitest';

/** Returns keep(o): o, registered to be disposed after the calling file's tests. */
export function disposeAfterAll(): <T extends { dispose(): void }>(o: T) => T {
  const owned: { dispose(): void }[] = [];
  afterAll(() => owned.reverse().forEach((o) => o.dispose()));
  return (o) => {
    owned.push(o);
    return o;
  };
}
