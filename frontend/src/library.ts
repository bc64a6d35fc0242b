// "My motions": the motions this browser made (GET /api/motions?client=…), newest first, from
// the server, so the list survives a reload and is the same in every tab. Its own small store
// (the list, whether the panel is open, a notice such as "that generation is gone").
import { create } from "zustand";
import { listMotions } from "./api/client";
import type { MotionListItem } from "./api/types";

export const LIBRARY_LIMIT = 20;

export interface LibraryState {
  items: MotionListItem[];
  loaded: boolean;
  loading: boolean;
  error: string | null;
  open: boolean;
  /** A message shown at the top of the panel (e.g. a job that no longer exists). */
  notice: string | null;
  setOpen(open: boolean): void;
}

export const useLibrary = create<LibraryState>()((set) => ({
  items: [],
  loaded: false,
  loading: false,
  error: null,
  open: true,
  notice: null,
  setOpen: (open) => set({ open }),
}));

let inFlight: Promise<void> | null = null;
let again = false;

/** Fetch the list again (coalesced: a refresh asked while one runs runs once after it). */
export function refreshLibrary(): Promise<void> {
  if (inFlight) {
    again = true;
    return inFlight;
  }
  useLibrary.setState({ loading: true });
  inFlight = (async () => {
    try {
      do {
        again = false;
        const items = await listMotions(LIBRARY_LIMIT);
        useLibrary.setState({ items, loaded: true, error: null });
      } while (again);
    } catch (err) {
      useLibrary.setState({ error: err instanceof Error ? err.message : String(err) });
    } finally {
      useLibrary.setState({ loading: false });
      inFlight = null;
    }
  })();
  return inFlight;
}

/** Open the panel with a notice (and a fresh list). */
export function showLibrary(notice: string | null = null): void {
  useLibrary.setState({ open: true, notice });
  void refreshLibrary();
}

/** Keep the list fresh when the tab comes back (another tab may have made motions). */
export function watchLibrary(target: Document = document): void {
  target.addEventListener("visibilitychange", () => {
    if (target.visibilityState === "visible") void refreshLibrary();
  });
}
