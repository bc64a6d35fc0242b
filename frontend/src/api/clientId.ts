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
