import { describe, expect, it } from "vitest";
import { intentKey, resumeFromSearch, resumeUrl } from "./intent";

describe("intentKey", () => {
  const base = { prompt: "a person walks forward", persons: 1 as const, seconds: 4 };
  it("is the same for the same request as the server reads it", () => {
    expect(intentKey({ ...base, prompt: "  a person   walks forward " })).toBe(intentKey(base));
  });
  it("differs when anything the job depends on differs", () => {
    const k = intentKey(base);
    expect(intentKey({ ...base, prompt: "a person runs" })).not.toBe(k);
    expect(intentKey({ ...base, persons: 2 })).not.toBe(k);
    expect(intentKey({ ...base, seconds: 5 })).not.toBe(k);
    expect(intentKey({ ...base, seed: 3 })).not.toBe(k);
    expect(intentKey({ ...base, trajectory: { person: 0, points: [[0, 0], [1, 1]] } })).not.toBe(k);
  });
});

describe("resume URL", () => {
  it("round-trips the job and its motion", () => {
    const url = resumeUrl("job_ABC-123", "mot_456");
    expect(url).toBe("/?job=job_ABC-123&motion=mot_456");
    expect(resumeFromSearch(url.slice(1))).toEqual({ job: "job_ABC-123", motion: "mot_456" });
    expect(resumeFromSearch("?job=j1")).toEqual({ job: "j1", motion: null });
  });
  it("ignores a missing or malformed job id", () => {
    expect(resumeFromSearch("")).toBeNull();
    expect(resumeFromSearch("?quality=light")).toBeNull();
    expect(resumeFromSearch("?job=%3Cscript%3E")).toBeNull();
    expect(resumeFromSearch("?job=ok&motion=../x")).toEqual({ job: "ok", motion: null });
  });
});
