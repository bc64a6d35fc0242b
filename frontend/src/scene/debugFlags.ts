// Profiling switches from the query string, to see what a rendered frame costs part by part:
// `?hide=ground,people,blobs,path` leaves scene parts out, `?pixelRatio=0.5` overrides the
// quality's pixel ratio. Nothing in the studio sets them; the perf notes in docs/studio.md do.

export interface DebugFlags {
  hide: Set<string>;
  pixelRatio: number | null;
}

export function debugFlags(search: string = typeof window === "undefined" ? "" : window.location.search): DebugFlags {
  const q = new URLSearchParams(search);
  const hide = new Set((q.get("hide") ?? "").split(",").map((s) => s.trim()).filter(Boolean));
  const pr = Number(q.get("pixelRatio"));
  return { hide, pixelRatio: Number.isFinite(pr) && pr > 0 && pr <= 4 ? pr : null };
}
