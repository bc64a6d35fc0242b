// UI state (zustand). Per-frame joint data is NOT here: it lives in the FrameBuffer `frames`
// and the fractional clock `playhead`, read by the render loop without React.
import { create } from "zustand";
import type { Skeleton } from "./api/types";
import { initialStream, type StreamState } from "./api/stream";
import { FrameBuffer } from "./playback/frameBuffer";

export const FPS = 20;

/** Joint positions and highlights of the current motion (plain arrays). */
export const frames = new FrameBuffer();
/** The playback clock: a fractional frame position, advanced by the render loop. */
export const playhead = { pos: 0 };
/** Counters the render loop keeps (read by the test hook). */
export const renderStats: { renders: number; quality: string } = { renders: 0, quality: "" };

export type Persons = 1 | 2;

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
}));
