// Display helpers for the panels.

export interface MetricRow {
  key: string;
  label: string;
  hint: string;
  /** Shown only for two-person motions. */
  pair?: boolean;
}

export const METRIC_ROWS: MetricRow[] = [
  { key: "intersection_volume", label: "Intersection volume (IV)", hint: "How much the two bodies overlap", pair: true },
  { key: "intersection_frequency", label: "Intersection frequency (IF)", hint: "Share of frames where the bodies overlap", pair: true },
  { key: "contact_frames", label: "Contact frames", hint: "Frames with hand or body contact between the two", pair: true },
  { key: "min_distance", label: "Closest distance", hint: "Smallest distance between the two people (m)", pair: true },
  { key: "foot_skating", label: "Foot skating", hint: "Feet sliding while on the ground" },
  { key: "bone_deviation", label: "Bone deviation", hint: "Change of bone lengths over the clip" },
  { key: "ground_penetration", label: "Ground penetration", hint: "How far joints sink below the floor" },
  { key: "floating", label: "Floating", hint: "How far the lowest joint hovers above the floor" },
];

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
