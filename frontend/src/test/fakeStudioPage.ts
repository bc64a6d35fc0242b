// The fake browser page the studio's unit tests run it in (studio.test.ts, studio.resume.test.ts):
// a `window` with a history that keeps its URL, the WebSocket class as FakeSocket (a test
// sends the stream's events itself), and the studio module loaded fresh for each test. Each test
// file stubs `fetch` itself: that is its own server.
import { vi } from "vitest";

/** A job stream as the page opens it: every socket opened is in `FakeSocket.opened`. */
export class FakeSocket {
  static opened: FakeSocket[] = [];
  onmessage: ((m: { data: string }) => void) | null = null;
  onerror: (() => void) | null = null;
  onclose: ((e: { code: number; reason: string }) => void) | null = null;
  /** The page closed it. */
  closed = false;
  constructor(readonly url: string) {
    FakeSocket.opened.push(this);
  }
  /** The server sends one event. */
  send(ev: object) {
    this.onmessage?.({ data: JSON.stringify(ev) });
  }
  /** The connection drops (the server went away): no close frame. */
  drop() {
    this.onerror?.();
    this.onclose?.({ code: 1006, reason: "" });
  }
  close() {
    this.closed = true;
  }
}

/** Before each test: a page at "/" (history.pushState / replaceState are spies that move its
 * URL; location reads it) whose WebSocket is FakeSocket, with no socket opened yet. */
export function stubPage(): void {
  FakeSocket.opened = [];
  const history = {
    url: "/",
    pushState: vi.fn((_s: unknown, _t: string, url: string) => (history.url = url)),
    replaceState: vi.fn((_s: unknown, _t: string, url: string) => (history.url = url)),
  };
  vi.stubGlobal("window", {
    history,
    location: {
      get pathname() {
        return history.url.split("?")[0];
      },
      get search() {
        const i = history.url.indexOf("?");
        return i < 0 ? "" : history.url.slice(i);
      },
      protocol: "http:",
      host: "studio",
    },
    addEventListener: () => undefined,
    // the page's timers are the test's (fake ones where a test uses them)
    setTimeout: (f: () => void, ms: number) => setTimeout(f, ms),
  });
  vi.stubGlobal("WebSocket", FakeSocket);
}

/** After each test: the real globals back, and the next test's studio loaded from scratch. */
export function unstubPage(): void {
  vi.unstubAllGlobals();
  vi.resetModules();
}

/** The studio (src/studio.ts) and its store, fresh, with the form filled: a one-person 2 s
 * "a person walks forward". */
export async function loadStudio() {
  const mod = await import("../studio");
  const { useStudio } = await import("../store");
  useStudio.setState({ prompt: "a person walks forward", persons: 1, seconds: 2 });
  return { ...mod, useStudio };
}
