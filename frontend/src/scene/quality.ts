// Render quality by WebGL implementation: a software rasteriser (SwiftShader, llvmpipe — no GPU,
// as in headless CI or a GPU-less machine) pays per triangle and per pixel on the CPU, so it
// gets the light settings: no MSAA, no shadow map (blob shadows instead), fewer pixels.

export type Quality = "full" | "light";

export interface QualitySettings {
  antialias: boolean;
  shadowMap: boolean;
  maxPixelRatio: number;
  /** Tessellation: capsule [cap segments, radial segments], sphere [width, height segments]. */
  capsule: [number, number];
  sphere: [number, number];
  /** Pieces thinner than `radius` (m; wrists, elbows, ankles, feet, neck, collars, shoulders):
   * a coarser cylinder (`radial` sides) and sphere. */
  small: { radius: number; radial: number; sphere: [number, number] };
  /** Share the vertices at the shapes' seams and poles (same look, fewer vertices). */
  weld: boolean;
  /** The floor grid as line segments (LineGround) rather than a per-pixel shader (Ground). */
  gridLines: boolean;
  /** Hold the display's rate by lowering / raising the pixel ratio (resolution.ts). */
  dynamicResolution: boolean;
}

export const QUALITY: Record<Quality, QualitySettings> = {
  full: { antialias: true, shadowMap: true, maxPixelRatio: 2, capsule: [4, 12], sphere: [16, 12], small: { radius: 0, radial: 12, sphere: [16, 12] }, weld: true, gridLines: false, dynamicResolution: false },
  light: { antialias: false, shadowMap: false, maxPixelRatio: 0.75, capsule: [2, 8], sphere: [8, 6], small: { radius: 0.055, radial: 6, sphere: [6, 4] }, weld: true, gridLines: true, dynamicResolution: true },
};

const SOFTWARE = /swiftshader|llvmpipe|softpipe|software|basic render/i;

/** Quality for a WebGL renderer string; `override` (e.g. from ?quality=) wins when valid. */
export function qualityFor(renderer: string, override?: string | null): Quality {
  if (override === "full" || override === "light") return override;
  return SOFTWARE.test(renderer) ? "light" : "full";
}

/** The WebGL renderer string of this browser (a throwaway context). */
export function rendererName(): string {
  const canvas = document.createElement("canvas");
  const gl = (canvas.getContext("webgl2") ?? canvas.getContext("webgl")) as WebGLRenderingContext | null;
  if (!gl) return "";
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER) ?? "");
  gl.getExtension("WEBGL_lose_context")?.loseContext();
  return name;
}

export function detectQuality(): Quality {
  return qualityFor(rendererName(), new URLSearchParams(window.location.search).get("quality"));
}
