// Which contact joints glow green at a frame. The stream's contacts are every foot on the floor
// and every wrist touching the other person; painting them all kept both feet green whenever a
// person stood, drowning the cue. A contact glows where it is asked — a hand touching the other
// person (what a prompt such as "shake hands" or "hug" asks for) — or new: a foot that came down
// within the last NEW_FRAMES frames (a landing, a step), not one planted since the clip began.

/** How long (frames, at 20 fps: 0.3 s) a foot glows after it comes down. */
export const NEW_FRAMES = 6;

/** The foot joints of the skeleton (SMPL's ankles and feet), whose contacts are the floor's. */
export function footJoints(joints: readonly string[]): Set<number> {
  return new Set(joints.flatMap((n, j) => (/^(left|right)_(ankle|foot)$/.test(n) ? [j] : [])));
}

type Frames = readonly (readonly (readonly [number, number])[] | undefined)[];

function touching(contacts: Frames, t: number, person: number, joint: number): boolean {
  const c = contacts[t];
  if (!c) return false;
  for (const [p, j] of c) if (p === person && j === joint) return true;
  return false;
}

/** Person `person`'s joints that glow at frame t: contacts of frame t that are asked (not a
 * foot: a hand on the other person) or new (a foot whose contact began after the first frame and
 * at most NEW_FRAMES − 1 frames ago). */
export function glowingContacts(contacts: Frames, t: number, person: number, feet: ReadonlySet<number>, fresh = NEW_FRAMES): Set<number> {
  const out = new Set<number>();
  for (const [p, j] of contacts[t] ?? []) {
    if (p !== person) continue;
    if (!feet.has(j)) {
      out.add(j); // asked: a hand touching the other person
      continue;
    }
    // new: the frame before the run began is within `fresh` frames and not before the clip
    let s = t;
    while (s > 0 && t - s < fresh && touching(contacts, s - 1, person, j)) s--;
    if (s > 0 && t - s < fresh) out.add(j);
  }
  return out;
}

/** What the stage painted at the last pose: per person, the glowing contact joints (for the
 * test hook). */
export const glowStats: { joints: number[][] } = { joints: [] };
