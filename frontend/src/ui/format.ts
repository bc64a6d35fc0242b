// Display helpers for the panels.

/** The one name of a person everywhere in the UI: index 0 → "Person 1", 1 → "Person 2" (file
 * names say person1 / person2; the API numbers people from 0). */
export function personName(index: number): string {
  return `Person ${index + 1}`;
}

export interface MetricRow {
  key: string;
  label: string;
  /** What it measures, in a sentence (the row's hover text). */
  hint: string;
  /** The unit shown and the factor from the API's value (metres, m/s, shares, cm³, frames). */
  unit: string;
  scale: number;
  /** Shown only for two-person motions. */
  pair?: boolean;
}

export const METRIC_ROWS: MetricRow[] = [
  { key: "intersection_volume", label: "Body overlap (IV)", unit: "cm³", scale: 1, pair: true, hint: "How much the two bodies overlap: volume inside both, per frame on average (ARFlow's intersection volume)" },
  { key: "intersection_frequency", label: "Overlap frames (IF)", unit: "%", scale: 100, pair: true, hint: "Share of frames in which the two bodies overlap at all (ARFlow's intersection frequency)" },
  { key: "contact_frames", label: "Contact frames", unit: "frames", scale: 1, pair: true, hint: "Frames in which a hand touches the other person (within 3 cm of their body)" },
  { key: "min_distance", label: "Closest distance", unit: "cm", scale: 100, pair: true, hint: "Smallest gap between the two bodies over the clip; below zero they are inside each other" },
  { key: "foot_skating", label: "Foot skating", unit: "cm/s", scale: 100, hint: "How fast feet slide while planted on the floor (mean horizontal speed of a foot joint in ground contact)" },
  { key: "skating_ratio", label: "Skating frames", unit: "%", scale: 100, hint: "Share of frames in which a planted foot slides faster than 0.5 m/s" },
  { key: "bone_deviation", label: "Bone stretch", unit: "mm", scale: 1000, hint: "How much bone lengths change over the clip (mean difference from each bone's usual length)" },
  { key: "ground_penetration", label: "Below the floor", unit: "mm", scale: 1000, hint: "How deep the lowest joint sinks below the floor, on average" },
  { key: "floating", label: "Floating", unit: "cm", scale: 100, hint: "How high the lowest joint hovers above the floor in frames with no foot on the ground" },
];

export type Band = "green" | "amber" | "red";

export interface BandRule {
  better: "lower" | "higher";
  /** Green up to (lower is better) or from (higher is better) this value; amber to `amber`. */
  green: number;
  amber: number;
  /** The real captures' median (for the hover text). */
  p50?: number;
}

/** Which band a value falls in, or null without a rule or a value. */
export function metricBand(value: number | null | undefined, rule: BandRule | undefined): Band | null {
  if (value === null || value === undefined || !Number.isFinite(value) || !rule) return null;
  if (rule.better === "lower") return value <= rule.green ? "green" : value <= rule.amber ? "amber" : "red";
  return value >= rule.green ? "green" : value >= rule.amber ? "amber" : "red";
}

export const BAND_WORDS: Record<Band, string> = {
  green: "like real motion capture",
  amber: "worse than 9 in 10 real captures",
  red: "worse than 99 in 100 real captures",
};

/** A number in a display unit: at most three significant digits and two decimals, no
 * exponent; what rounds to nothing shows as 0 ("2.6e-19 m" of bone stretch is "0 mm"). */
export function formatQuantity(value: number | null | undefined, scale = 1): string {
  if (value === undefined || value === null || !Number.isFinite(value)) return "—";
  const v = value * scale;
  const abs = Math.abs(v);
  if (abs < 0.005) return "0";
  const digits = abs >= 100 ? 0 : abs >= 10 ? 1 : 2;
  return v.toFixed(digits).replace(/\.0+$/, "").replace(/(\.\d*?)0+$/, "$1").replace("-", "−");
}

/** A metric row's value with its unit, e.g. "4.8 cm/s", "12 %", "14 frames (0.7 s)". */
export function formatMetricValue(row: MetricRow, value: number | null | undefined, fps = 20): string {
  const q = formatQuantity(value, row.scale);
  if (q === "—") return q;
  if (row.unit === "frames") return `${q} frames (${((value ?? 0) / fps).toFixed(1)} s)`;
  return `${q} ${row.unit}`;
}

/** The hover text: what the metric is, and the bands from the real captures, in its unit. */
export function metricTitle(row: MetricRow, rule: BandRule | undefined): string {
  if (!rule) return `${row.hint}.`;
  const f = (x: number | undefined) => (x === undefined ? "?" : `${formatQuantity(x, row.scale)} ${row.unit}`);
  const bands =
    rule.better === "lower"
      ? `green up to ${f(rule.green)}, amber up to ${f(rule.amber)}, red above`
      : `green from ${f(rule.green)} up, amber from ${f(rule.amber)}, red below`;
  return `${row.hint}. Real motion captures: median ${f(rule.p50)}; ${bands}.`;
}

/** A metric value with about three significant digits; integers stay integers. */
export function formatMetric(value: number | undefined | null): string {
  if (value === undefined || value === null || Number.isNaN(value)) return "—";
  if (Number.isInteger(value)) return String(value);
  const abs = Math.abs(value);
  if (abs === 0) return "0";
  if (abs >= 100) return value.toFixed(0);
  if (abs >= 0.01) return value.toPrecision(3).replace(/\.?0+$/, "");
  return value.toExponential(2);
}
