// What the people are drawn as: the part-coloured mannequin (default) or the skinned character
// (the GLB export's mesh). The choice is UI state (zustand, remembered in localStorage;
// `?figure=character|mannequin` overrides it for one page without storing it). The character's
// data — the humanoid template and the current motion's rig from the JSON export (the server's
// rotation solver) — are plain objects the render loop reads. A motion still streaming has no
// rotations yet: the mannequin stands in until it is stored.
import { create } from "zustand";
import { exportUrl } from "./api/client";
import { parseRig, type MotionRig } from "./playback/rig";
import type { Skeleton } from "./api/types";
import type { Character } from "./scene/Character";
import type { QualitySettings } from "./scene/quality";
import { debugFlags } from "./scene/debugFlags";
import { renderStats, useStudio } from "./store";

export type Figure = "mannequin" | "character";
/** off: the mannequin is chosen; empty: nothing on stage; waiting: a motion is streaming (no
 * rotations until it is stored); loading: the mesh or the rig is on its way; ready: shown. */
export type FigureStatus = "off" | "empty" | "waiting" | "loading" | "ready" | "error";

const KEY = "interplay-figure";

/** The figure a page starts with: `?figure=` when valid, else the remembered one. */
export function initialFigure(search: string, stored: string | null): Figure {
  const q = new URLSearchParams(search).get("figure");
  if (q === "character" || q === "mannequin") return q;
  return stored === "character" ? "character" : "mannequin";
}

function stored(): string | null {
  try {
    return localStorage.getItem(KEY);
  } catch {
    return null;
  }
}

interface FigureState {
  figure: Figure;
  status: FigureStatus;
  error: string | null;
  setFigure(figure: Figure): void;
}

export const useFigure = create<FigureState>()((set) => ({
  figure: initialFigure(typeof window === "undefined" ? "" : window.location.search, stored()),
  status: "off",
  error: null,
  setFigure: (figure) => {
    try {
      localStorage.setItem(KEY, figure);
    } catch {
      /* private mode: not remembered */
    }
    set({ figure });
  },
}));

/** Makes a person's character from the loaded template (scene/Character.ts, loaded on demand:
 * GLTFLoader and the mesh cost a page that shows the mannequin nothing). */
export type CharacterMaker = (skeleton: Skeleton, person: number, offsets: ArrayLike<number>, quality: QualitySettings) => Character;

/** Whether the character skins on the CPU: in light quality (software WebGL), where the
 * vertex shader's bone texture reads cost more than skinning ~1,700 vertices in JS
 * (docs/studio.md); `?skin=gpu|cpu` chooses for profiling. */
export function cpuSkinning(quality: string, flag: "gpu" | "cpu" | null): boolean {
  return (flag ?? (quality === "light" ? "cpu" : "gpu")) === "cpu";
}

/** Read by the render loop: the maker once the mesh is loaded, the rig of the motion on stage. */
export const figureData: { make: CharacterMaker | null; rig: MotionRig | null } = { make: null, rig: null };

async function loadMaker(): Promise<CharacterMaker> {
  const { Character, loadHumanoid } = await import("./scene/Character");
  // light quality (software WebGL, set by the viewport before it watches): the lighter body
  const flags = debugFlags();
  const template = await loadHumanoid((flags.detail ?? renderStats.quality) === "light");
  const cpu = cpuSkinning(renderStats.quality, flags.skinning);
  return (skeleton, person, offsets, quality) => new Character(template, skeleton, person, offsets, quality, cpu);
}
/** Written by the render loop (for the test hook): what is drawn now, how many characters. */
export const figureStats: { shown: Figure; characters: number } = { shown: "mannequin", characters: 0 };

let templateLoading = false;
let templateFailed: string | null = null;
let rigLoading: string | null = null;
let rigFailed: { id: string; why: string } | null = null;

function setStatus(status: FigureStatus, error: string | null = null): void {
  const s = useFigure.getState();
  if (s.status !== status || s.error !== error) useFigure.setState({ status, error });
}

function reason(err: unknown): string {
  return err instanceof Error ? err.message : String(err);
}

/** The rig of a stored motion, from its version-2 JSON export. */
export async function fetchRig(motionId: string): Promise<MotionRig> {
  const res = await fetch(exportUrl(motionId, "json"));
  if (!res.ok) throw new Error(`HTTP ${res.status}`);
  return parseRig(motionId, await res.json());
}

/** Bring the character's data in step with the studio (cheap when nothing changed). */
function sync(): void {
  if (useFigure.getState().figure !== "character") return setStatus("off");
  if (templateFailed) return setStatus("error", `the character's mesh did not load (${templateFailed})`);
  if (!figureData.make && !templateLoading) {
    templateLoading = true;
    loadMaker().then(
      (make) => {
        figureData.make = make;
        templateLoading = false;
        sync();
      },
      (err: unknown) => {
        templateLoading = false;
        templateFailed = reason(err);
        sync();
      },
    );
  }
  const s = useStudio.getState();
  const id = s.stream.phase === "done" ? s.motionId : null;
  if (!id) return setStatus(s.stream.phase === "connecting" || s.stream.phase === "generating" ? "waiting" : "empty");
  if (rigFailed?.id === id) return setStatus("error", `the motion's rotations did not load (${rigFailed.why})`);
  if (figureData.rig?.motionId === id) return setStatus(figureData.make ? "ready" : "loading");
  setStatus("loading");
  if (rigLoading === id) return;
  rigLoading = id;
  fetchRig(id).then(
    (rig) => {
      if (rigLoading !== id) return; // another motion since
      rigLoading = null;
      figureData.rig = rig;
      sync();
    },
    (err: unknown) => {
      if (rigLoading !== id) return;
      rigLoading = null;
      rigFailed = { id, why: reason(err) };
      sync();
    },
  );
}

/** Follow the studio and the figure choice (the viewport calls it once); returns the stop. */
export function watchFigure(): () => void {
  const stops = [
    useStudio.subscribe(() => sync()),
    useFigure.subscribe((s, prev) => {
      if (s.figure === prev.figure) return;
      templateFailed = null; // choosing again tries a failed load again
      rigFailed = null;
      sync();
    }),
  ];
  sync();
  return () => stops.forEach((stop) => stop());
}
