// Immersive VR on the page's renderer (WebXR through three.js's renderer.xr): whether the browser
// offers 'immersive-vr', entering a session with the viewer standing in front of the avatar and
// facing it, and each XR frame's head and grip poses as an XrSample for XrTracking.input()
// (xr_tracking.ts). Not tried on a headset (README, "The page"): the tests drive XrTracking with a
// recorded stream instead (tests/page/xr_tracking.test.ts).
import { Quaternion, Vector3, type WebGLRenderer } from 'three';

import { type XrSample, xrSample } from './xr_tracking.js';

/** Whether this browser can enter immersive VR (navigator.xr.isSessionSupported); false without WebXR or when it will not say. */
export async function immersiveVrSupported(): Promise<boolean> {
  if (!navigator.xr) return false;
  try {
    return await navigator.xr.isSessionSupported('immersive-vr');
  } catch {
    return false;
  }
}

/** What a session tells its owner. */
export interface VrEvents {
  /** The session ended (the user left VR, the headset was taken off, or end()). */
  ended(): void;
  /** A controller's squeeze button was pressed (track mode calibrates anew). */
  squeezed(): void;
}

export class VrSession {
  private constructor(
    private readonly renderer: WebGLRenderer,
    private readonly session: XRSession,
  ) {}

  /**
   * Enters immersive VR on `renderer` (a 'local-floor' reference space: y = 0 is the floor) with
   * the viewer at `at` (scene units) looking along `facing` (a horizontal direction), as if
   * standing there. Rejects with the browser's reason when the session cannot start.
   */
  static async start(renderer: WebGLRenderer, at: Vector3, facing: Vector3, events: VrEvents): Promise<VrSession> {
    if (!navigator.xr) throw new Error('this browser has no WebXR (navigator.xr)');
    const session = await navigator.xr.requestSession('immersive-vr', { optionalFeatures: ['local-floor'] });
    session.addEventListener('end', () => {
      renderer.xr.enabled = false;
      events.ended();
    });
    session.addEventListener('squeeze', () => events.squeezed());
    renderer.xr.enabled = true;
    renderer.xr.setReferenceSpaceType('local-floor');
    try {
      await renderer.xr.setSession(session);
    } catch (e) {
      void session.end().catch(() => {}); // e.g. no 'local-floor' space: the session is of no use
      throw e;
    }
    const floor = renderer.xr.getReferenceSpace();
    if (floor) renderer.xr.setReferenceSpace(floor.getOffsetReferenceSpace(viewerPlacement(at, facing)));
    return new VrSession(renderer, session);
  }

  /** This XR frame's head and grip poses in the renderer's reference space, or null outside an XR frame. */
  sample(): XrSample | null {
    const frame = this.renderer.xr.getFrame();
    const space = this.renderer.xr.getReferenceSpace();
    return frame && space ? xrSample(frame, space, this.session.inputSources) : null;
  }

  /** Leaves VR (VrEvents.ended follows). */
  end(): void {
    void this.session.end().catch(() => {}); // already ending
  }
}

/**
 * The offset of a reference space in which a user standing at its old origin, looking along its
 * -Z, stands at `at` looking along `facing`: the inverse of that placement.
 */
function viewerPlacement(at: Vector3, facing: Vector3): XRRigidTransform {
  const yaw = Math.atan2(facing.x, facing.z) - Math.PI; // from -Z to `facing`, about +Y
  const inverse = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), -yaw);
  const p = at.clone().applyQuaternion(inverse).negate();
  return new XRRigidTransform({ x: p.x, y: p.y, z: p.z }, { x: inverse.x, y: inverse.y, z: inverse.z, w: inverse.w });
}
