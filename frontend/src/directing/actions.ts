// Directing actions: apply an edit (body part, frame range, drawn path) to the current motion
// as a new version, move between versions (undo/redo), re-run a planned segment.
import { editMotion, getMotion, rerunSegment as rerunSegmentApi } from "../api/client";
import type { EditRequest, Motion } from "../api/types";
import { refreshLibrary } from "../library";
import { fail, generate, openMotion, showInUrl, showMotion, currentTrajectory } from "../studio";
import { frames, playhead, useStudio } from "../store";
import { keptPosition, type HeldPlayhead } from "../playback/keep";
import { canRedo, canUndo, current, pushVersion, redo as redoV, undo as undoV } from "./versions";

/** Where playback stands now (to keep it across a new version). */
function holdPlayhead(): HeldPlayhead {
  return { pos: playhead.pos, playing: useStudio.getState().playing };
}

/** Back to where playback stood, on the version now shown (an edit keeps the playhead). */
function restorePlayhead(held: HeldPlayhead): void {
  const pos = keptPosition(held.pos, frames.received);
  playhead.pos = pos;
  useStudio.setState({ frame: Math.floor(pos), playing: held.playing });
}

function randomSeed(): number {
  return Math.floor(Math.random() * 2 ** 31);
}

/** Make a new version of the current one (`make` answers it); it becomes the next version
 * (undo returns to this one) and plays. `label` says what is being done meanwhile. */
async function newVersion(make: (id: string) => Promise<Motion>, label: string | null = null): Promise<boolean> {
  const s = useStudio.getState();
  const id = current(s.versions) ?? s.motionId;
  if (!id || s.editing) return false;
  useStudio.setState({ editing: true, editLabel: label, error: null });
  try {
    const motion = await make(id);
    const held = holdPlayhead();
    showMotion(motion);
    restorePlayhead(held);
    useStudio.setState((st) => ({ versions: pushVersion(st.versions, motion.id) }));
    showInUrl(motion.id, "push");
    void refreshLibrary();
    return true;
  } catch (err) {
    fail(err);
    return false;
  } finally {
    useStudio.setState({ editing: false, editLabel: null });
  }
}

/** POST /edit on the current version; the answer becomes the next version and plays. */
export function applyEdit(req: EditRequest): Promise<boolean> {
  return newVersion((id) => editMotion(id, { seed: randomSeed(), ...req }));
}

/** Edit the selected part (or the whole body) with an instruction, over the selected range. */
export function applyPartEdit(prompt: string): Promise<boolean> {
  const { selected, range } = useStudio.getState();
  const req: EditRequest = { part: selected?.part ?? "whole_body", prompt };
  if (range) req.frames = range;
  return applyEdit(req);
}

/** Send the drawn path to /edit: the current motion follows it. */
export function applyPathToMotion(): Promise<boolean> {
  const trajectory = currentTrajectory();
  if (!trajectory) {
    useStudio.setState({ error: "draw a path first (at least two points)" });
    return Promise.resolve(false);
  }
  return applyEdit({ trajectory });
}

async function goTo(id: string | null): Promise<void> {
  if (!id) return;
  const held = holdPlayhead();
  await openMotion(id);
  if (useStudio.getState().motionId === id) restorePlayhead(held);
  showInUrl(id, "replace");
}

export async function undo(): Promise<void> {
  const v = useStudio.getState().versions;
  if (!canUndo(v) || useStudio.getState().editing) return;
  await goTo(current(undoV(v)));
}

export async function redo(): Promise<void> {
  const v = useStudio.getState().versions;
  if (!canRedo(v) || useStudio.getState().editing) return;
  await goTo(current(redoV(v)));
}

/** Re-run plan segment i of the current motion: (`job`) generated again with a new seed in
 * place — the other segments' frames stay, a new version (undo returns to this one) — or
 * (`inbetween`) an in-between edit of its frames. Without a stored motion (a failed job) the
 * segment's prompt becomes a new job. */
export async function rerunSegment(i: number, how: "job" | "inbetween"): Promise<void> {
  const { stream, seconds, motionPersons, motionId } = useStudio.getState();
  const seg = stream.plan?.segments[i];
  if (!seg) return;
  if (how === "inbetween") {
    await applyEdit({ part: "whole_body", prompt: seg.prompt, frames: [seg.start, seg.end] });
    return;
  }
  if (motionId && stream.phase === "done") {
    const n = stream.plan?.segments.length ?? 1;
    await newVersion((id) => rerunSegmentApi(id, i, randomSeed()), `Re-running segment ${i + 1} of ${n} with a new seed…`);
    return;
  }
  const persons = (motionPersons === 2 ? 2 : 1) as 1 | 2;
  const secs = Math.max(1, Math.min(20, Math.round((seg.end - seg.start) / 20) || seconds));
  await generate({ prompt: seg.prompt, persons, seconds: secs, seed: randomSeed() });
}

/** Reload the current version (after an error). */
export async function reload(): Promise<void> {
  const id = useStudio.getState().motionId;
  if (id) showMotion(await getMotion(id));
}
