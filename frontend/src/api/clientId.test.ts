import { afterEach, describe, expect, it } from "vitest";
import { CLIENT_ID, clientId, newClientId, resetClientId } from "./clientId";

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
