import { afterEach, describe, expect, it } from "vitest";
import { CLIENT_ID, adoptClientId, clientId, libraryLink, linkedLibrary, newClientId, resetClientId } from "./clientId";

function memory(initial: Record<string, string> = {}) {
  const data = { ...initial };
  return {
    data,
    getItem: (k: string) => data[k] ?? null,
    setItem: (k: string, v: string) => {
      data[k] = v;
    },
  };
}

afterEach(() => resetClientId());

describe("clientId", () => {
  it("is 22 URL-safe characters of 16 random bytes, as the server's ids", () => {
    const id = newClientId(new Uint8Array(16).fill(255));
    expect(id).toBe("_____________________w");
    expect(CLIENT_ID.test(id)).toBe(true);
    expect(CLIENT_ID.test(newClientId())).toBe(true);
    expect(newClientId()).not.toBe(newClientId());
  });
  it("is made once and kept in storage", () => {
    const store = memory();
    const id = clientId(store);
    expect(store.data["interplay-client"]).toBe(id);
    resetClientId();
    expect(clientId(store)).toBe(id);
  });
  it("replaces a malformed stored id and works without storage", () => {
    const store = memory({ "interplay-client": "bad id" });
    const id = clientId(store);
    expect(CLIENT_ID.test(id) && id !== "bad id").toBe(true);
    resetClientId();
    const broken = { getItem: () => { throw new Error("denied"); }, setItem: () => { throw new Error("denied"); } };
    expect(CLIENT_ID.test(clientId(broken))).toBe(true);
    resetClientId();
    expect(CLIENT_ID.test(clientId(null))).toBe(true);
  });
});

describe("a library link", () => {
  it("carries the id, and only an id's shape is taken from a URL", () => {
    const id = "A".repeat(11) + "b".repeat(11);
    expect(libraryLink(id, "https://studio.example")).toBe(`https://studio.example/?library=${id}`);
    expect(linkedLibrary(`?library=${id}`)).toBe(id);
    expect(linkedLibrary(new URL(libraryLink(id, "http://x")).search)).toBe(id);
    expect(linkedLibrary("?library=short")).toBeNull();
    expect(linkedLibrary("?library=has%20spaces%20in%20it%20!!!!!!!")).toBeNull();
    expect(linkedLibrary("?job=x")).toBeNull();
  });

  it("adopting it makes it this browser's id and keeps the one before aside", () => {
    const store = memory();
    const mine = clientId(store);
    const theirs = "T".repeat(22);
    expect(adoptClientId(theirs, store)).toBe(mine);
    expect(clientId(store)).toBe(theirs);
    expect(store.data["interplay-client"]).toBe(theirs);
    expect(store.data["interplay-client-previous"]).toBe(mine);
    resetClientId();
    expect(clientId(store)).toBe(theirs); // kept across a reload
    expect(adoptClientId(theirs, store)).toBeNull(); // the same again: nothing set aside
    expect(() => adoptClientId("nope", store)).toThrow();
  });
});
