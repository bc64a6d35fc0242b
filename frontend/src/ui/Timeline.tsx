import { useShallow } from "zustand/react/shallow";
import { SPEEDS, formatSeconds, playFrom } from "../playback/timeline";
import { FPS, frames, playhead, useStudio } from "../store";
import { TimelineTrack } from "./TimelineTrack";

/** Play/pause, the track (segments, marks, playhead) over the scrubber in one lane (one pixel
 * mapping: playback/timeline.ts `frameToX`), speed, loop and the frame counter. */
export function Timeline() {
  const s = useStudio(
    useShallow((s) => ({
      frame: s.frame,
      playing: s.playing,
      speed: s.speed,
      loop: s.loop,
      received: s.stream.received,
      total: s.stream.total,
      setPlaying: s.setPlaying,
      setSpeed: s.setSpeed,
      setLoop: s.setLoop,
      seek: s.seek,
    })),
  );
  const total = s.total;
  const empty = total === 0;
  const shown = empty ? 0 : s.frame + 1;

  const toggle = () => {
    if (!s.playing) s.seek(Math.floor(playFrom(playhead.pos, frames.received, frames.total)));
    s.setPlaying(!s.playing);
  };

  return (
    <div className="timeline" data-testid="timeline">
      <button
        className="icon-button play"
        data-testid="play"
        onClick={toggle}
        disabled={empty}
        aria-label={s.playing && !empty ? "Pause" : "Play"}
        title={s.playing && !empty ? "Pause (Space)" : "Play (Space)"}
      >
        {s.playing && !empty ? "❚❚" : "▶"}
      </button>
      <div className="timeline__lane">
        <TimelineTrack />
        <input
          className="timeline__scrubber"
          data-testid="scrubber"
          type="range"
          aria-label="Frame"
          min={0}
          max={Math.max(0, total - 1)}
          step={1}
          value={s.frame}
          disabled={empty}
          onChange={(e) => s.seek(Math.min(Number(e.target.value), Math.max(0, s.received - 1)))}
          style={{ ["--loaded" as string]: `${total ? (100 * s.received) / total : 0}%` }}
        />
      </div>
      <span className="timeline__counter" data-testid="frame-counter">
        <span>
          {shown} / {total}
        </span>
        <span className="muted">
          {formatSeconds(empty ? 0 : s.frame, FPS)} / {formatSeconds(total, FPS)}
        </span>
      </span>
      <select
        aria-label="Speed"
        data-testid="speed"
        value={s.speed}
        onChange={(e) => s.setSpeed(Number(e.target.value))}
      >
        {SPEEDS.map((v) => (
          <option key={v} value={v}>
            {v}×
          </option>
        ))}
      </select>
      <label className="toggle" title="Loop playback" data-testid="loop-toggle">
        <input type="checkbox" data-testid="loop" checked={s.loop} onChange={(e) => s.setLoop(e.target.checked)} />
        Loop
      </label>
    </div>
  );
}
