// Timeline maths: the playback clock is a fractional frame position advanced by wall time.
// While frames are still streaming the clock waits at the last frame received.

export const SPEEDS = [0.25, 0.5, 1, 1.5, 2] as const;

export interface ClockState {
  /** Fractional frame position. */
  pos: number;
  playing: boolean;
}

export interface ClockContext {
  fps: number;
  speed: number;
  loop: boolean;
  /** Frames playable now (the received prefix). */
  available: number;
  /** Frames the motion will have in all. */
  total: number;
}

export function advance(clock: ClockState, dt: number, ctx: ClockContext): ClockState {
  if (ctx.available <= 0) return { pos: 0, playing: clock.playing };
  if (!clock.playing) return { pos: Math.min(clock.pos, ctx.available - 1), playing: false };
  const pos = clock.pos + Math.max(0, dt) * ctx.fps * ctx.speed;
  const complete = ctx.available >= ctx.total;
  if (!complete) return { pos: Math.min(pos, ctx.available - 1), playing: true };
  const n = ctx.available;
  if (pos < n) return { pos, playing: true }; // frame floor(pos) is still inside the clip
  if (ctx.loop) return { pos: pos % n, playing: true };
  return { pos: n - 1, playing: false };
}

/** The frame to show for a clock position. */
export function frameIndex(pos: number, available: number): number {
  if (available <= 0) return 0;
  return Math.min(available - 1, Math.max(0, Math.floor(pos)));
}

/** What to draw at a clock position while playing: frame `frame` blended towards `next` by
 * `weight` (joints interpolated between the 20 fps samples, so a display's every refresh shows a
 * new pose). No blend past the last playable frame (nor across a loop's seam). */
export function blendAt(pos: number, available: number): { frame: number; next: number; weight: number } {
  const frame = frameIndex(pos, available);
  const next = Math.min(available - 1, frame + 1);
  const weight = next > frame ? Math.min(1, Math.max(0, pos - frame)) : 0;
  return { frame, next, weight };
}

/** Frame under a scrubber fraction in [0, 1] of a clip of `total` frames. */
export function scrubFrame(fraction: number, total: number): number {
  if (total <= 1) return 0;
  const f = Math.min(1, Math.max(0, fraction));
  return Math.round(f * (total - 1));
}

/** Seconds of a frame count, e.g. "2.35 s". */
export function formatSeconds(frames: number, fps: number): string {
  return `${(fps > 0 ? frames / fps : 0).toFixed(2)} s`;
}

/** Where a play press should start: from the top when the clip had played to its end. */
export function playFrom(pos: number, available: number, total: number): number {
  return available >= total && available > 0 && pos >= available - 1 ? 0 : pos;
}

/** Width (CSS px) of the scrubber's thumb (styles.css `--thumb`). A native range input puts
 * value 0 at half a thumb from its left edge and the last value half a thumb from its right,
 * so everything drawn along the timeline (segments, marks, playhead, the distance plot) is
 * inset by half a thumb on each side and shares this one mapping. */
export const THUMB_PX = 14;

/** Fraction in [0, 1] along the usable width for a frame of a clip of `total` frames. */
export function frameFraction(frame: number, total: number): number {
  if (total <= 1) return 0;
  return Math.min(1, Math.max(0, frame / (total - 1)));
}

/** Client x (px) of a frame on a scrubber whose box starts at `left` and is `width` wide. */
export function frameToX(frame: number, total: number, left: number, width: number, thumb = THUMB_PX): number {
  return left + thumb / 2 + frameFraction(frame, total) * Math.max(0, width - thumb);
}

/** The frame under client x on the same scrubber (nearest; clamped to the clip). */
export function xToFrame(x: number, total: number, left: number, width: number, thumb = THUMB_PX): number {
  const usable = width - thumb;
  if (total <= 1 || usable <= 0) return 0;
  return scrubFrame((x - left - thumb / 2) / usable, total);
}

/** CSS `left` of a frame inside the inset box (percent of its width). */
export function framePercent(frame: number, total: number): string {
  return `${100 * frameFraction(frame, total)}%`;
}
