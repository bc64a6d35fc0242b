// This browser's client id: random, made once and kept in localStorage, sent with every job
// and edit (`X-Interplay-Client`) so that GET /api/motions?client=<id> lists what this browser
// made ("My motions"), in any tab, after a reload. It is never shown with a shared motion.
const KEY = "interplay-client";
/** The server's id shape (22–64 URL-safe characters). */
export const CLIENT_ID = /^[A-Za-z0-9_-]{22,64}$/;
export const CLIENT_HEADER = "X-Interplay-Client";

/** 16 random bytes as URL-safe base64 (22 characters, 128 bits), like the server's ids. */
export function newClientId(bytes: Uint8Array = crypto.getRandomValues(new Uint8Array(16))): string {
  let s = "";
  for (const b of bytes) s += String.fromCharCode(b);
  return btoa(s).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

let memo: string | null = null;

/** The id, made and stored on first use; without storage (private mode) one per page. */
export function clientId(storage: Pick<Storage, "getItem" | "setItem"> | null = safeStorage()): string {
  if (memo) return memo;
  let id: string | null = null;
  try {
    id = storage?.getItem(KEY) ?? null;
  } catch {
    id = null;
  }
  if (!id || !CLIENT_ID.test(id)) {
    id = newClientId();
    try {
      storage?.setItem(KEY, id);
    } catch {
      /* not kept: this page's motions are still listed while it is open */
    }
  }
  memo = id;
  return id;
}

/** Forget the memoised id (tests). */
export function resetClientId(): void {
  memo = null;
}

function safeStorage(): Storage | null {
  try {
    return typeof localStorage === "undefined" ? null : localStorage;
  } catch {
    return null;
  }
}

// Opening the same library in another browser: a link carrying the id (`/?library=<id>`).
// Whoever has the link lists (and adds to) that library, as with any bearer token; it is never
// part of a motion's share link.
const PREVIOUS_KEY = "interplay-client-previous";
export const LIBRARY_PARAM = "library";

/** The link that opens this library (`id`'s My motions) in another browser. */
export function libraryLink(id: string, origin: string): string {
  return `${origin}/?${LIBRARY_PARAM}=${encodeURIComponent(id)}`;
}

/** The library id a URL's query carries, or null (none, or not an id's shape). */
export function linkedLibrary(search: string): string | null {
  const id = new URLSearchParams(search).get(LIBRARY_PARAM);
  return id && CLIENT_ID.test(id) ? id : null;
}

/** Make `id` this browser's client id (kept in storage): its My motions is then that library,
 * and what this browser makes is added to it. The id it had before is kept aside (not lost);
 * answers it, or null when it was the same or there was none. */
export function adoptClientId(id: string, storage: Pick<Storage, "getItem" | "setItem"> | null = safeStorage()): string | null {
  if (!CLIENT_ID.test(id)) throw new Error(`not a client id: ${id}`);
  let before: string | null = memo;
  try {
    before ??= storage?.getItem(KEY) ?? null;
    if (before && before !== id) storage?.setItem(PREVIOUS_KEY, before);
    storage?.setItem(KEY, id);
  } catch {
    /* not kept: this page shows the library while it is open */
  }
  memo = id;
  return before && before !== id ? before : null;
}
