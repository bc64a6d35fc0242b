// "My motions": the motions this browser made (GET /api/motions?client=…), newest first, from
// the server, so the list survives a reload and is the same in every tab. Every motion stored
// for the client can be reached: the list shows a page at a time ("Show more" loads the next,
// "n of N" says how many there are), never a silent cap. A link (`/?library=<client id>`)
// opens the same library in another browser. Its own small store (the list, whether the panel
// is open, a notice such as "that generation is gone").
import { create } from "zustand";
import { listMotionPage } from "./api/client";
import { adoptClientId, clientId, libraryLink, linkedLibrary, LIBRARY_PARAM } from "./api/clientId";
import type { MotionListItem, MotionPage } from "./api/types";

/** Motions a page (the API's `limit`, at most 50). */
export const LIBRARY_PAGE = 20;
/** The API's largest page. */
const MAX_PAGE = 50;

export interface LibraryState {
  items: MotionListItem[];
  /** The cursor of the page after the last shown (null: everything is shown). */
  next: string | null;
  /** How many motions the library holds in all. */
  total: number;
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
  next: null,
  total: 0,
  loaded: false,
  loading: false,
  error: null,
  open: true,
  notice: null,
  setOpen: (open) => set({ open }),
}));

/** `page` appended to `items` (a motion already listed is not listed twice). */
export function appendPage(items: MotionListItem[], page: MotionPage): MotionListItem[] {
  const seen = new Set(items.map((m) => m.id));
  return [...items, ...page.motions.filter((m) => !seen.has(m.id))];
}

/** Pages from the first until at least `want` motions are listed (or there are no more):
 * a refresh keeps as many shown as before. `fetchPage(limit, after)` answers one page. */
export async function loadPages(
  want: number,
  fetchPage: (limit: number, after: string | null) => Promise<MotionPage>,
): Promise<{ items: MotionListItem[]; next: string | null; total: number }> {
  let items: MotionListItem[] = [];
  let next: string | null = null;
  let total = 0;
  do {
    const page = await fetchPage(Math.min(MAX_PAGE, Math.max(LIBRARY_PAGE, want - items.length)), next);
    items = appendPage(items, page);
    next = page.next;
    total = page.total;
  } while (next && items.length < want);
  return { items, next, total };
}

let inFlight: Promise<void> | null = null;
let again = false;

/** Fetch the list again, as many motions as are shown (coalesced: a refresh asked while one
 * runs runs once after it). */
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
        const page = await loadPages(Math.max(LIBRARY_PAGE, useLibrary.getState().items.length), listMotionPage);
        useLibrary.setState({ ...page, loaded: true, error: null });
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

/** The next page, after those shown ("Show more"). */
export async function loadMore(): Promise<void> {
  const { next, loading } = useLibrary.getState();
  if (!next || loading || inFlight) return;
  useLibrary.setState({ loading: true });
  try {
    const page = await listMotionPage(LIBRARY_PAGE, next);
    useLibrary.setState((s) => ({ items: appendPage(s.items, page), next: page.next, total: page.total, error: null }));
  } catch (err) {
    useLibrary.setState({ error: err instanceof Error ? err.message : String(err) });
  } finally {
    useLibrary.setState({ loading: false });
  }
}

/** The link that opens this library in another browser. */
export function thisLibraryLink(origin: string = window.location.origin): string {
  return libraryLink(clientId(), origin);
}

/** A page opened with a library link (`/?library=<id>`): that library becomes this browser's
 * (its My motions, and where what it makes is listed), the parameter leaves the address bar and
 * the panel says so. Before the first render (the list must not load the old one first). */
export function adoptLinkedLibrary(win: Window = window): boolean {
  const id = linkedLibrary(win.location.search);
  if (!id) return false;
  const mine = clientId() === id;
  const before = adoptClientId(id);
  const url = new URL(win.location.href);
  url.searchParams.delete(LIBRARY_PARAM);
  win.history.replaceState(win.history.state, "", url.pathname + url.search + url.hash);
  useLibrary.setState({
    open: true,
    notice: mine
      ? "This link is this browser's own library."
      : `This browser now shows the library from the link; what you make here is added to it.${before ? " Its own list is kept aside." : ""}`,
  });
  return true;
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
