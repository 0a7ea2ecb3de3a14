// JSON text with what JSON.stringify cannot write: numbers that parse as +-Infinity (1e999) and
// arrays nested deeper than a recursive stringify could go. Mutators put marker strings in the
// document; jsonText() turns them into that raw text.

/** Marker values for a document: written as 1e999, -1e999 and `depth` nested arrays. */
export const INFINITY_MARK = '__fuzz_inf__';
export const NEG_INFINITY_MARK = '__fuzz_ninf__';
export function deepMark(depth: number): string {
  return `__fuzz_deep_${depth}__`;
}

/** The JSON text of `doc` with the markers replaced. */
export function jsonText(doc: unknown): string {
  return JSON.stringify(doc).replace(/"__fuzz_(inf|ninf|deep_(\d+))__"/g, (_, what: string, depth?: string) => {
    if (what === 'inf') return '1e999';
    if (what === 'ninf') return '-1e999';
    const d = Number(depth);
    return '['.repeat(d) + ']'.repeat(d);
  });
}
