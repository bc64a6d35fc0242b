// Undo/redo over a motion's versions: a linear list of ids (root → newest) and where we are.
// A new edit made from an older version drops the versions after it (as an editor's redo does).
export interface Versions {
  ids: string[];
  index: number;
}

export const noVersions: Versions = { ids: [], index: -1 };

export function current(v: Versions): string | null {
  return v.index >= 0 ? v.ids[v.index] : null;
}

/** After an edit of the current version made `id`. */
export function pushVersion(v: Versions, id: string): Versions {
  const ids = [...v.ids.slice(0, v.index + 1), id];
  return { ids, index: ids.length - 1 };
}

/** The history of an opened motion: its chain from the root, positioned at `id`. */
export function fromHistory(chain: string[], id: string): Versions {
  const ids = chain.includes(id) ? chain : [...chain, id];
  return { ids, index: ids.indexOf(id) };
}

/** Move to another version of the same chain, keeping later ones for redo. */
export function moveTo(v: Versions, id: string): Versions {
  const i = v.ids.indexOf(id);
  return i < 0 ? fromHistory([id], id) : { ids: v.ids, index: i };
}

export const canUndo = (v: Versions) => v.index > 0;
export const canRedo = (v: Versions) => v.index >= 0 && v.index < v.ids.length - 1;
export const undo = (v: Versions): Versions => (canUndo(v) ? { ...v, index: v.index - 1 } : v);
export const redo = (v: Versions): Versions => (canRedo(v) ? { ...v, index: v.index + 1 } : v);
