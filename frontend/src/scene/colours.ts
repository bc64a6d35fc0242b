// Body-part colouring: each bone takes the part of its child joint (skeleton.joint_part),
// each part its colour from GET /api/skeleton; the second person is a tinted variant.
import type { Skeleton } from "../api/types";

export const PERSON_TINT = "#fff1cc";
export const PERSON_TINT_AMOUNT = 0.45;
export const CONTACT_COLOUR = "#39ff88";
/** The marks where two people's bodies overlap (PenetrationMarks.ts) and on the timeline. */
export const PENETRATION_COLOUR = "#ff3b3b";

function parseHex(hex: string): [number, number, number] {
  const m = /^#?([0-9a-f]{6})$/i.exec(hex.trim());
  if (!m) throw new Error(`not a #rrggbb colour: ${hex}`);
  const v = parseInt(m[1], 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255];
}

function toHex([r, g, b]: [number, number, number]): string {
  return "#" + [r, g, b].map((c) => Math.round(c).toString(16).padStart(2, "0")).join("");
}

/** Linear mix of two #rrggbb colours: amount 0 → a, 1 → b. */
export function mixHex(a: string, b: string, amount: number): string {
  const ca = parseHex(a);
  const cb = parseHex(b);
  return toHex([0, 1, 2].map((i) => ca[i] + (cb[i] - ca[i]) * amount) as [number, number, number]);
}

/** Colour of a body part for a person (0: the part colour, 1: tinted towards PERSON_TINT). */
export function partColour(skeleton: Skeleton, part: string, person: number): string {
  const base = skeleton.colours[part];
  if (!base) throw new Error(`no colour for body part ${part}`);
  return person === 0 ? base : mixHex(base, PERSON_TINT, PERSON_TINT_AMOUNT);
}

/** Bones as [child, parent] joint pairs, one per non-root joint. */
export function bones(skeleton: Skeleton): [number, number][] {
  return skeleton.parents.flatMap((p, j) => (p >= 0 ? [[j, p] as [number, number]] : []));
}

/** Colour of each joint (and of the bone ending at it) for one person. */
export function jointColours(skeleton: Skeleton, person: number): string[] {
  return skeleton.joint_part.map((part) => partColour(skeleton, part, person));
}

/** Joints (bone ends) of a person in contact at one frame, from highlight [person, joint] pairs. */
export function contactJoints(contacts: [number, number][] | undefined, person: number): Set<number> {
  return new Set((contacts ?? []).filter(([p]) => p === person).map(([, j]) => j));
}
