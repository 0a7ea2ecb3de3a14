// A small window onto track mode for browser tests and tools, as probe.ts is onto the drag mode:
// the tracked points and where their handles are on screen, the avatar's head, hands and feet,
// where the feet were planted, the clip's ghost, and the last solve. Set as window.ikTrack by main.ts.
import { Vector3 } from 'three';

import type { ScreenPoint } from '../view/stage.js';
import type { PageApp } from './app.js';
import type { TrackSource } from './track_mode.js';

export interface TrackProbe {
  active(): boolean;
  /** Why the rig shown cannot be tracked; null when it can. */
  problem(): string | null;
  source(): TrackSource;
  /** The tracked points: 3 per point (head, left hand, right hand), rig units. */
  points(): number[];
  /** Where tracked point k's handle is on screen (client pixels), or null. */
  pointScreen(k: number): ScreenPoint | null;
  /** The point holding the gizmo, or null. */
  selected(): number | null;
  /** The avatar's head, left and right hand, left and right foot and hips tips now (3 each, rig units); [] when track mode is off. */
  tips(): number[];
  /** Those as the avatar stood when track mode went on. */
  standingTips(): number[];
  /** Where each foot (left, right) is planted (rig units), or null while it steps; [] when track mode is off. */
  plantedFeet(): Array<number[] | null>;
  /** The avatar's height at rest, rig units; NaN when track mode is off. */
  height(): number;
  /** Solves since track mode went on. */
  solves(): number;
  /** The last solve: every tracked point within its tolerances, and its stop reason; null before one. */
  lastSolve(): { reached: boolean; stopReason: string; ms: number } | null;
  clipNames(): string[];
  /** The clip playing (file order), or null. */
  playingClip(): number | null;
  /** The ghost's head and hand tips as drawn, its offset taken off (3 each, rig units), or null without a ghost. */
  ghostTips(): number[] | null;
  /** Where the ghost stands relative to the avatar (rig units), or null. */
  ghostOffset(): [number, number, number] | null;
}

declare global {
  interface Window {
    ikTrack?: TrackProbe;
  }
}

export function makeTrackProbe(app: PageApp): TrackProbe {
  const { track } = app;
  const stage = app.controller.stage;
  const p = new Vector3();
  return {
    active: () => track.active,
    problem: () => track.problem(),
    source: () => track.source,
    points: () => Array.from(track.points.positions),
    pointScreen: (k) =>
      track.active && k >= 0 && k < 3 ? stage.toScreen(p.fromArray(track.points.positions, 3 * k)) : null,
    selected: () => track.gizmos.handles.selected,
    tips: () => Array.from(track.avatar?.solver.tips() ?? []),
    standingTips: () => Array.from(track.avatar?.standingTips ?? []),
    plantedFeet: () => track.avatar?.solver.plantedFeet() ?? [],
    height: () => track.avatar?.standing.height ?? NaN,
    solves: () => track.solves,
    lastSolve: () =>
      track.outcome
        ? { reached: track.outcome.reached, stopReason: track.outcome.stopReason, ms: track.avatar?.ms ?? NaN }
        : null,
    clipNames: () => track.clipNames(),
    playingClip: () => track.clipPlayer?.playing ?? null,
    ghostTips: () => (track.clipPlayer ? Array.from(track.clipPlayer.ghostTips()) : null),
    ghostOffset: () =>
      track.clipPlayer ? (track.clipPlayer.root.position.toArray() as [number, number, number]) : null,
  };
}
