import { describe, expect, it } from "vitest";
import bandsFile from "./metricBands.json";
import { METRIC_ROWS, formatMetric, formatMetricValue, formatQuantity, metricBand, metricTitle, personName, type BandRule } from "./format";

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

const row = (key: string) => METRIC_ROWS.find((r) => r.key === key)!;
const BANDS = bandsFile.bands as Record<string, BandRule>;

describe("metrics for people", () => {
  it("shows values in units, never as exponents", () => {
    expect(formatMetricValue(row("bone_deviation"), 2.6e-19)).toBe("0 mm");
    expect(formatMetricValue(row("foot_skating"), 3.09e-3)).toBe("0.31 cm/s");
    expect(formatMetricValue(row("foot_skating"), 0.0483)).toBe("4.83 cm/s");
    expect(formatMetricValue(row("intersection_frequency"), 0.1125)).toBe("11.3 %");
    expect(formatMetricValue(row("min_distance"), -0.0466)).toBe("−4.66 cm");
    expect(formatMetricValue(row("intersection_volume"), 203.98)).toBe("204 cm³");
    expect(formatMetricValue(row("contact_frames"), 14)).toBe("14 frames (0.7 s)");
    expect(formatMetricValue(row("floating"), null)).toBe("—");
    expect(formatQuantity(1.5, 1)).toBe("1.5");
    for (const r of METRIC_ROWS) expect(r.hint.length, r.key).toBeGreaterThan(20);
  });

  it("bands a value against the real-capture range (less is better, or more for the closest distance)", () => {
    const lower: BandRule = { better: "lower", green: 0.1, amber: 0.3 };
    expect([0, 0.1, 0.2, 0.3, 0.31].map((v) => metricBand(v, lower))).toEqual(["green", "green", "amber", "amber", "red"]);
    const higher: BandRule = { better: "higher", green: -0.12, amber: -0.14 };
    expect([0.5, -0.12, -0.13, -0.2].map((v) => metricBand(v, higher))).toEqual(["green", "green", "amber", "red"]);
    expect(metricBand(null, lower)).toBeNull();
    expect(metricBand(1, undefined)).toBeNull();
  });

  it("has a committed band for every banded row, ordered green before amber", () => {
    for (const r of METRIC_ROWS) {
      const b = BANDS[r.key];
      if (r.key === "contact_frames") {
        expect(b).toBeUndefined(); // a count the prompt decides: no good or bad
        continue;
      }
      expect(b, r.key).toBeDefined();
      if (b.better === "lower") expect(b.amber).toBeGreaterThanOrEqual(b.green);
      else expect(b.amber).toBeLessThanOrEqual(b.green);
      expect(metricTitle(r, b)).toMatch(/Real motion captures: median .+; green/);
    }
    // generated bones do not stretch (FK): the 2.60e-19 is green, in millimetres
    expect(metricBand(2.6e-19, BANDS.bone_deviation)).toBe("green");
  });

  it("names people one way", () => {
    expect([personName(0), personName(1)]).toEqual(["Person 1", "Person 2"]);
  });
});
