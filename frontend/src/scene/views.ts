// The viewport's preset views as the UI asks for them, and what the scene shows, outside React
// state: a button puts a request here, the render loop (Viewport.tsx) takes it at its next
// refresh and moves the camera once — after that the orbit controls are the user's alone. The
// loop writes back the camera and the penetration marks it drew, for the test hook.
import type { ViewPreset } from "./framing";

export const VIEW_PRESETS: { preset: ViewPreset; label: string; name: string; hint: string }[] = [
  { preset: "front", label: "Front", name: "Front view", hint: "Look at the people from their front" },
  { preset: "side", label: "Side", name: "Side view", hint: "Look at the people from the side (the front view's right)" },
  // (not "Top view": the path tool's own button is named so)
  { preset: "top", label: "Top", name: "Top-down view", hint: "Look straight down on the people" },
  { preset: "fit", label: "Frame both", name: "Frame both people", hint: "Keep this direction and fit everyone in the view" },
  { preset: "default", label: "Reset", name: "Reset view", hint: "Back to the opening view (two people: from the side of the line between them)" },
];

/** A preset asked for and not yet applied (null when none). */
export const viewRequest: { preset: ViewPreset | null } = { preset: null };

export function requestView(preset: ViewPreset): void {
  viewRequest.preset = preset;
}

/** What the scene shows now: the last view applied (and whether the user has orbited since),
 * the camera, and the penetration marks drawn at the pose shown ([x, y, z, radius, depth] ×
 * count in `marks`, a view of the stage's own buffer). */
export const viewStats: {
  view: ViewPreset | null;
  moved: boolean;
  position: [number, number, number];
  target: [number, number, number];
  markCount: number;
  marks: Float32Array | null;
} = { view: null, moved: false, position: [0, 0, 0], target: [0, 0, 0], markCount: 0, marks: null };
