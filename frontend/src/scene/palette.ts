// The stage's colours per UI theme: the background, the floor grid and the light bouncing off
// the floor (the hemisphere light's ground colour). Dark is the studio's original look; light
// lifts the whole viewport to match the light panels. Colours are display (sRGB) values.
export type StageTheme = "dark" | "light";

export interface StagePalette {
  /** What the canvas clears to (and where the full-quality floor fades to). */
  background: string;
  /** The floor (light quality draws no floor plane: the background is the floor). */
  floor: string;
  minor: string;
  major: string;
  /** Hemisphere light: sky and the floor's bounce. */
  sky: string;
  bounce: string;
}

export const PALETTES: Record<StageTheme, StagePalette> = {
  dark: { background: "#14161b", floor: "#181b22", minor: "#252a34", major: "#363e4e", sky: "#dbe6ff", bounce: "#2b2f38" },
  light: { background: "#dfe3ea", floor: "#e6e9ef", minor: "#cdd2db", major: "#aab2c0", sky: "#f2f5ff", bounce: "#b9bfca" },
};

/** Relative luminance (WCAG) of a #rrggbb colour, for tests and contrast checks. */
export function luminance(hex: string): number {
  const v = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255).map((c) => (c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4));
  return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
}
