// The page's keyboard shortcuts, in the order the help overlay lists them: selecting targets,
// editing the pose and its history, the gizmo and the target's goals, then the modes (track, step,
// compare) and the help. A key does what the panel's button does (PanelActions), the targets' and
// the gizmo's keys what TargetActions does; this table names the keys and says what they do.
import type { Shortcut } from './keyboard.js';
import type { PageSettings } from './page_settings.js';
import type { PanelActions } from './panel.js';
import type { TargetActions } from './target_actions.js';
import type { TrackMode } from './track_mode.js';

/** The page's shortcuts; labels that depend on `settings` read them each time the help opens. */
export function pageShortcuts(
  settings: PageSettings,
  actions: PanelActions,
  targets: TargetActions,
  track: TrackMode,
): Shortcut[] {
  return [...editShortcuts(actions, targets), ...modeShortcuts(settings, actions, targets, track)];
}

/** Selecting targets, resetting, undo and redo, the gizmo and the target's goals. */
function editShortcuts(actions: PanelActions, targets: TargetActions): Shortcut[] {
  return [
    {
      keys: ['Tab'],
      label: 'select the next target (in track mode: the next tracked point)',
      run: () => targets.stepTarget(1),
      focusKey: true,
    },
    { keys: ['Shift+Tab'], label: 'select the previous target', run: () => targets.stepTarget(-1), focusKey: true },
    { keys: ['R'], label: 'reset the pose', run: () => actions.resetPose() },
    {
      keys: ['Ctrl+Z'],
      label: 'undo (target moves, effector changes, reset, rig loads, pose files)',
      run: () => actions.undo(),
    },
    { keys: ['Ctrl+Shift+Z', 'Ctrl+Y'], label: 'redo', run: () => actions.redo() },
    { keys: ['W'], label: 'gizmo: translate the target', run: () => targets.setGizmo('translate') },
    {
      keys: ['E'],
      label: 'gizmo: rotate the target (the hand turns to its orientation)',
      run: () => targets.setGizmo('rotate'),
    },
    { keys: ['Q'], label: 'gizmo: swing the target about the root joint', run: () => targets.setGizmo('swing') },
    {
      keys: ['O'],
      label: 'orientation goal of the selected target on or off',
      run: () => targets.setOrientationGoal(),
    },
    {
      keys: ['P'],
      label: 'pole handles on or off (drag one to turn an elbow or knee towards it)',
      run: () => targets.togglePoleHandles(),
    },
  ];
}

/** Track mode, a step, compare, the help and Esc. */
function modeShortcuts(
  settings: PageSettings,
  actions: PanelActions,
  targets: TargetActions,
  track: TrackMode,
): Shortcut[] {
  return [
    {
      keys: ['T'],
      label: 'track mode on or off: gizmos on the head and hands move the whole body (a recognised humanoid)',
      run: () => track.toggle(),
    },
    {
      keys: ['S'],
      label: () => `step mode: one iteration of ${settings.method}${settings.paperMode ? ' (paper mode)' : ''}`,
      run: () => actions.step(),
    },
    { keys: ['C'], label: () => compareHelp(settings), run: () => actions.compare() },
    { keys: ['?', 'H'], label: 'show or hide this help', run: () => actions.help() },
    {
      keys: ['Escape'],
      label: 'deselect: the gizmo lets go of its target (with this help open: close the help)',
      run: () => targets.deselect(),
    },
  ];
}

/** What C does with the settings in the panel now (the help overlay reads it each time it opens). */
function compareHelp(s: PageSettings): string {
  const paper = s.paperMode ? ', as the report ran them (paper mode)' : '';
  return `compare every method from the ${s.compareFrom}${paper}: ${s.compareTimeBudgetMs} ms and ${s.compareMaxIterations} iterations each, ${s.restarts} restart${s.restarts === 1 ? '' : 's'}`;
}
