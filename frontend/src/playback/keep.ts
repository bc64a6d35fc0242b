// Where playback stands, kept across a change of motion that is the same take (an edit, a
// re-run, undo / redo between its versions): the playhead stays where it was — clamped into the
// new version's frames — and so does play / pause, instead of starting over near frame 0.

export interface HeldPlayhead {
  pos: number;
  playing: boolean;
}

/** The playhead position `pos` (fractional frames) on a motion of `frames` frames. */
export function keptPosition(pos: number, frames: number): number {
  if (!(frames > 0) || !Number.isFinite(pos)) return 0;
  return Math.min(Math.max(pos, 0), frames - 1);
}
