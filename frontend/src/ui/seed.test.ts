import { describe, expect, it } from "vitest";
import { parseSeed, randomSeed } from "./SeedField";

describe("the seed field", () => {
  it("reads a whole number within the API's range, else none (a random seed)", () => {
    expect(parseSeed("1234", 2 ** 31 - 1)).toBe(1234);
    expect(parseSeed(" 0 ", 10)).toBe(0);
    for (const t of ["", "  ", "-1", "1.5", "1e3", "abc", "11"]) expect(parseSeed(t, 10), t).toBeNull();
  });

  it("picks new seeds inside [0, max]", () => {
    expect(randomSeed(10, () => 0)).toBe(0);
    expect(randomSeed(10, () => 0.9999999)).toBe(10);
    for (let i = 0; i < 100; i++) {
      const s = randomSeed(2 ** 31 - 1);
      expect(Number.isInteger(s) && s >= 0 && s <= 2 ** 31 - 1).toBe(true);
    }
  });
});
