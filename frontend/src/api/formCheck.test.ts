// @vitest-environment node
import { describe, expect, it } from "vitest";
import { formProblems, plainError, promptLength } from "./formCheck";
import { DEFAULT_LIMITS } from "./limits";

const ok = { prompt: "a person walks", seconds: 4, persons: 1 };
const problems = (v: Partial<typeof ok>) => formProblems({ ...ok, ...v }, DEFAULT_LIMITS);

describe("formProblems", () => {
  it("lets a valid form go", () => {
    expect(problems({})).toEqual([]);
    expect(problems({ seconds: 1, persons: 2 })).toEqual([]);
    expect(problems({ seconds: 20, prompt: "x".repeat(500) })).toEqual([]);
  });

  it("blocks an empty prompt, or one of spaces only", () => {
    for (const prompt of ["", "   ", "\n\t"]) expect(problems({ prompt })).toEqual([{ field: "prompt", message: "Type what the people do first." }]);
  });

  it("says how far over the limit a long prompt is, counted as the server counts", () => {
    expect(problems({ prompt: "x".repeat(10_000) })).toEqual([
      { field: "prompt", message: "The prompt is 10,000 characters long; the limit is 500. Shorten it by 9,500." },
    ]);
    // runs of spaces count once (the server collapses them)
    expect(promptLength("  a   person\n walks ")).toBe(14);
    expect(problems({ prompt: "x ".repeat(250) + "   " })).toEqual([]);
  });

  it("keeps seconds within the API's range", () => {
    expect(problems({ seconds: 0 })[0].message).toBe("The length must be from 1 to 20 seconds; 0 is too short.");
    expect(problems({ seconds: -3 })[0].message).toBe("The length must be from 1 to 20 seconds; -3 is too short.");
    expect(problems({ seconds: 999 })[0].message).toBe("The length must be from 1 to 20 seconds; 999 is too long.");
    expect(problems({ seconds: NaN })[0]).toEqual({ field: "seconds", message: "Give the length in seconds, from 1 to 20." });
    expect(formProblems({ ...ok, seconds: 25 }, { ...DEFAULT_LIMITS, secondsMax: 30 })).toEqual([]);
  });

  it("keeps people within the schema's choices", () => {
    expect(problems({ persons: 3 })).toEqual([{ field: "persons", message: "A motion has 1 to 2 people." }]);
    expect(problems({ persons: 0 })[0].field).toBe("persons");
  });
});

describe("plainError", () => {
  it("turns the API's details into sentences naming the page's fields", () => {
    expect(plainError("seconds must be at most 20 (got 999)")).toBe("The length in seconds must be at most 20 (got 999).");
    expect(plainError("persons must be 1 or 2 (got 3); seconds must be at least 1 (got 0)")).toBe(
      "The number of people must be 1 or 2 (got 3). The length in seconds must be at least 1 (got 0).",
    );
    expect(plainError("prompt is 599 characters long; the limit is 500")).toBe("The prompt is 599 characters long; the limit is 500.");
    expect(plainError("trajectory: the drawn path is 600 m long; the limit is 200 m")).toBe("The path: the drawn path is 600 m long; the limit is 200 m.");
    expect(plainError("trajectory.points.1.0 must be a number (got true)")).toBe("The path's points must be a number (got true).");
  });

  it("rewords pydantic's raw validation text, whatever sends it", () => {
    expect(plainError("seconds: Input should be less than or equal to 20")).toBe("The length in seconds must be at most 20.");
    expect(plainError("plan: segments.0.count: Input should be less than or equal to 20")).toBe("Plan: segments.0.count must be at most 20.");
    expect(plainError("prompt: Value error, must not be empty")).toBe("The prompt must not be empty.");
  });

  it("ends and capitalises any other message, once", () => {
    expect(plainError("cannot reach the Interplay server")).toBe("Cannot reach the Interplay server.");
    expect(plainError("the count asked (21 claps) is more than the plan can hold.")).toBe("The count asked (21 claps) is more than the plan can hold.");
    expect(plainError("")).toBe("Something went wrong.");
  });
});
