import { describe, expect, it } from "vitest";
import { formatMetric } from "./format";

describe("formatMetric", () => {
  it("shows about three significant digits, integers as they are, missing as a dash", () => {
    expect(formatMetric(9.173846682739349)).toBe("9.17");
    expect(formatMetric(0.08)).toBe("0.08");
    expect(formatMetric(181.4)).toBe("181");
    expect(formatMetric(72)).toBe("72");
    expect(formatMetric(-0.07708950941346739)).toBe("-0.0771");
    expect(formatMetric(2.2581847049489433e-8)).toBe("2.26e-8");
    expect(formatMetric(null)).toBe("—");
    expect(formatMetric(undefined)).toBe("—");
  });
});
