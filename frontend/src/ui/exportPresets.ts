/** The export presets the API takes (GET /api/motions/{id}/export): frame rate, units and joint
 * names for BVH and GLB, the up axis for BVH only. Defaults are left out of the URL, so a
 * download without presets is the plain one. */
export const FPS_CHOICES = [20, 24, 30, 60] as const;
export type Presets = {
  fps: (typeof FPS_CHOICES)[number];
  units: "m" | "cm";
  names: "smpl" | "mixamo";
  up: "y" | "z";
};
export const DEFAULT_PRESETS: Presets = { fps: 20, units: "m", names: "smpl", up: "y" };

/** url (an export URL with its query) with the presets that apply to its format added. */
export function withPresets(url: string, format: "bvh" | "glb" | "json", p: Presets): string {
  if (format === "json") return url;
  const [path, query = ""] = url.split("?");
  const q = new URLSearchParams(query);
  if (p.fps !== DEFAULT_PRESETS.fps) q.set("fps", String(p.fps));
  if (p.units !== DEFAULT_PRESETS.units) q.set("units", p.units);
  if (p.names !== DEFAULT_PRESETS.names) q.set("names", p.names);
  if (format === "bvh" && p.up !== DEFAULT_PRESETS.up) q.set("up", p.up);
  return `${path}?${q}`;
}

/** A short description of the presets for the buttons' titles ("24 fps, cm, Mixamo names"). */
export function describePresets(p: Presets, format: "bvh" | "glb"): string {
  const parts = [`${p.fps} fps`, p.units, p.names === "mixamo" ? "Mixamo names" : "SMPL names"];
  if (format === "bvh") parts.push(`${p.up.toUpperCase()} up`);
  return parts.join(", ");
}
