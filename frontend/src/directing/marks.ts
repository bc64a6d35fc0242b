// Timeline marks: runs of consecutive frames with penetration or contact between the people,
// one mark per run (click it to jump to its first frame).
export interface Mark {
  kind: "penetration" | "contact";
  start: number;
  end: number; // exclusive
}

/** Runs of frames where `has(frame)` holds. */
export function runs(n: number, has: (t: number) => boolean): [number, number][] {
  const out: [number, number][] = [];
  let start = -1;
  for (let t = 0; t <= n; t++) {
    const on = t < n && has(t);
    if (on && start < 0) start = t;
    if (!on && start >= 0) {
      out.push([start, t]);
      start = -1;
    }
  }
  return out;
}

/** Marks from per-frame highlights. Contacts count only between the two people (a contact
 * joint of person p while the other person is also touching), not feet on the floor: a frame
 * is a contact frame when both people have a contact joint and min_distance is under 5 cm. */
export function timelineMarks(
  n: number,
  penetration: ([number, string][] | undefined)[],
  contacts: ([number, number][] | undefined)[],
  minDistance: (number | undefined)[],
  persons: number,
): Mark[] {
  if (persons < 2) return [];
  const pen = runs(n, (t) => (penetration[t]?.length ?? 0) > 0).map(([s, e]) => ({ kind: "penetration" as const, start: s, end: e }));
  const touch = runs(n, (t) => {
    const d = minDistance[t];
    const c = contacts[t] ?? [];
    return d !== undefined && d < 0.05 && c.some(([p]) => p === 0) && c.some(([p]) => p === 1) && !(penetration[t]?.length);
  }).map(([s, e]) => ({ kind: "contact" as const, start: s, end: e }));
  return [...pen, ...touch].sort((a, b) => a.start - b.start);
}
