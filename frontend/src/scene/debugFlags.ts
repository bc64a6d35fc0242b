// Profiling switches from the query string, to see what a rendered frame costs part by part:
// `?hide=ground,people,blobs,path` leaves scene parts out, `?pixelRatio=0.5` overrides the
// quality's pixel ratio (and fixes it: no dynamic resolution), `?dynres=0` turns the light
// quality's dynamic resolution off, `?alpha=1` asks for a canvas with an alpha channel. Nothing in the studio sets them; the perf notes in docs/studio.md do.

export interface DebugFlags {
  hide: Set<string>;
  pixelRatio: number | null;
  dynamicResolution: boolean;
  alpha: boolean;
}

export function debugFlags(search: string = typeof window === "undefined" ? "" : window.location.search): DebugFlags {
  const q = new URLSearchParams(search);
  const hide = new Set((q.get("hide") ?? "").split(",").map((s) => s.trim()).filter(Boolean));
  const pr = Number(q.get("pixelRatio"));
  const pixelRatio = Number.isFinite(pr) && pr > 0 && pr <= 4 ? pr : null;
  return { hide, pixelRatio, dynamicResolution: pixelRatio === null && q.get("dynres") !== "0", alpha: q.get("alpha") === "1" };
}
