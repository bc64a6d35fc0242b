import { afterEach, describe, expect, it, vi } from "vitest";
import { ApiError, createJob, errorMessage, exportUrl, motionIdFromPath, shareUrl } from "./client";

afterEach(() => vi.unstubAllGlobals());

describe("client", () => {
  it("reads FastAPI error details, plain or validation lists", () => {
    expect(errorMessage({ detail: "prompt must not be empty" }, 422)).toBe("prompt must not be empty");
    expect(
      errorMessage({ detail: [{ loc: ["body", "seconds"], msg: "Input should be less than or equal to 20" }] }, 422),
    ).toBe("seconds: Input should be less than or equal to 20");
    expect(errorMessage(null, 502)).toBe("request failed (HTTP 502)");
  });

  it("raises an ApiError with the server's detail", async () => {
    const fetch = vi.fn(async () => new Response(JSON.stringify({ detail: "prompt is empty" }), { status: 422 }));
    vi.stubGlobal("fetch", fetch);
    const err = await createJob({ prompt: "", persons: 1, seconds: 3 }).catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect(err).toMatchObject({ status: 422, message: "prompt is empty" });
    const [url, init] = fetch.mock.calls[0] as unknown as [string, RequestInit];
    expect(url).toBe("/api/jobs");
    expect(JSON.parse(String(init.body))).toEqual({ prompt: "", persons: 1, seconds: 3 });
  });

  it("builds share and export URLs and reads ids from paths", () => {
    expect(shareUrl("Ab_9-x", "http://h:1")).toBe("http://h:1/m/Ab_9-x");
    expect(exportUrl("id1", "bvh", 1)).toBe("/api/motions/id1/export?format=bvh&person=1");
    expect(exportUrl("id1", "json")).toBe("/api/motions/id1/export?format=json");
    expect(motionIdFromPath("/m/Ab_9-x")).toBe("Ab_9-x");
    expect(motionIdFromPath("/m/")).toBeNull();
    expect(motionIdFromPath("/m/a/b")).toBeNull();
    expect(motionIdFromPath("/")).toBeNull();
  });
});
