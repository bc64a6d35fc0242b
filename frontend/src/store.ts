// UI state (zustand). Per-frame joint data is NOT here: it lives in the FrameBuffer `frames`
// and the fractional clock `playhead`, read by the render loop without React.
import { create } from "zustand";
import type { Skeleton } from "./api/types";
import { initialStream, type StreamState } from "./api/stream";
import { FrameBuffer } from "./playback/frameBuffer";
import type { EditInfo, EditPart } from "./api/types";
import type { Point, Preset } from "./directing/path";
import { noVersions, type Versions } from "./directing/versions";
import { DEFAULT_LIMITS, type Limits } from "./api/limits";

export const FPS = 20;

/** Joint positions and highlights of the current motion (plain arrays). */
export const frames = new FrameBuffer();
/** The playback clock: a fractional frame position, advanced by the render loop. */
export const playhead = { pos: 0 };
/** Counters the render loop keeps (read by the test hook). */
/** What the render loop reports: frames drawn, the quality, the render scale (pixel ratio) now. */
export const renderStats: { renders: number; quality: string; scale: number } = { renders: 0, quality: "", scale: 0 };

/** Pointer state the render loop reads (not React state): the part under the pointer, and the
 * points of a path being drawn right now (committed to the store on release). */
export const pointer: { hover: { person: number; part: EditPart } | null; drawing: Point[] | null; version: number } = {
  hover: null,
  drawing: null,
  version: 0,
};

/** Set by the viewport: where a world point appears on screen (client pixels), for the test hook. */
export const sceneProbe: { project: ((x: number, y: number, z: number) => [number, number]) | null; ground: ((cx: number, cy: number) => [number, number] | null) | null } = {
  project: null,
  ground: null,
};

export type Persons = 1 | 2;
export type Tool = "view" | "path" | "part";
export type Theme = "dark" | "light";

export interface PathState {
  person: 0 | 1;
  points: Point[];
  /** The preset it came from (regenerated when the size changes), or null for a drawn path. */
  preset: Preset | null;
  size: number;
}

const THEME_KEY = "interplay-theme";

function storedTheme(): Theme {
  try {
    return localStorage.getItem(THEME_KEY) === "light" ? "light" : "dark";
  } catch {
    return "dark";
  }
}

export interface StudioState {
  // the prompt form
  prompt: string;
  persons: Persons;
  seconds: number;
  // the current motion and its stream
  stream: StreamState;
  motionId: string | null;
  motionPersons: number;
  skeleton: Skeleton | null;
  error: string | null;
  // playback
  playing: boolean;
  speed: number;
  loop: boolean;
  /** The integer frame on screen (changes at most `FPS` × speed times a second). */
  frame: number;

  setPrompt(prompt: string): void;
  setPersons(persons: Persons): void;
  setSeconds(seconds: number): void;
  setError(error: string | null): void;
  setPlaying(playing: boolean): void;
  setSpeed(speed: number): void;
  setLoop(loop: boolean): void;
  seek(frame: number): void;

  // directing
  tool: Tool;
  path: PathState;
  selected: { person: number; part: EditPart } | null;
  /** A frame range [a, b) selected on the timeline (edits are limited to it). */
  range: [number, number] | null;
  editing: boolean;
  /** What made the version shown (its edit of the parent), or null for a generated motion. */
  edit: EditInfo | null;
  versions: Versions;
  theme: Theme;
  /** The shortcut sheet (`?`) is open. */
  shortcuts: boolean;
  /** Drawing a path looks straight down on the floor (on by default; a toggle in the toolbar). */
  topView: boolean;
  /** The request of the generation starting or running (its `intentKey`), so the same
   * request is not sent twice; null when none. */
  intent: { key: string; starting: boolean } | null;
  /** What the edit being applied is, for the progress ("Applying the edit…" when null). */
  editLabel: string | null;
  /** The seed the next Generate sends, or null for a random one. */
  seed: number | null;
  /** The request limits, read from the API's schema (/openapi.json) at start-up. */
  limits: Limits;
  setTool(tool: Tool): void;
  setPath(path: Partial<PathState>): void;
  select(sel: { person: number; part: EditPart } | null): void;
  setRange(range: [number, number] | null): void;
  setTheme(theme: Theme): void;
  setShortcuts(open: boolean): void;
  setTopView(on: boolean): void;
  setSeed(seed: number | null): void;
}

export const useStudio = create<StudioState>()((set) => ({
  prompt: "",
  persons: 1,
  seconds: 4,
  stream: initialStream,
  motionId: null,
  motionPersons: 0,
  skeleton: null,
  error: null,
  playing: true,
  speed: 1,
  loop: true,
  frame: 0,

  setPrompt: (prompt) => set({ prompt }),
  setPersons: (persons) => set({ persons }),
  setSeconds: (seconds) => set({ seconds }),
  setError: (error) => set({ error }),
  setPlaying: (playing) => set({ playing }),
  setSpeed: (speed) => set({ speed }),
  setLoop: (loop) => set({ loop }),
  seek: (frame) => {
    playhead.pos = frame;
    set({ frame });
  },

  tool: "view",
  path: { person: 0, points: [], preset: null, size: 3 },
  selected: null,
  range: null,
  editing: false,
  edit: null,
  versions: noVersions,
  theme: storedTheme(),
  shortcuts: false,
  topView: true,
  intent: null,
  editLabel: null,
  seed: null,
  limits: DEFAULT_LIMITS,
  setTool: (tool) => set((s) => ({ tool: s.tool === tool ? "view" : tool })),
  setPath: (path) => {
    pointer.version++;
    set((s) => ({ path: { ...s.path, ...path } }));
  },
  select: (selected) => set({ selected }),
  setRange: (range) => set({ range }),
  setTheme: (theme) => {
    try {
      localStorage.setItem(THEME_KEY, theme);
    } catch {
      /* private mode: not remembered */
    }
    set({ theme });
  },
  setShortcuts: (shortcuts) => set({ shortcuts }),
  setTopView: (topView) => set({ topView }),
  setSeed: (seed) => set({ seed }),
}));
