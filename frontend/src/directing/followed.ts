// The path the motion on stage followed (a drawn path it was generated with, or a path edit),
// kept on the floor after generating — it used to vanish when the path was used up — with a
// toggle to hide it. The path waiting for the next Generate (the store's `path`) is another
// thing: it is drawn instead while there is one.
import { create } from "zustand";
import type { EditInfo, Plan } from "../api/types";
import type { Point } from "./path";

export interface FollowedPath {
  /** The motion (version) that followed it. */
  motionId: string;
  person: number;
  points: Point[];
}

const SHOW_KEY = "interplay-show-path";

function storedShow(): boolean {
  try {
    return localStorage.getItem(SHOW_KEY) !== "0";
  } catch {
    return true;
  }
}

export const useFollowed = create<{ path: FollowedPath | null; show: boolean; setShow(show: boolean): void }>()((set) => ({
  path: null,
  show: storedShow(),
  setShow: (show) => {
    try {
      localStorage.setItem(SHOW_KEY, show ? "1" : "0");
    } catch {
      /* private mode: not remembered */
    }
    set({ show });
  },
}));

/** Drawn points [[x, z], …] of a trajectory as the API stores it, or null (a preset shape). */
function pointsOf(t: unknown): { person: number; points: Point[] } | null {
  if (typeof t !== "object" || t === null) return null;
  const { points, person } = t as { points?: unknown; person?: unknown };
  if (!Array.isArray(points) || points.length < 2) return null;
  const ok = points.every((p) => Array.isArray(p) && p.length === 2 && p.every((v) => typeof v === "number" && Number.isFinite(v)));
  return ok ? { person: typeof person === "number" ? person : 0, points: points as Point[] } : null;
}

/** The path a stored motion followed: its own path edit's, else the one its plan was made
 * with (a version made by another edit keeps its parent's plan, and so its path). */
export function followedOf(motion: { id: string; plan?: Plan | null; edit?: EditInfo | null }): FollowedPath | null {
  const found = pointsOf(motion.edit?.trajectory) ?? pointsOf(motion.plan?.trajectory);
  return found ? { motionId: motion.id, ...found } : null;
}

/** What the floor shows: the path being drawn or waiting for the next Generate when there is
 * one; else the path the motion on stage followed — while its motion (or a version of it, in
 * `versions`) is on stage and the toggle is on; else nothing. */
export function shownPath(
  pending: { person: number; points: Point[] },
  followed: FollowedPath | null,
  show: boolean,
  motionId: string | null,
  versions: readonly string[],
): { person: number; points: Point[]; followed: boolean } {
  if (pending.points.length > 0 || !followed || !show || !motionId) return { ...pending, followed: false };
  const onStage = followed.motionId === motionId || (versions.includes(followed.motionId) && versions.includes(motionId));
  return onStage ? { person: followed.person, points: followed.points, followed: true } : { ...pending, followed: false };
}
