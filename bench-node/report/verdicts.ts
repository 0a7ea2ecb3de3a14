// The targets bench:report checks (its "met" columns): each check gives its table cell and, when
// missed, a line for the summary the report prints, writes and exits non-zero on.

export class Verdicts {
  /** One line per missed target: where (section, rig, experiment, ...) and by how much. */
  readonly missed: string[] = [];
  private checked = 0;

  /** The cell of a check: 'yes' when `ok`; else '**no**', and `what` joins the missed targets. */
  mark(ok: boolean, what: string): string {
    this.checked++;
    if (ok) return 'yes';
    this.missed.push(what);
    return '**no**';
  }

  /** "All 63 targets met." or "5 of 63 targets missed:" and one "- ..." line per miss. */
  summary(): string[] {
    if (this.missed.length === 0) return [`All ${this.checked} targets met.`];
    return [`${this.missed.length} of ${this.checked} targets missed:`, '', ...this.missed.map((m) => `- ${m}`)];
  }
}
