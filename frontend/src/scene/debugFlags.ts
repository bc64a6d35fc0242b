// Profiling switches from the query string, to see what a rendered frame costs part by part:
// `?hide=ground,people,blobs,path` leaves scene parts out (`poses`: the bodies keep their first
// pose, so no vertex uploads), `?pixelRatio=0.5` overrides the
// quality's pixel ratio (and fixes it: no dynamic resolution), `?dynres=0` turns the light
// quality's dynamic resolution off, `?alpha=1` asks for a canvas with an alpha channel, `?tess=8x6,8,6x4,6` sets the body's tessellation (sphere,
// cylinder sides, thin pieces' sphere and sides; `?tess=old` the light quality's before the
// thin-piece shapes and welding), `?detail=full|light` the skinned character's mesh (light
// quality's default: light, lightBody.ts), `?skin=gpu|cpu` where it is skinned (light quality's
// default: cpu, figure.ts). Nothing in the studio sets them; the perf notes in
// docs/studio.md do.

export interface DebugFlags {
  hide: Set<string>;
  pixelRatio: number | null;
  dynamicResolution: boolean;
  alpha: boolean;
  /** Body tessellation override: "old", or [sphere w, h, cylinder sides, thin sphere w, h, thin sides]. */
  tess: "old" | number[] | null;
  /** The character's mesh: the full one or the light level of detail (null: by quality). */
  detail: "full" | "light" | null;
  /** Where the character is skinned (null: by quality). */
  skinning: "gpu" | "cpu" | null;
}

export function debugFlags(search: string = typeof window === "undefined" ? "" : window.location.search): DebugFlags {
  const q = new URLSearchParams(search);
  const hide = new Set((q.get("hide") ?? "").split(",").map((s) => s.trim()).filter(Boolean));
  const pr = Number(q.get("pixelRatio"));
  const pixelRatio = Number.isFinite(pr) && pr > 0 && pr <= 4 ? pr : null;
  const t = q.get("tess");
  const nums = (t ?? "").split(/[x,]/).map(Number);
  const tess = t === "old" ? "old" : nums.length === 6 && nums.every((n) => Number.isInteger(n) && n >= 2 && n <= 64) ? nums : null;
  const d = q.get("detail");
  const detail = d === "full" || d === "light" ? d : null;
  const k = q.get("skin");
  const skinning = k === "gpu" || k === "cpu" ? k : null;
  return { hide, pixelRatio, dynamicResolution: pixelRatio === null && q.get("dynres") !== "0", alpha: q.get("alpha") === "1", tess, detail, skinning };
}
